#include "tangle/analysis/ClashDamage.hpp"

#include <algorithm>
#include <cmath>

namespace tangle::analysis {

int LineClashDamage::impacts() const {
  int n = 0;
  for (const ClashDamageBin& b : bins) n += b.impacts;
  return n;
}

double LineClashDamage::energy() const {
  double e = 0.0;
  for (const ClashDamageBin& b : bins) e += b.energy;
  return e;
}

std::vector<LineClashDamage> clashDamage(const model::Model& model, const std::vector<int>& lines,
                                         const std::vector<contact::ContactEvent>& events, double binLength,
                                         double energyThreshold) {
  std::vector<LineClashDamage> out;
  std::vector<int> slot(model.lines().size(), -1);  // index into out of each line
  for (const int l : lines) {
    if (slot[static_cast<std::size_t>(l)] >= 0) continue;
    const double length = model.lines()[static_cast<std::size_t>(l)].length;
    // Bins of the given length; the last one ends at the line's end (a remainder under 1 mm joins the bin
    // before it, so that no bin is a sliver of round-off).
    const int count = std::max(1, static_cast<int>(std::ceil(length / binLength - 1e-3 / binLength)));
    LineClashDamage d;
    d.line = l;
    for (int b = 0; b < count; ++b)
      d.bins.push_back({b * binLength, b + 1 == count ? length : (b + 1) * binLength});
    slot[static_cast<std::size_t>(l)] = static_cast<int>(out.size());
    out.push_back(std::move(d));
  }
  const auto add = [&](int line, double arc, const contact::ContactEvent& e) {
    const int s = slot[static_cast<std::size_t>(line)];
    if (s < 0) return;
    std::vector<ClashDamageBin>& bins = out[static_cast<std::size_t>(s)].bins;
    const auto b = static_cast<std::size_t>(
        std::clamp(static_cast<int>(std::floor(arc / binLength)), 0, static_cast<int>(bins.size()) - 1));
    ClashDamageBin& bin = bins[b];
    ++bin.impacts;
    // An energy that could not be measured (NaN) is not summed; the impact still counts.
    const double energy = std::isfinite(e.impactEnergy) ? e.impactEnergy : 0.0;
    if (energy > energyThreshold) ++bin.impactsAbove;
    bin.energy += energy;
    bin.largestEnergy = std::max(bin.largestEnergy, energy);
    if (std::isfinite(e.impactVelocity)) bin.largestVelocity = std::max(bin.largestVelocity, e.impactVelocity);
  };
  for (const contact::ContactEvent& e : events) {
    if (!e.impact) continue;
    add(e.lineA, e.arcAStart, e);
    add(e.lineB, e.arcBStart, e);  // a line touching itself is hit at two places
  }
  return out;
}

}  // namespace tangle::analysis
