#pragma once
/// @file ContactKinematics.hpp
/// Contact detection geometry (narrow phase) and its derivatives.
///
/// The distance between a point xA(s) on segment A = (a0, a1) and a point xB(t) on segment B = (b0, b1),
/// xA(s) = (1 - s) a0 + s a1, xB(t) = (1 - t) b0 + t b1, where each parameter is either held fixed (a
/// Gauss point of the slave line, a clamped end of a segment) or free and at the minimum of the distance
/// (a closest-point projection). With u = xA - xB and V = |u|^2 / 2, the value function of the projection
/// V*(q) = min_p V(q, p) over the free parameters p has (envelope theorem)
///     grad V* = dV/dq,        Hess V* = V_qq - V_qp V_pp^-1 V_pq,
/// because dp/dq = -V_pp^-1 V_pq at the minimum. For linear shape functions V_qq(i, j) = w_i w_j I,
/// V_{x_i p_k} = w_i m_k + c_ik u (m_k = du/dp_k, c_ik = d w_i / d p_k), V_pp(k, l) = m_k . m_l. The
/// distance d = sqrt(2 V*) then has grad d = grad V* / d = (w_i n) and Hess d = (Hess V* - grad d grad d^T) / d.
/// These are exact (the true closest points, never a distance along an approximate normal); docs/theory.md
/// section 9.3.

#include <Eigen/Dense>

#include "tangle/core/Types.hpp"

namespace tangle::contact {

/// ABC blending: line-to-line only below this crossing angle, point-to-point only above kBlendUpper [rad].
inline constexpr double kBlendLower = 10.0 * 3.141592653589793 / 180.0;
inline constexpr double kBlendUpper = 20.0 * 3.141592653589793 / 180.0;
/// Gauss points per contact interval of the line-to-line part.
inline constexpr int kGaussPoints = 4;
/// Regularisation depth of the line-to-line penalty law as a fraction of the sum of the radii [-].
inline constexpr double kRegularisationFraction = 0.01;

using Vec12 = Eigen::Matrix<double, 12, 1>;
using Mat12 = Eigen::Matrix<double, 12, 12>;

/// Distance between two points on two segments, with its first and second derivatives with respect to
/// the 12 node coordinates (a0, a1, b0, b1).
struct DistanceKinematics {
  double distance = 0.0;  ///< sign * |xA - xB| [m]
  Vec3 normal = Vec3::UnitZ();  ///< sign * (xA - xB) / |xA - xB|: unit normal from B to A
  Vec12 gradient = Vec12::Zero();  ///< d distance / dq
  Mat12 hessian = Mat12::Zero();   ///< d^2 distance / dq^2 (only if requested)
};

/// @param sFree, tFree whether s (t) is a free projection parameter (then it must be at the minimum of
///        the distance over that parameter) or held fixed
/// @param sign +1, or -1 to measure the distance along the reversed direction (lines that have passed
///        through each other keep the normal of the side they came from)
DistanceKinematics distanceKinematics(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1, double s,
                                      double t, bool sFree, bool tFree, double sign, bool wantHessian);

/// Interval [xi0, xi1] of the slave segment A (parameter xi in [0, 1]) whose points project orthogonally
/// into the master segment B (t in [0, 1]) and lie closer than `reach` to B's axis. The distance to B's
/// axis is linear-plus-quadratic in xi, so the interval is exact (integration interval segmentation,
/// Meier, Popp & Wall 2016, sec. 4.4). Returns false if empty.
bool contactInterval(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1, double reach, double& xi0,
                     double& xi1);

/// Orthogonal projection parameter of point p onto the axis of segment (b0, b1) (not clamped).
inline double projectOnAxis(const Vec3& p, const Vec3& b0, const Vec3& b1) {
  const Vec3 m = b1 - b0;
  const double mm = m.squaredNorm();
  return mm > 0.0 ? (p - b0).dot(m) / mm : 0.0;
}

/// Angle [rad] in [0, pi/2] between the axes of two segments.
double crossingAngle(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1);

/// Weight in [0, 1] of the point-to-point part at crossing angle `angle` [rad] (ABC blending): 0 below
/// `lower`, 1 above `upper`, a C1 cubic (smoothstep) in between; the line-to-line part gets 1 - weight.
double pointToPointWeight(double angle, double lower, double upper);

}  // namespace tangle::contact
