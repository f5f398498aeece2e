#pragma once
/// @file PrescribedMotion.hpp
/// Prescribed displacement of a held line end about its initial position: ramped harmonic motion
/// or a time-history table (linear interpolation, held at its last value).

#include <functional>

#include "tangle/core/Types.hpp"
#include "tangle/model/ModelSpec.hpp"

namespace tangle::time {

/// Displacement, velocity and acceleration of a prescribed motion at one time.
struct MotionValue {
  Vec3 displacement = Vec3::Zero();  ///< [m]
  Vec3 velocity = Vec3::Zero();      ///< [m/s]
  Vec3 acceleration = Vec3::Zero();  ///< [m/s^2]
  bool hasRotation = false;          ///< the node's rotation is prescribed too (vessel nodes)
  Mat3 rotation = Mat3::Identity();  ///< absolute rotation (vessel axes to global)
  Vec3 angularVelocity = Vec3::Zero();      ///< spatial [rad/s]
  Vec3 angularAcceleration = Vec3::Zero();  ///< spatial [rad/s^2]
};

/// A prescribed end motion.
class PrescribedMotion {
 public:
  /// @param spec harmonic amplitude/period/phase or table
  /// @param rampTime start-up ramp duration [s] (harmonic motion only; a table is used as given)
  PrescribedMotion(const model::EndMotionSpec& spec, double rampTime) : m_spec(spec), m_rampTime(rampTime) {}
  /// Motion at time t [s].
  MotionValue at(double t) const;

 private:
  model::EndMotionSpec m_spec;
  double m_rampTime;
};

}  // namespace tangle::time
