#pragma once
/// @file CurrentGrid.hpp
/// A current given on a grid in space and time (MoorDyn's 4D current, Currents = 5): the velocity at the
/// nodes of a rectilinear grid x, y, z, t, interpolated linearly in each of the four coordinates.

#include <array>
#include <string>
#include <vector>

#include "tangle/core/Types.hpp"

namespace tangle::hydro {

/// Velocity of the water [m/s] on a grid of x, y, z [m] (global axes, z up, 0 at still water) and time t [s].
/// Between the nodes the velocity is quadrilinear (linear in each coordinate, as MoorDyn's interp4); outside
/// the grid every coordinate is clamped to its end ticks: the velocity beyond the grid's last time is held
/// (MoorDyn repeats its grid with a period one time step longer than its span: not followed). Immutable,
/// thread-safe.
class CurrentGrid {
 public:
  /// @param ticks x, y, z [m] and t [s] ticks, each strictly increasing, at least one each
  /// @param velocity one value per node [m/s], x slowest, t fastest: index ((ix ny + iy) nz + iz) nt + it
  /// @throws tangle::Error for ticks that do not increase, non-finite values or a size that does not match
  CurrentGrid(std::array<std::vector<double>, 4> ticks, std::vector<Vec3> velocity);

  /// The velocity at `position` [m] and time t [s] [m/s].
  Vec3 velocity(const Vec3& position, double t) const;

  /// The ticks of coordinate `axis` (0 x, 1 y, 2 z [m], 3 t [s]).
  const std::vector<double>& ticks(int axis) const { return m_ticks[static_cast<std::size_t>(axis)]; }
  /// True when every velocity is zero.
  bool isZero() const;

 private:
  std::array<std::vector<double>, 4> m_ticks;
  std::vector<Vec3> m_velocity;
};

/// Reads a 4D current grid in MoorDyn's current_profile_4d.txt format: a line "nx ny nz nt", a line of nx x
/// ticks, then y, z and t tick lines, then one row "x y z t ux uy uz" per grid node (any order; each
/// coordinate one of its ticks). Blank lines are skipped. (MoorDyn itself skips the first node row: a bug not
/// followed.)
/// @throws tangle::InputError naming the file, the line and what was expected
CurrentGrid readCurrentGridFile(const std::string& path);

}  // namespace tangle::hydro
