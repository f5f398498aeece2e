#pragma once
/// @file Rotation.hpp
/// Rotation utilities: skew matrices and the exponential/logarithm maps of SO(3).
/// Rotations are composed multiplicatively (R <- exp(dtheta) R, spatial increments), never by
/// adding angles (Crisfield 1997, "Non-linear finite element analysis of solids and structures",
/// vol. 2, ch. 16-17).

#include "tangle/core/Types.hpp"

namespace tangle::geometry {

/// Skew-symmetric matrix S(v) with S(v) w = v x w.
Mat3 skew(const Vec3& v);
/// Axial vector of the skew part: vee((A - A^T)/2).
Vec3 axial(const Mat3& a);
/// Rodrigues' formula: rotation matrix of the rotation vector theta [rad].
Mat3 expMap(const Vec3& theta);
/// Rotation vector [rad] of a rotation matrix (|result| <= pi), stable near zero.
Vec3 logMap(const Mat3& r);
/// An orthonormal right-handed frame whose first column is the unit vector t; the second column is
/// the projection of `hint` (or of a default axis when hint is parallel to t).
Mat3 frameFromTangent(const Vec3& t, const Vec3& hint = Vec3::UnitZ());
/// Smallest rotation taking unit vector a onto unit vector b (parallel transport of frames).
Mat3 rotationBetween(const Vec3& a, const Vec3& b);

}  // namespace tangle::geometry
