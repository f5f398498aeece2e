#pragma once
/// @file CurrentProfile.hpp
/// Current: horizontal velocity varying piecewise-linearly with the vertical coordinate, steady or changing
/// in time through a history of such profiles.

#include <memory>
#include <vector>

#include "tangle/core/Types.hpp"
#include "tangle/hydro/CurrentGrid.hpp"

namespace tangle::hydro {

/// One level of a current profile.
struct CurrentLevel {
  double z = 0.0;        ///< level [m], global z (0 = still water level, negative below), <= 0
  double speed = 0.0;    ///< current speed [m/s], >= 0
  double azimuth = 0.0;  ///< direction the current flows towards, anticlockwise from +x [rad]
};

/// Piecewise-linear current profile in the global z coordinate (not depth below the surface: a caller
/// reading depths d converts with z = -d).
/// Between two levels the speed is interpolated linearly in z, and so is the azimuth, along the shorter
/// arc between the two level azimuths (exactly opposite directions turn anticlockwise). Beyond the end
/// levels the profile is constant: below the deepest level it keeps the deepest value and above the
/// highest level, including z > 0 (wave crests), it keeps the highest value. The current is NOT set to
/// zero above z = 0 and is not stretched to the instantaneous surface: whether a point is wet is
/// decided by the caller (e.g. with WaveField::elevation). Immutable, thread-safe.
class CurrentProfile {
 public:
  /// No current (velocity() is zero everywhere).
  CurrentProfile() = default;

  /// @param levels at least one level, in any order (sorted by z here); z <= 0 and distinct,
  ///        speed >= 0, all values finite
  /// @throws tangle::Error with the offending level and value otherwise
  explicit CurrentProfile(std::vector<CurrentLevel> levels);

  /// Uniform current of speed [m/s] towards azimuth [rad] over the whole water column.
  static CurrentProfile uniform(double speed, double azimuth);

  /// Horizontal current velocity [m/s] at global level z [m] (see the class comment for z outside the
  /// levels); with a history, its first profile's (the statics' current).
  Vec3 velocity(double z) const { return m_levels.empty() ? Vec3::Zero() : profileVelocity(z); }

  /// The velocity at level z [m] and time t [s]: with a history (withHistory), interpolated linearly in time
  /// between the profiles before and after t, component by component (MoorDyn's dynamic current grid), and
  /// the first or last profile's outside their times; otherwise velocity(z).
  /// (Inline for a steady current: the Morison loop asks at every element of every evaluation, and with
  /// no current at all the call was 2-3 % of a coupled host's run.)
  Vec3 velocity(double z, double t) const { return m_times.empty() ? velocity(z) : historyVelocity(z, t); }

  /// A current changing in time: `profiles` at increasing `times` [s] (at least one; the first is this
  /// profile's steady value). @throws tangle::Error for times not increasing or sizes that differ
  static CurrentProfile withHistory(std::vector<double> times, std::vector<CurrentProfile> profiles);

  /// A current on a grid in space and time (MoorDyn's Currents 5): velocity(position, t) is the grid's.
  static CurrentProfile withGrid(std::shared_ptr<const CurrentGrid> grid);

  /// The velocity at `position` [m] and time t [s] [m/s]: the grid's where there is one (it may have a
  /// vertical component), else velocity(position.z(), t).
  Vec3 velocity(const Vec3& position, double t) const {
    return m_grid ? m_grid->velocity(position, t) : velocity(position.z(), t);
  }

  /// True when the current changes in time.
  bool changes() const { return !m_times.empty() || (m_grid && m_grid->ticks(3).size() > 1); }

  /// The levels, sorted by increasing z (deepest first); empty for no current.
  const std::vector<CurrentLevel>& levels() const { return m_levels; }

  /// True when every speed is zero (or there are no levels).
  bool isZero() const;

 private:
  /// velocity(z, t) with a history.
  Vec3 historyVelocity(double z, double t) const;
  /// velocity() with at least one level.
  Vec3 profileVelocity(double z) const;
  std::vector<CurrentLevel> m_levels;
  std::shared_ptr<const CurrentGrid> m_grid;  // a grid in space and time, or none
  std::vector<double> m_times;              // a history's times [s], increasing; empty: steady
  std::vector<CurrentProfile> m_snapshots;  // and its profiles (steady ones)
  std::vector<double> m_unwrappedAzimuth;  // level azimuths made continuous along the shorter arcs [rad]
  std::vector<Vec2> m_unwrappedDirection;  // (cos, sin) of m_unwrappedAzimuth [-]
  Vec2 m_frontDirection = Vec2::UnitX();   // (cos, sin) of the lowest level's azimuth [-]
  Vec2 m_backDirection = Vec2::UnitX();    // (cos, sin) of the highest level's azimuth [-]
};

}  // namespace tangle::hydro
