#include "tangle/contact/ContactKinematics.hpp"

#include <algorithm>
#include <cmath>

namespace tangle::contact {

DistanceKinematics distanceKinematics(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1, double s,
                                      double t, bool sFree, bool tFree, double sign, bool wantHessian) {
  DistanceKinematics k;
  const double w[4] = {1.0 - s, s, -(1.0 - t), -t};
  const Vec3 u = w[0] * a0 + w[1] * a1 + w[2] * b0 + w[3] * b1;
  const double d = u.norm();
  k.distance = sign * d;
  k.normal = d > 0.0 ? Vec3(sign * u / d) : Vec3(Vec3::UnitZ());
  for (int i = 0; i < 4; ++i) k.gradient.segment<3>(3 * i) = w[i] * k.normal;
  if (!wantHessian || d <= 0.0) return k;
  // Hessian of V* = |u|^2 / 2 (envelope theorem over the free parameters).
  Mat12 hv = Mat12::Zero();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) hv.block<3, 3>(3 * i, 3 * j) = w[i] * w[j] * Mat3::Identity();
  Eigen::Matrix<double, 12, 2> b = Eigen::Matrix<double, 12, 2>::Zero();
  Vec3 m[2];
  int nFree = 0;
  if (sFree) {
    m[nFree] = a1 - a0;
    const double c[4] = {-1.0, 1.0, 0.0, 0.0};
    for (int i = 0; i < 4; ++i) b.block<3, 1>(3 * i, nFree) = w[i] * m[nFree] + c[i] * u;
    ++nFree;
  }
  if (tFree) {
    m[nFree] = -(b1 - b0);
    const double c[4] = {0.0, 0.0, 1.0, -1.0};
    for (int i = 0; i < 4; ++i) b.block<3, 1>(3 * i, nFree) = w[i] * m[nFree] + c[i] * u;
    ++nFree;
  }
  if (nFree == 1) {
    const double app = m[0].squaredNorm();
    if (app > 0.0) hv -= b.col(0) * b.col(0).transpose() / app;
  } else if (nFree == 2) {
    Eigen::Matrix2d app;
    app << m[0].dot(m[0]), m[0].dot(m[1]), m[1].dot(m[0]), m[1].dot(m[1]);
    const double det = app.determinant();
    if (std::abs(det) > 1e-12 * app(0, 0) * app(1, 1)) hv -= b * app.inverse() * b.transpose();
  }
  const Vec12 g = sign * k.gradient;  // gradient of the unsigned distance
  k.hessian = sign * (hv - g * g.transpose()) / d;
  return k;
}

bool contactInterval(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1, double reach, double& xi0,
                     double& xi1) {
  const Vec3 m = b1 - b0;
  const double mm = m.squaredNorm();
  if (mm <= 0.0) return false;
  // t(xi) = t0 + xi t1; perpendicular part r(xi) = r0 + xi r1.
  const double t0 = (a0 - b0).dot(m) / mm;
  const double t1 = (a1 - a0).dot(m) / mm;
  const Vec3 r0 = (a0 - b0) - t0 * m;
  const Vec3 r1 = (a1 - a0) - t1 * m;
  double lo = 0.0, hi = 1.0;
  // 0 <= t(xi) <= 1
  if (std::abs(t1) > 1e-14) {
    double x0 = -t0 / t1, x1 = (1.0 - t0) / t1;
    if (x0 > x1) std::swap(x0, x1);
    lo = std::max(lo, x0);
    hi = std::min(hi, x1);
  } else if (t0 < 0.0 || t0 > 1.0) {
    return false;
  }
  if (lo >= hi) return false;
  // |r(xi)|^2 < reach^2: a xi^2 + 2 b xi + c < 0
  const double a = r1.squaredNorm(), bq = r0.dot(r1), c = r0.squaredNorm() - reach * reach;
  if (a <= 1e-14 * std::max(1.0, r0.squaredNorm())) {
    if (c >= 0.0) return false;
  } else {
    const double disc = bq * bq - a * c;
    if (disc <= 0.0) return false;
    const double sq = std::sqrt(disc);
    lo = std::max(lo, (-bq - sq) / a);
    hi = std::min(hi, (-bq + sq) / a);
  }
  if (lo >= hi) return false;
  xi0 = lo;
  xi1 = hi;
  return true;
}

double crossingAngle(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
  const Vec3 ta = a1 - a0, tb = b1 - b0;
  const double na = ta.norm(), nb = tb.norm();
  if (na <= 0.0 || nb <= 0.0) return 0.5 * 3.141592653589793;
  const double c = std::min(1.0, std::abs(ta.dot(tb)) / (na * nb));
  const double sn = ta.cross(tb).norm() / (na * nb);
  return std::atan2(sn, c);
}

double pointToPointWeight(double angle, double lower, double upper) {
  if (angle <= lower) return 0.0;
  if (angle >= upper) return 1.0;
  const double x = (angle - lower) / (upper - lower);
  return x * x * (3.0 - 2.0 * x);
}

}  // namespace tangle::contact
