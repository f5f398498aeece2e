#pragma once
/// @file Ramp.hpp
/// Smooth start-up ramp r(t) = (1 - cos(pi t / T)) / 2 for t < T, 1 after: zero value and slope at
/// t = 0, so loads and motions start without a jerk (the usual practice, e.g. OrcaFlex build-up). In core:
/// the hydrodynamics, the vessels and the prescribed motions all ramp.

#include <cmath>

#include "tangle/core/Units.hpp"

namespace tangle::core {

/// Ramp value and its first two time derivatives.
struct RampValue {
  double value = 1.0;  ///< [-]
  double rate = 0.0;   ///< [1/s]
  double accel = 0.0;  ///< [1/s^2]
};

/// Evaluates the ramp of duration `rampTime` [s] at time t [s].
inline RampValue ramp(double t, double rampTime) {
  if (rampTime <= 0.0 || t >= rampTime) return {};
  if (t <= 0.0) return {0.0, 0.0, 0.0};
  const double w = kPi / rampTime;
  return {0.5 * (1.0 - std::cos(w * t)), 0.5 * w * std::sin(w * t), 0.5 * w * w * std::cos(w * t)};
}

}  // namespace tangle::core
