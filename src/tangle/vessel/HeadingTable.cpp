/// @file HeadingTable.cpp
/// Periodic linear interpolation of heading tables.

#include "tangle/vessel/HeadingTable.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "tangle/core/Error.hpp"
#include "tangle/core/Units.hpp"

namespace tangle::vessel {

double wrapTwoPi(double angle) {
  constexpr double twoPi = 2.0 * kPi;
  double a = std::fmod(angle, twoPi);
  if (a < 0.0) a += twoPi;
  if (a >= twoPi) a -= twoPi;  // fmod/addition rounding can land exactly on 2 pi
  return a;
}

void validateHeadingTable(const model::HeadingTable& table, const std::string& name) {
  const std::size_t n = table.heading.size();
  if (n == 0) throw Error(fmt::format("{}: the table is empty (at least one heading is needed)", name));
  if (table.values.size() != n) {
    throw Error(fmt::format("{}: {} headings but {} value rows", name, n, table.values.size()));
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double h = table.heading[i];
    if (!std::isfinite(h) || h < 0.0 || h >= 2.0 * kPi) {
      throw Error(fmt::format("{}: heading {} = {} rad is outside [0, 2 pi)", name, i, h));
    }
    if (i > 0 && !(h > table.heading[i - 1])) {
      throw Error(fmt::format("{}: headings must be strictly ascending (heading {} = {} rad follows {} rad)",
                              name, i, h, table.heading[i - 1]));
    }
    if (!table.values[i].allFinite()) throw Error(fmt::format("{}: value row {} is not finite", name, i));
  }
}

HeadingSample interpolateWithSlope(const model::HeadingTable& table, double relativeHeading) {
  validateHeadingTable(table);
  const std::vector<double>& h = table.heading;
  const std::size_t n = h.size();
  HeadingSample sample;
  if (n == 1) {
    sample.value = table.values[0];
    return sample;
  }
  const double x = wrapTwoPi(relativeHeading);
  double h0 = 0.0;
  double h1 = 0.0;
  std::size_t i0 = 0;
  std::size_t i1 = 0;
  if (x < h.front() || x >= h.back()) {  // wrap-around segment h_{n-1} -> h_0 + 2 pi
    i0 = n - 1;
    i1 = 0;
    h0 = h.back();
    h1 = h.front() + 2.0 * kPi;
  } else {
    const auto it = std::upper_bound(h.begin(), h.end(), x);  // first heading > x; exists since x < h.back()
    i1 = static_cast<std::size_t>(it - h.begin());
    i0 = i1 - 1;
    h0 = h[i0];
    h1 = h[i1];
  }
  double xs = x;
  if (xs < h0) xs += 2.0 * kPi;  // x in [0, h_0) on the wrap-around segment
  const double span = h1 - h0;
  const double w = (xs - h0) / span;
  sample.slope = (table.values[i1] - table.values[i0]) / span;
  sample.value = (1.0 - w) * table.values[i0] + w * table.values[i1];
  return sample;
}

Vec3 interpolate(const model::HeadingTable& table, double relativeHeading) {
  return interpolateWithSlope(table, relativeHeading).value;
}

}  // namespace tangle::vessel
