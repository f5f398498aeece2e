/// @file WakeModel.cpp
/// Huse and Blevins wake deficits (formulas in WakeModel.hpp).

#include "tangle/hydro/WakeModel.hpp"

#include <algorithm>
#include <cmath>

namespace tangle::hydro {

WakeValue wakeAt(const WakeCoefficients& c, double x, double y, double cd, double diameter,
                 double downstreamDiameter) {
  WakeValue w;
  if (!(x > 0.0) || !(cd > 0.0) || !(diameter > 0.0)) return w;
  const double cdD = cd * diameter;
  if (c.kind == WakeKind::Huse) {
    const double xs = x + diameter / (4.0 * c.k1 * c.k1 * cd);  // virtual wake source
    const double b = c.k1 * std::sqrt(cdD * xs);
    w.halfWidth = b;
    w.deficit = std::min(1.0, c.k2 * std::sqrt(cdD / xs) * std::exp(-c.k3 * (y / b) * (y / b)));
    return w;
  }
  // Blevins: the fit is singular at the upstream centre; no closer than two diameters.
  const double xe = std::max(x, 2.0 * diameter);
  const double spread = cdD * xe;  // [m^2]
  const double u = std::min(1.0, c.a1 * std::sqrt(cdD / xe) * std::exp(-c.a2 * y * y / spread));
  w.deficit = u;
  w.halfWidth = std::sqrt(std::log(2.0) * spread / c.a2);
  w.liftCoefficient = c.a3 * u * y * downstreamDiameter / spread;
  return w;
}

}  // namespace tangle::hydro
