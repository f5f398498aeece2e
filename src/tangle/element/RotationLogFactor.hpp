#pragma once
/// @file RotationLogFactor.hpp
/// Private helper of the element module: the factor of the SO(3) logarithm written as a smooth
/// function of c = cos(theta) = (trace(R) - 1) / 2, so that it can be differentiated twice at
/// exactly zero rotation.
///
/// log(R) = g(c) / 2 * v,  v = (R32 - R23, R13 - R31, R21 - R12),  g(c) = theta / sin(theta)
/// (e.g. Crisfield 1997, vol. 2, sec. 16.8; Battini & Pacoste 2002, eq. 8), valid for theta < pi.

#include <array>
#include <cmath>
#include <cstddef>

namespace tangle::element {

/// g(c) = theta / sin(theta) with theta = acos(c), and its first two derivatives with respect to c.
struct ThetaOverSin {
  double value = 1.0;   ///< g(c) [-]
  double first = 0.0;   ///< dg/dc [-]
  double second = 0.0;  ///< d^2g/dc^2 [-]
};

/// Below this x = 1 - c the series is used (theta < ~0.451 rad); the direct formula above it
/// loses at most ~theta^-2 ~ 5 in relative accuracy of the second derivative.
inline constexpr double kLogSeriesLimit = 0.1;

/// Number of series terms: for x < 0.1 each term is <= 0.05 times the previous one, and 18 terms reach
/// machine precision for the value and both derivatives.
inline constexpr int kLogSeriesTerms = 18;

/// The series coefficients a_k = 2^k (k!)^2 / (2k + 1)! (a_0 = 1, a_k = a_{k-1} k / (2k + 1)), computed
/// once (the recurrence's divisions made the series, evaluated twice per beam element and residual, a
/// visible share of a riser run: docs/performance.md).
inline constexpr std::array<double, kLogSeriesTerms> kLogSeries = [] {
  std::array<double, kLogSeriesTerms> a{};
  a[0] = 1.0;
  for (int k = 1; k < kLogSeriesTerms; ++k) a[k] = a[k - 1] * k / (2.0 * k + 1.0);
  return a;
}();

/// g(c) = theta/sin(theta) and derivatives, for -1 < c <= 1 (theta in [0, pi)).
/// Near c = 1 the Taylor series in x = 1 - c is used, g = sum_k a_k x^k (kLogSeries); its radius of
/// convergence is x = 2 (theta = pi).
/// Away from c = 1 (s = sin(theta) = sqrt(1 - c^2)):
///   g = theta / s,  g' = (theta c - s) / s^3,  g'' = (theta s^2 + 3 c (theta c - s)) / s^5.
inline ThetaOverSin thetaOverSin(double c) {
  ThetaOverSin r;
  const double x = 1.0 - c;
  if (x < kLogSeriesLimit) {
    double xk = 1.0;   // x^k
    double xk1 = 0.0;  // x^(k-1) (multiplied by k = 0 when k = 0)
    double xk2 = 0.0;  // x^(k-2) (multiplied by k (k - 1) = 0 when k < 2)
    r.value = 0.0;
    double dgdx = 0.0;
    double d2gdx2 = 0.0;
    for (int k = 0; k < kLogSeriesTerms; ++k) {
      const double a = kLogSeries[static_cast<std::size_t>(k)];
      r.value += a * xk;
      dgdx += k * a * xk1;
      d2gdx2 += k * (k - 1) * a * xk2;
      xk2 = xk1;
      xk1 = xk;
      xk *= x;
    }
    r.first = -dgdx;
    r.second = d2gdx2;
  } else {
    const double theta = std::acos(c);
    const double s = std::sqrt((1.0 - c) * (1.0 + c));
    const double n = theta * c - s;
    r.value = theta / s;
    r.first = n / (s * s * s);
    r.second = (theta * s * s + 3.0 * c * n) / (s * s * s * s * s);
  }
  return r;
}

/// g(c) alone (the internal force needs no derivative of it): the series summed only while its terms
/// matter (a term below 1e-17 of the first ends the sum; the remaining ones are smaller still, each at
/// most x/2 times the one before), so a small local rotation (x ~ 1e-6) costs three terms.
inline double thetaOverSinValue(double c) {
  const double x = 1.0 - c;
  if (x < kLogSeriesLimit) {
    double value = 1.0;
    double xk = 1.0;
    for (int k = 1; k < kLogSeriesTerms; ++k) {
      xk *= x;
      const double term = kLogSeries[static_cast<std::size_t>(k)] * xk;
      value += term;
      if (std::abs(term) <= 1e-17) break;
    }
    return value;
  }
  return std::acos(c) / std::sqrt((1.0 - c) * (1.0 + c));
}

}  // namespace tangle::element
