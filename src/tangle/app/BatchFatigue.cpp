#include "tangle/app/BatchFatigue.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>

#include "tangle/core/Csv.hpp"
#include "tangle/core/OutputFile.hpp"

namespace tangle::app {

namespace fs = std::filesystem;

namespace {

/// The columns of a fatigue CSV file that the total needs.
struct FatigueTable {
  std::vector<double> arcLength, damagePerYear;
  double designFactor = 1.0;  ///< from life = 1 / (DFF D_year) of the first node with damage
  bool valid = false;
};

FatigueTable readFatigueTable(const fs::path& file) {
  FatigueTable t;
  std::ifstream in(file);
  std::string line;
  if (!std::getline(in, line)) return t;
  const std::vector<std::string> header = core::splitCsvRow(line);
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const std::size_t arc = column("arc_length_m"), damage = column("damage_per_year"), life = column("life_years");
  if (arc >= header.size() || damage >= header.size() || life >= header.size()) return t;
  bool factorFound = false;
  while (std::getline(in, line)) {
    const std::vector<std::string> f = core::splitCsvRow(line);
    if (f.size() != header.size()) return t;
    t.arcLength.push_back(std::stod(f[arc]));
    const double d = std::stod(f[damage]);
    t.damagePerYear.push_back(d);
    const double years = f[life] == "inf" ? std::numeric_limits<double>::infinity() : std::stod(f[life]);
    if (!factorFound && d > 0.0 && std::isfinite(years)) {
      t.designFactor = 1.0 / (years * d);
      factorFound = true;
    }
  }
  t.valid = true;
  return t;
}

}  // namespace

std::string writeBatchFatigue(const fs::path& dir, const BatchPlan& plan, const std::vector<fs::path>& caseDirs,
                              const std::vector<CaseSummary>& rows) {
  const std::size_t seeds = std::max<std::size_t>(1, plan.seeds.size());
  const std::size_t states = plan.cases.size() / seeds;
  // Per line file stem: the damage per year summed over the sea states, and per node the sea state with
  // the largest share.
  struct Total {
    std::vector<double> arcLength, damage, largestShare;
    std::vector<std::string> largestState;
    double designFactor = 1.0;
    bool mismatch = false;
  };
  std::map<std::string, Total> totals;
  std::string notes;
  int counted = 0;
  for (std::size_t s = 0; s < states; ++s) {
    const std::string& state = plan.cases[s * seeds].name;
    bool complete = true;
    for (std::size_t k = 0; k < seeds; ++k) complete = complete && rows[s * seeds + k].status.rfind("completed", 0) == 0;
    if (!complete) {
      notes += fmt::format("  sea state '{}' left out: not every {} completed\n", state, seeds > 1 ? "seed" : "run");
      continue;
    }
    // The mean over this sea state's seeds, per line.
    std::map<std::string, FatigueTable> mean;
    for (std::size_t k = 0; k < seeds; ++k) {
      const fs::path folder = caseDirs[s * seeds + k] / "fatigue";
      if (!fs::is_directory(folder)) continue;
      for (const fs::directory_entry& e : fs::directory_iterator(folder)) {
        if (e.path().extension() != ".csv" || e.path().filename() == "summary.csv") continue;
        const FatigueTable t = readFatigueTable(e.path());
        if (!t.valid) continue;
        FatigueTable& m = mean[e.path().stem().string()];
        if (!m.valid) {
          m = t;
          std::fill(m.damagePerYear.begin(), m.damagePerYear.end(), 0.0);
        }
        if (t.arcLength != m.arcLength) {
          totals[e.path().stem().string()].mismatch = true;
          continue;
        }
        for (std::size_t i = 0; i < t.arcLength.size(); ++i)
          m.damagePerYear[i] += t.damagePerYear[i] / static_cast<double>(seeds);
      }
    }
    if (!mean.empty()) ++counted;
    for (const auto& [stem, m] : mean) {
      Total& total = totals[stem];
      if (total.mismatch) continue;
      if (total.arcLength.empty()) {
        total.arcLength = m.arcLength;
        total.damage.assign(m.arcLength.size(), 0.0);
        total.largestShare.assign(m.arcLength.size(), -1.0);
        total.largestState.assign(m.arcLength.size(), "");
        total.designFactor = m.designFactor;
      } else if (m.arcLength != total.arcLength) {
        total.mismatch = true;
        continue;
      }
      for (std::size_t i = 0; i < m.arcLength.size(); ++i) {
        total.damage[i] += m.damagePerYear[i];
        if (m.damagePerYear[i] > total.largestShare[i]) {
          total.largestShare[i] = m.damagePerYear[i];
          total.largestState[i] = state;
        }
      }
    }
  }
  if (totals.empty()) return notes;
  fs::create_directories(dir / "fatigue_total");
  core::OutputFile summary(dir / "fatigue_total" / "summary.csv");
  summary.write("line,arc_length_m,damage_per_year,life_years,design_factor,largest_sea_state,largest_share\n");
  std::string text = fmt::format("long-term fatigue over {} sea state(s){} (fatigue_total/):\n", counted,
                                 seeds > 1 ? fmt::format(", the mean of {} seeds each", seeds) : std::string());
  for (const auto& [stem, total] : totals) {
    if (total.mismatch) {
      text += fmt::format("  line '{}' left out: its nodes differ between the cases (another mesh)\n", stem);
      continue;
    }
    const auto life = [&](double d) {
      return d > 0.0 ? 1.0 / (total.designFactor * d) : std::numeric_limits<double>::infinity();
    };
    const auto number = [](double v) { return std::isfinite(v) ? fmt::format("{:.6e}", v) : std::string("inf"); };
    core::OutputFile out(dir / "fatigue_total" / (stem + ".csv"));
    out.write("arc_length_m,damage_per_year,life_years,largest_sea_state,largest_share\n");
    std::size_t worst = 0;
    for (std::size_t i = 0; i < total.arcLength.size(); ++i) {
      const double share = total.damage[i] > 0.0 ? total.largestShare[i] / total.damage[i] : 0.0;
      out.write(fmt::format("{:.4f},{:.6e},{},{},{:.4f}\n", total.arcLength[i], total.damage[i],
                            number(life(total.damage[i])), core::csvField(total.largestState[i]), share));
      if (total.damage[i] > total.damage[worst]) worst = i;
    }
    out.close();
    const double share = total.damage[worst] > 0.0 ? total.largestShare[worst] / total.damage[worst] : 0.0;
    summary.write(fmt::format("{},{:.4f},{:.6e},{},{:g},{},{:.4f}\n", core::csvField(stem), total.arcLength[worst],
                              total.damage[worst], number(life(total.damage[worst])), total.designFactor,
                              core::csvField(total.largestState[worst]), share));
    text += fmt::format("  line '{}': shortest life {:.4g} years at {:.1f} m (damage {:.3e} per year, {:.0f} % of it "
                        "from '{}')\n",
                        stem, life(total.damage[worst]), total.arcLength[worst], total.damage[worst], 100.0 * share,
                        total.largestState[worst]);
  }
  summary.close();
  return text + notes;
}

}  // namespace tangle::app
