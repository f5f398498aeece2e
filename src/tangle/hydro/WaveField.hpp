#pragma once
/// @file WaveField.hpp
/// Abstract interface of a wave field: free-surface elevation and fluid kinematics in space and time.
/// Implementations: AiryWave (regular linear wave), JonswapSea (irregular long-crested sea).

#include "tangle/core/Types.hpp"

namespace tangle::hydro {

/// Fluid velocity and acceleration at one point and instant, global axes.
/// The acceleration is the local (Eulerian) derivative du/dt: linear wave theory drops the
/// convective term (u . grad) u, which is second order in the wave steepness (Dean & Dalrymple 1991,
/// "Water wave mechanics for engineers and scientists", ch. 3-4).
struct FluidKinematics {
  Vec3 velocity = Vec3::Zero();      ///< fluid velocity [m/s]
  Vec3 acceleration = Vec3::Zero();  ///< fluid acceleration [m/s^2]
};

/// How linear-wave kinematics are evaluated up to the instantaneous free surface.
enum class Stretching {
  /// Wheeler (1970) stretching of the whole water column: the linear profile is evaluated at
  /// z' = h (z - eta) / (h + eta), which maps [-h, eta] onto [-h, 0] (the default).
  Wheeler,
  /// "Vertical" stretching (constant extrapolation): below z = 0 the linear profile is evaluated at z,
  /// between z = 0 and a crest eta > 0 it keeps its z = 0 value.
  Vertical,
  /// No stretching: linear theory as derived, valid up to z = 0 only. Below min(0, eta) the linear
  /// profile at z; above z = 0 (under a crest) no fluid kinematics.
  None,
};

/// True when a point at level z is wet for the kinematics of a surface at eta under `stretching`
/// (z <= eta, and z <= 0 without stretching).
inline bool wetForKinematics(double z, double eta, Stretching stretching) {
  return z <= eta && (stretching != Stretching::None || z <= 0.0);
}

/// A wave field. Implementations are immutable after construction and thread-safe (const methods only).
/// Positions are global [m] (z up, z = 0 at still water level, seabed at z = -depth), time t [s].
class WaveField {
 public:
  virtual ~WaveField() = default;

  /// Free-surface elevation eta(x, y, t) above still water level [m].
  virtual double elevation(double x, double y, double t) const = 0;

  /// Fluid kinematics at point p [m] and time t [s]. Zero above the instantaneous surface
  /// (p.z() > eta(p.x(), p.y(), t)); below the seabed (p.z() < -depth) the seabed values are returned.
  virtual FluidKinematics kinematics(const Vec3& p, double t) const = 0;

  /// kinematics(p, t), with the elevation at (p.x, p.y) [m] in `elevation`, equal to elevation(p.x, p.y, t).
  /// The Morison loads need both at every element midpoint and step, and the kinematics find the
  /// elevation anyway (for the stretching): implementations evaluate the phases once.
  virtual FluidKinematics kinematics(const Vec3& p, double t, double& elevation) const {
    elevation = this->elevation(p.x(), p.y(), t);
    return kinematics(p, t);
  }

 protected:
  WaveField() = default;
  WaveField(const WaveField&) = default;
  WaveField& operator=(const WaveField&) = default;
  WaveField(WaveField&&) = default;
  WaveField& operator=(WaveField&&) = default;
};

}  // namespace tangle::hydro
