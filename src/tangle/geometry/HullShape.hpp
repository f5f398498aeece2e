#pragma once
/// @file HullShape.hpp
/// A solid a vessel's hull is built of, for contact (issue 46, "hulls that can be hit"): a box, a
/// flat-ended cylinder or a capsule, in the vessel's axes. A ship's hull is a box or a few; a semi's columns
/// are cylinders and its pontoons boxes; a TLP's tendons' porches and a spar are capsules or cylinders.
///
/// The contact asks each shape one question: the signed distance of a point (negative inside) and the
/// outward normal there, the gradient of that distance (ShapeDistance). These are the exact Euclidean
/// distances of each solid (the box and cylinder as in Quilez's signed distance functions: outside, the
/// distance to the nearest face, edge or corner; inside, minus the distance to the nearest face). A box's or
/// a cylinder's normal turns at its edges and corners outside (continuously: the distance is C1 outside) and
/// jumps across the planes that bisect its edges inside (the nearest face changes); a capsule's is smooth.
///
/// A hull meets another hull through points on its surface (surfacePoints: a box's edges and corners, a
/// cylinder's end rings, cap centres and generators, a capsule's rings, generators and poles) tested against
/// the other hull's shapes, both ways round: the way OrcaFlex treats a 6D buoy's vertices against shapes.
/// Any crossing of two of these solids puts an edge, corner or generator of one inside the other, so it
/// is found; its depth is the sampled points', at most about half the spacing of the points deeper.

#include <string>
#include <vector>

#include "tangle/core/Types.hpp"

namespace tangle::geometry {

/// Signed distance of a point to a shape (ShapeDistance).
struct ShapeDistance {
  double distance = 0.0;        ///< > 0 outside, < 0 inside [m]
  Vec3 normal = Vec3::UnitZ();  ///< outward unit normal, the gradient of the distance [-]
};

/// One solid of a hull, in the axes of its vessel [m].
class HullShape {
 public:
  enum class Kind { Box, Cylinder, Capsule };

  /// A box with edges along the vessel axes: centre [m] and size (lengths along x, y, z) [m], all > 0.
  static HullShape box(const Vec3& centre, const Vec3& size);
  /// A flat-ended cylinder between the centres of its end faces [m], diameter [m] > 0.
  static HullShape cylinder(const Vec3& endA, const Vec3& endB, double diameter);
  /// A capsule (a cylinder with hemispherical ends centred on endA and endB [m], a sphere when they
  /// coincide), diameter [m] > 0.
  static HullShape capsule(const Vec3& endA, const Vec3& endB, double diameter);

  Kind kind() const { return m_kind; }
  /// "box", "cylinder" or "capsule".
  std::string kindName() const;
  /// The signed distance and outward normal at point p, both in the shape's (vessel) axes.
  ShapeDistance distance(const Vec3& p) const;
  /// Points on the shape's surface [m] (vessel axes), no two further apart along an edge, ring or generator
  /// than `spacing` [m] (> 0); a ring has at least 8 points.
  std::vector<Vec3> surfacePoints(double spacing) const;
  /// The largest distance of the shape's surface from point c [m] (a bounding sphere about c).
  double reach(const Vec3& c) const;
  /// Volume [m^3] (for the report; a hull's shapes may overlap).
  double volume() const;
  /// One line for logs: kind and dimensions.
  std::string describe() const;

  /// Box: centre and size; cylinder and capsule: the two end centres and the diameter in size.x().
  const Vec3& centre() const { return m_centre; }
  const Vec3& size() const { return m_size; }
  const Vec3& endA() const { return m_endA; }
  const Vec3& endB() const { return m_endB; }
  double diameter() const { return m_size.x(); }

 private:
  Kind m_kind = Kind::Box;
  Vec3 m_centre = Vec3::Zero();
  Vec3 m_size = Vec3::Ones();
  Vec3 m_endA = Vec3::Zero();
  Vec3 m_endB = Vec3::Zero();
};

}  // namespace tangle::geometry
