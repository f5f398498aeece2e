#pragma once
/// @file SeabedSurface.hpp
/// The shape of the seabed: flat at z = -depth, a plane with a slope, or a bathymetry grid. Every use of
/// the seabed (the contact reaction and friction, the as-laid and catenary start shapes, the anchors'
/// seating, touchdown and clearance results, the reader's checks) asks this one object for the seabed's
/// height and normal under a point.

#include <string>
#include <vector>

#include "tangle/core/Types.hpp"

namespace tangle::seabed {

/// The seabed under one horizontal position.
struct SeabedPoint {
  double height = 0.0;          ///< z of the seabed [m] (negative below still water)
  Vec3 normal = Vec3::UnitZ();  ///< unit normal, pointing up into the water [-]
};

/// Seabed height z = h(x, y) [m] and its unit normal.
///
/// - Flat: h = -depth.
/// - Plane: h = -depth + tan(slope) (x cos(azimuth) + y sin(azimuth)): `depth` under the origin, rising by
///   `slope` towards `azimuth` (the up-slope direction, anticlockwise from +x; OrcaFlex's "slope direction").
/// - Grid: heights at the nodes of a rectilinear grid (x and y ticks increasing), held at the edge value
///   beyond the grid (as MoorDyn's SeafloorFile, Seafloor.cpp getDepthAt), and between the nodes either
///   - bilinear (MoorDyn's interp2): the normal is the bilinear surface's within a cell, so it turns at the
///     cell edges (a crease: a line laid along one meets a knife edge), or
///   - cubic: the bicubic Hermite patch of each cell (tensor product of cubic Hermite polynomials; e.g.
///     de Boor, "A practical guide to splines", or Fritsch & Carlson 1980 for the 1D form) with node slopes
///     h_x, h_y and twist h_xy from the three-point (parabolic) differences on the uneven ticks, one-sided at
///     the grid's edges: the surface and its normal are continuous across the cell edges (C1), and it goes
///     through every node. A cubic can overshoot the nodes' heights between them where the slope changes
///     abruptly (by a fraction of the change of height over a cell).
///
/// The clearance of a sphere of radius r centred at p is measured along the local normal,
/// gap = (p_z - h(p_x, p_y)) n_z - r: exact for a plane, first order in the surface's curvature for a grid.
class SeabedSurface {
 public:
  enum class Kind { Flat, Plane, Grid };
  /// Between a grid's nodes (see the class comment).
  enum class Interpolation { Bilinear, Cubic };

  /// Flat seabed at z = -depth [m].
  static SeabedSurface flat(double depth);
  /// Plane: @param depth depth under the origin [m]; @param slope angle to the horizontal [rad], [0, pi/2);
  /// @param azimuth direction in which the seabed rises, anticlockwise from +x [rad].
  static SeabedSurface plane(double depth, double slope, double azimuth);
  /// Grid: @param x ticks [m] (increasing, at least one); @param y ticks [m] (increasing, at least one);
  /// @param height z of the seabed [m] at (x[i], y[j]), stored at height[j * x.size() + i].
  /// Throws std::invalid_argument on ticks that do not increase or a size that does not match.
  static SeabedSurface grid(std::vector<double> x, std::vector<double> y, std::vector<double> height,
                            Interpolation interpolation = Interpolation::Bilinear);
  /// The same grid with another interpolation (a flat or plane surface is returned unchanged).
  SeabedSurface interpolated(Interpolation interpolation) const;
  Interpolation interpolation() const { return m_interpolation; }

  Kind kind() const { return m_kind; }
  bool isFlat() const { return m_kind == Kind::Flat; }

  /// z of the seabed under (x, y) [m].
  double height(double x, double y) const;
  /// Height and unit normal under (x, y).
  SeabedPoint at(double x, double y) const;

  /// Clearance [m] of a sphere of radius `radius` [m] centred at `position` [m] along the local normal
  /// (< 0: it penetrates the seabed). Flat: (p_z - r) + depth.
  double gap(const Vec3& position, double radius) const {
    // Flat: the arithmetic of the flat seabed before slopes, so that flat models keep their results bit for
    // bit; inline (every node of every assembly asks: an out-of-line call was 1.2 % of a coupled host's run).
    if (m_kind == Kind::Flat) return (position.z() - radius) + m_depth;
    return surfaceGap(position, radius);
  }
  /// z [m] of the centre of a sphere of radius `radius` [m] at (x, y) that penetrates the seabed by
  /// `penetration` [m] along the normal: h + (radius - penetration) / n_z. Flat: (-depth + radius) -
  /// penetration.
  double restingZ(double x, double y, double radius, double penetration) const;

  /// (x, y) [m] of the foot of the seabed's normal through `position` [m] (the point of the seabed nearest
  /// to it, to first order): where an elastic friction anchor of a node there sits. Flat: (p_x, p_y).
  Vec2 footprint(const Vec3& position) const;

  /// The depth under the origin [m] (flat and plane); the grid's deepest point for a grid.
  double referenceDepth() const { return m_depth; }
  double slope() const { return m_slope; }                            ///< [rad] (plane)
  double azimuth() const { return m_azimuth; }                        ///< [rad] (plane)
  const std::vector<double>& gridX() const { return m_x; }            ///< [m] (grid)
  const std::vector<double>& gridY() const { return m_y; }            ///< [m] (grid)
  const std::vector<double>& gridHeight() const { return m_height; }  ///< [m] (grid), y-major
  /// Shallowest and deepest seabed depth [m] over the region (a plane's over a disc of radius `extent` [m]
  /// about the origin).
  double shallowestDepth(double extent) const;
  double deepestDepth(double extent) const;
  /// One line for logs and summaries, e.g. "plane, 100 m deep at the origin, rising 5 deg towards 90 deg".
  std::string describe() const;

 private:
  /// gap() off a flat seabed.
  double surfaceGap(const Vec3& position, double radius) const;

  Kind m_kind = Kind::Flat;
  double m_depth = 100.0;
  double m_slope = 0.0;
  double m_azimuth = 0.0;
  Vec2 m_gradient = Vec2::Zero();  // plane: (dh/dx, dh/dy)
  std::vector<double> m_x, m_y, m_height;
  Interpolation m_interpolation = Interpolation::Bilinear;
  /// Cubic: the node slopes dh/dx, dh/dy [-] and twists d2h/dxdy [1/m], stored as m_height.
  std::vector<double> m_hx, m_hy, m_hxy;
  /// Fills m_hx, m_hy, m_hxy (cubic).
  void computeNodeSlopes();
  SeabedPoint cubicAt(double x, double y) const;
};

/// Reads a bathymetry grid in MoorDyn's SeafloorFile format (MoorDyn v2 Seafloor.cpp): line 1 "nx ny",
/// line 2 the nx x ticks, line 3 the ny y ticks, then one "x y z" row per grid node (z of the seabed,
/// negative; each row snaps to the tick at or below its x and y, as MoorDyn's calcInsertIndex).
/// Throws InputError naming the file and line for anything else, and for grid nodes left without a row.
SeabedSurface readSeafloorFile(const std::string& path);

}  // namespace tangle::seabed
