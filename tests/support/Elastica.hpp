#pragma once
// The elastica of a cantilever under a vertical tip dead load, the reference of the beam statics tests
// (Mattiasson 1981, Int. J. Numer. Meth. Eng. 17:145-153, Table 1), computed independently by shooting on
// EI theta'' = -P cos(theta), theta(0) = 0, theta'(L) = 0 with RK4 (checked against Mattiasson's table
// in CantileverTest).

#include <array>
#include <cmath>
#include <utility>

namespace tangle::test {

/// Elastica of a cantilever with a tip dead load: returns (horizontal shortening u/L, deflection w/L).
inline std::pair<double, double> elastica(double loadParameter) {
  // Non-dimensional: s in [0,1], theta'' = -k cos(theta), k = P L^2 / EI; shoot on kappa0 = theta'(0).
  auto integrate = [&](double kappa0, double* u, double* w) {
    const int n = 4000;
    const double h = 1.0 / n;
    double th = 0.0, om = kappa0, x = 0.0, z = 0.0;
    auto f = [&](double t, double o) { return std::array<double, 4>{o, -loadParameter * std::cos(t), std::cos(t), std::sin(t)}; };
    for (int i = 0; i < n; ++i) {
      const auto k1 = f(th, om);
      const auto k2 = f(th + 0.5 * h * k1[0], om + 0.5 * h * k1[1]);
      const auto k3 = f(th + 0.5 * h * k2[0], om + 0.5 * h * k2[1]);
      const auto k4 = f(th + h * k3[0], om + h * k3[1]);
      th += h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]);
      om += h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]);
      x += h / 6 * (k1[2] + 2 * k2[2] + 2 * k3[2] + k4[2]);
      z += h / 6 * (k1[3] + 2 * k2[3] + 2 * k3[3] + k4[3]);
    }
    if (u) *u = 1.0 - x;
    if (w) *w = z;  // theta measured downward: z is the downward deflection
    return om;      // theta'(1), must vanish
  };
  double lo = 0.0, hi = loadParameter;  // theta'(0) in (0, k]
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (integrate(mid, nullptr, nullptr) > 0.0 ? hi : lo) = mid;
  }
  double u = 0.0, w = 0.0;
  integrate(0.5 * (lo + hi), &u, &w);
  return {u, w};
}

}  // namespace tangle::test
