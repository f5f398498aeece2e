#include "tangle/solver/ForceBalance.hpp"

#include <algorithm>
#include <cstdio>

namespace tangle::solver {

namespace {

std::string format(const ForceBalance& b, const char* kind) {
  char text[256];
  std::snprintf(text, sizeof text,
                "equilibrium audit: %s '%s' is out of balance by (%.4g, %.4g, %.4g) N, %.3g of its reference "
                "force %.4g N (tolerance %.1e)",
                kind, b.name.c_str(), b.residual.x(), b.residual.y(), b.residual.z(), b.relativeResidual(),
                b.scale, b.tolerance);
  return text;
}

}  // namespace

double EquilibriumAudit::worstRelativeResidual() const {
  double worst = 0.0;
  for (const ForceBalance& b : lines) worst = std::max(worst, b.relativeResidual());
  for (const ForceBalance& b : vessels) worst = std::max(worst, b.relativeResidual());
  for (const ForceBalance& b : points) worst = std::max(worst, b.relativeResidual());
  return worst;
}

std::vector<std::string> EquilibriumAudit::warnings() const {
  std::vector<std::string> out;
  for (const ForceBalance& b : lines)
    if (!b.balanced()) out.push_back(format(b, "line"));
  for (const ForceBalance& b : vessels)
    if (!b.balanced()) out.push_back(format(b, "vessel"));
  for (const ForceBalance& b : points)
    if (!b.balanced()) out.push_back(format(b, "point"));
  return out;
}

}  // namespace tangle::solver
