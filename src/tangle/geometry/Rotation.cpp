#include "tangle/geometry/Rotation.hpp"

#include <cmath>

namespace tangle::geometry {

Mat3 skew(const Vec3& v) {
  Mat3 s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

Vec3 axial(const Mat3& a) {
  return 0.5 * Vec3(a(2, 1) - a(1, 2), a(0, 2) - a(2, 0), a(1, 0) - a(0, 1));
}

Mat3 expMap(const Vec3& theta) {
  const double angle = theta.norm();
  const Mat3 s = skew(theta);
  double a, b;  // R = I + a S + b S^2
  if (angle < 1e-6) {
    // Taylor series of sin(x)/x and (1 - cos x)/x^2.
    const double a2 = angle * angle;
    a = 1.0 - a2 / 6.0;
    b = 0.5 - a2 / 24.0;
  } else {
    a = std::sin(angle) / angle;
    b = (1.0 - std::cos(angle)) / (angle * angle);
  }
  return Mat3::Identity() + a * s + b * s * s;
}

Vec3 logMap(const Mat3& r) {
  // Eigen's AngleAxis uses a stable algorithm for angles near 0 and pi.
  const Eigen::AngleAxisd aa(r);
  return aa.angle() * aa.axis();
}

Mat3 frameFromTangent(const Vec3& t, const Vec3& hint) {
  const Vec3 e1 = t.normalized();
  Vec3 h = hint - hint.dot(e1) * e1;
  if (h.norm() < 1e-8) {
    const Vec3 alt = std::abs(e1.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    h = alt - alt.dot(e1) * e1;
  }
  const Vec3 e2 = h.normalized();
  Mat3 f;
  f.col(0) = e1;
  f.col(1) = e2;
  f.col(2) = e1.cross(e2);
  return f;
}

Mat3 rotationBetween(const Vec3& a, const Vec3& b) {
  return Eigen::Quaterniond::FromTwoVectors(a, b).toRotationMatrix();
}

}  // namespace tangle::geometry
