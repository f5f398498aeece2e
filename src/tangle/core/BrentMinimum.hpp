#pragma once
/// @file BrentMinimum.hpp
/// The minimum of a function of one variable on an interval, without derivatives.

#include <cmath>
#include <utility>

namespace tangle::core {

/// The minimum of f on [a, b], started from x in [a, b] with f(x) = fx, by Brent's method: parabolic steps
/// through the three best points where they fall well inside the bracket, golden sections otherwise (R. P.
/// Brent, Algorithms for Minimization without Derivatives, 1973, ch. 5). Returns (x, f(x)) of the lowest
/// value found after at most `evaluations` evaluations or when the bracket is within `tolerance` of x.
template <class Function>
std::pair<double, double> brentMinimum(const Function& f, double a, double b, double x, double fx,
                                       double tolerance, int evaluations) {
  constexpr double kGoldenSection = 0.3819660112501051;  // (3 - sqrt 5) / 2
  double w = x, v = x, fw = fx, fv = fx;
  double step = 0.0, previousStep = 0.0;
  for (int n = 0; n < evaluations; ++n) {
    const double middle = 0.5 * (a + b);
    if (std::abs(x - middle) <= 2.0 * tolerance - 0.5 * (b - a)) break;
    bool parabolic = false;
    if (std::abs(previousStep) > tolerance) {
      // The vertex of the parabola through (x, fx), (w, fw), (v, fv), as x + p / q.
      const double r = (x - w) * (fx - fv);
      double q = (x - v) * (fx - fw);
      double p = (x - v) * q - (x - w) * r;
      q = 2.0 * (q - r);
      if (q > 0.0) p = -p;
      q = std::abs(q);
      const double older = previousStep;
      previousStep = step;
      // Accepted if it is less than half the step before last (the iteration converges) and inside.
      if (std::abs(p) < std::abs(0.5 * q * older) && p > q * (a - x) && p < q * (b - x)) {
        step = p / q;
        const double u = x + step;
        if (u - a < 2.0 * tolerance || b - u < 2.0 * tolerance) step = x < middle ? tolerance : -tolerance;
        parabolic = true;
      }
    }
    if (!parabolic) {
      previousStep = (x < middle ? b : a) - x;
      step = kGoldenSection * previousStep;
    }
    const double u = x + (std::abs(step) >= tolerance ? step : (step > 0.0 ? tolerance : -tolerance));
    const double fu = f(u);
    if (fu <= fx) {
      (u < x ? b : a) = x;
      v = w;
      fv = fw;
      w = x;
      fw = fx;
      x = u;
      fx = fu;
    } else {
      (u < x ? a : b) = u;
      if (fu <= fw || w == x) {
        v = w;
        fv = fw;
        w = u;
        fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u;
        fv = fu;
      }
    }
  }
  return {x, fx};
}

}  // namespace tangle::core
