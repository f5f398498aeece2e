#pragma once
/// @file PrescribedMotion.hpp
/// (The model layer: vessels and the integrators both use it.)
/// Prescribed displacement of a held line end about its initial position: ramped harmonic motion
/// or a time-history table, held at its first value before the table and its last value after it.
/// Table interpolation:
///  - linear (default): displacement piecewise linear; velocity the slope of the segment that *ends*
///    at or after t (left-continuous: at a row time the velocity of the segment that led there, so the
///    step arriving at a row sees the motion it made, and the last row keeps the last segment's
///    velocity instead of dropping to zero); acceleration zero;
///  - cubic: clamped cubic spline through the rows with zero velocity at the first and last row (the
///    motion is held outside the table), so displacement, velocity and acceleration are continuous.

#include <functional>
#include <vector>

#include "tangle/core/Types.hpp"
#include "tangle/model/ModelSpec.hpp"

namespace tangle::model {

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

/// A constrained node whose translations follow a prescribed motion about `basePosition` (and, for a
/// vessel node, whose rotation follows a prescribed rotation): what the integrators impose on held nodes.
struct PrescribedNode {
  int node = 0;
  Vec3 basePosition = Vec3::Zero();           ///< position at t = 0 [m]
  std::function<MotionValue(double)> motion;  ///< motion at time t [s]
};

/// A prescribed end motion.
class PrescribedMotion {
 public:
  /// @param spec harmonic amplitude/period/phase or table
  /// @param rampTime start-up ramp duration [s] (harmonic motion only; a table is used as given)
  PrescribedMotion(const EndMotionSpec& spec, double rampTime);
  /// Motion at time t [s].
  MotionValue at(double t) const;
  /// Where a cubic table's spline leaves the range of the two rows it runs between, most: a hold written as
  /// two equal rows after a move is passed and come back to (a table (0, 0), (20, -5), (40, -5) reaches
  /// -5.55 m at 27 s). Zero for a linear table and harmonic motion.
  struct Overshoot {
    double distance = 0.0;                  ///< beyond the nearer of the two rows [m]
    double time = 0.0;                      ///< [s]
    int axis = 0;                           ///< 0 x, 1 y, 2 z
    double rowTimeA = 0.0, rowTimeB = 0.0;  ///< the rows' times [s]
  };
  Overshoot tableOvershoot() const;

 private:
  MotionValue tableAt(double t) const;
  EndMotionSpec m_spec;
  double m_rampTime;
  std::vector<Vec3> m_second;  ///< spline second derivatives at the rows [m/s^2] (cubic tables)
};

}  // namespace tangle::model
