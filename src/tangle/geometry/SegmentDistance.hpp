#pragma once
/// @file SegmentDistance.hpp
/// Closest points of two 3D segments: the narrow phase of the line-to-line contact search.
///
/// Algorithm: D. Eberly, "Distance Between Two Line Segments in 3D", Geometric Tools (2005), the
/// version the seed paper uses (Silva, Pereira & Jacob, CMNE/CILAMCE 2007, section 5.1). With
///   P(s) = B0 + s M0 (segment 0),  Q(t) = B1 + t M1 (segment 1),  s, t in [0, 1],
/// the squared distance is the quadratic
///   Q(s,t) = a s^2 + 2 b s t + c t^2 + 2 d s + 2 e t + f,
///   a = M0.M0, b = -M0.M1, c = M1.M1, d = M0.D, e = -M1.D, f = D.D,  D = B0 - B1,
/// whose unconstrained minimiser is s^ = (b e - c d)/det, t^ = (b d - a e)/det, det = a c - b^2.
/// The (s,t) plane is cut into 9 regions around the unit square (labels as in Eberly's paper):
///
///        t
///        ^
///    4   |   3   |   2
///   -----+-------+-----  t = 1
///    5   |   0   |   1
///   -----+-------+-----  t = 0
///    6   |   7   |   8
///       s=0     s=1   -> s
///
/// Region 0 holds the minimiser; in regions 1, 3, 5, 7 the minimum is on the edge next to the
/// region; in the corner regions 2, 4, 6, 8 it is on one of the two edges meeting at the corner,
/// chosen by the sign of the gradient of Q at the corner. Each edge case is a clamped 1D
/// minimisation; at most one division is done on the common path and it is deferred until the
/// region is known (Eberly 2005).
///
/// Deviations from Eberly (2005), all for round-off robustness, none changes the exact-arithmetic
/// result (see SegmentDistance.cpp for the error analysis):
/// - det and the numerators of s^, t^ are evaluated through the Binet-Cauchy identity,
///   det = |M0 x M1|^2, b e - c d = (M0 x M1).(M1 x D), b d - a e = (M0 x M1).(M0 x D): det is
///   then never negative (the |a c - b^2| of the 2005 text is not needed) and the relative error of
///   s^, t^ grows like eps/angle instead of eps/angle^2 for nearly parallel segments.
/// - The parallel test is relative, det <= kParallelTolerance * a * c (i.e. sin^2 of the angle
///   between the segments), so it does not depend on the length unit.
/// - For nearly parallel segments (sin^2(angle) <= kNearlyParallel) t is recomputed in region 0 as
///   the exact clamped minimiser for the computed s (one more division): without it the distance
///   error of crossing nearly parallel segments grows like eps L / angle.
/// - Parallel segments (and zero-length ones) get the middle of the overlap of the two segments
///   along their common direction, or the closest pair of end points when they do not overlap.

#include "tangle/core/Types.hpp"

namespace tangle::geometry {

/// sin^2 of the angle between the segments (det / (a c)) at or below which they are treated as
/// parallel: angles below about 1e-12 rad. The parallel treatment is exact only at angle 0; below
/// this tolerance its distance error is under 2 angle min(|M0|, |M1|), i.e. 2e-12 of the segment
/// length (analysis in SegmentDistance.cpp).
inline constexpr double kParallelTolerance = 1e-24;

/// sin^2 of the angle between the segments (det / (a c)) at or below which region 0 refines t
/// (angles below about 0.01 rad); see the file comment.
inline constexpr double kNearlyParallel = 1e-4;

/// Result of segmentDistance (layout after GeometricTools' DistSegmentSegment result).
struct SegmentDistanceResult {
  /// Minimum distance between the two segments [m] (|closest0 - closest1|).
  double distance = 0.0;
  /// Square of distance [m^2] (computed from the closest points, not from Q(s,t)).
  double squaredDistance = 0.0;
  /// Parameter of the closest point on segment 0, in [0, 1] [-]: closest0 = p0 + s (p1 - p0).
  double s = 0.0;
  /// Parameter of the closest point on segment 1, in [0, 1] [-]: closest1 = q0 + t (q1 - q0).
  double t = 0.0;
  /// Closest point on segment 0 [m].
  Vec3 closest0 = Vec3::Zero();
  /// Closest point on segment 1 [m].
  Vec3 closest1 = Vec3::Zero();
  /// Region of the (s,t) plane (0..8, Eberly 2005 labels, see the file comment) in which the
  /// unconstrained minimiser (s^, t^) was located; -1 when the segments were treated as parallel.
  int region = -1;
  /// True when the segments were treated as parallel: det <= kParallelTolerance a c, which
  /// includes zero-length segments.
  bool parallel = false;
};

/// Closest points of segment 0 (from p0 to p1) and segment 1 (from q0 to q1), points in [m].
/// Zero-length segments are allowed (point-point and point-segment distances).
/// When several pairs are at the minimum distance (parallel overlapping segments) the pair in the
/// middle of the overlap is returned.
/// Accuracy: the distance error is a few ulp of the coordinates' magnitude, also for nearly
/// parallel segments; below an angle of 1e-12 rad (parallel treatment) it is at most 2e-12 of the
/// shorter segment's length (analysis in SegmentDistance.cpp).
/// @throws tangle::Error if a coordinate is not finite or the squared distance overflows.
/// Reference: D. Eberly, "Distance Between Two Line Segments in 3D", Geometric Tools (2005).
SegmentDistanceResult segmentDistance(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1);

/// Gap [m] between two axis-aligned boxes [loA, hiA] and [loB, hiB] (0 where they overlap): a lower bound of
/// the distance between anything inside them, far cheaper than segmentDistance, for culling.
inline double boxGap(const Vec3& loA, const Vec3& hiA, const Vec3& loB, const Vec3& hiB) {
  return (loB - hiA).cwiseMax(loA - hiB).cwiseMax(0.0).norm();
}
/// boxGap of the bounding boxes of segments p0 p1 and q0 q1 [m]: at most segmentDistance.
inline double segmentBoxGap(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  return boxGap(p0.cwiseMin(p1), p0.cwiseMax(p1), q0.cwiseMin(q1), q0.cwiseMax(q1));
}

}  // namespace tangle::geometry
