#include "tangle/geometry/HullShape.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tangle/core/Error.hpp"
#include "tangle/geometry/Rotation.hpp"

namespace tangle::geometry {
namespace {

/// Number of intervals of a length at most `spacing` long (at least one).
int intervals(double length, double spacing) {
  return std::max(1, static_cast<int>(std::ceil(length / spacing - 1e-9)));
}

/// A ring of points about `centre` in the plane normal to the unit `axis`, radius r.
void addRing(std::vector<Vec3>& out, const Vec3& centre, const Mat3& frame, double r, int count) {
  for (int k = 0; k < count; ++k) {
    const double a = 2.0 * std::numbers::pi * k / count;
    out.push_back(centre + r * (std::cos(a) * frame.col(1) + std::sin(a) * frame.col(2)));
  }
}

int ringCount(double diameter, double spacing) {
  return std::max(8, intervals(std::numbers::pi * diameter, spacing));
}

void requireFinite(const Vec3& v, const char* what) {
  if (!v.allFinite()) throw Error(fmt::format("hull shape: {} is not finite", what));
}

}  // namespace

HullShape HullShape::box(const Vec3& centre, const Vec3& size) {
  requireFinite(centre, "the box's centre");
  if (!(size.array() > 0.0).all() || !size.allFinite())
    throw Error("hull shape: a box's size must be three lengths > 0");
  HullShape s;
  s.m_kind = Kind::Box;
  s.m_centre = centre;
  s.m_size = size;
  return s;
}

HullShape HullShape::cylinder(const Vec3& endA, const Vec3& endB, double diameter) {
  requireFinite(endA, "end_a");
  requireFinite(endB, "end_b");
  if (!(diameter > 0.0) || !std::isfinite(diameter)) throw Error("hull shape: a diameter must be > 0");
  if ((endB - endA).norm() <= 0.0) throw Error("hull shape: a cylinder's ends must differ");
  HullShape s;
  s.m_kind = Kind::Cylinder;
  s.m_endA = endA;
  s.m_endB = endB;
  s.m_centre = 0.5 * (endA + endB);
  s.m_size = Vec3(diameter, (endB - endA).norm(), 0.0);
  return s;
}

HullShape HullShape::capsule(const Vec3& endA, const Vec3& endB, double diameter) {
  HullShape s = cylinder(endA, endA == endB ? Vec3(endA + Vec3::UnitZ()) : endB, diameter);
  s.m_kind = Kind::Capsule;
  s.m_endB = endB;
  s.m_centre = 0.5 * (endA + endB);
  s.m_size = Vec3(diameter, (endB - endA).norm(), 0.0);
  return s;
}

std::string HullShape::kindName() const {
  switch (m_kind) {
    case Kind::Box:
      return "box";
    case Kind::Cylinder:
      return "cylinder";
    case Kind::Capsule:
      return "capsule";
  }
  return "shape";
}

ShapeDistance HullShape::distance(const Vec3& p) const {
  ShapeDistance out;
  if (m_kind == Kind::Box) {
    // Quilez's box distance: q = |p - c| - h per axis; outside, |max(q, 0)|; inside, the largest q.
    const Vec3 local = p - m_centre;
    const Vec3 q = local.cwiseAbs() - 0.5 * m_size;
    const Vec3 sign = local.unaryExpr([](double x) { return x < 0.0 ? -1.0 : 1.0; });
    const Vec3 outside = q.cwiseMax(0.0);
    if ((q.array() > 0.0).any()) {
      out.distance = outside.norm();
      out.normal = sign.cwiseProduct(outside) / out.distance;
    } else {
      int k = 0;
      out.distance = q.maxCoeff(&k);
      out.normal = Vec3::Zero();
      out.normal[k] = sign[k];
    }
    return out;
  }
  const Vec3 d = m_endB - m_endA;
  const double length = d.norm();
  const Vec3 axis = length > 0.0 ? Vec3(d / length) : Vec3(Vec3::UnitZ());
  const double radius = 0.5 * m_size.x();
  const double s = (p - m_endA).dot(axis);
  if (m_kind == Kind::Capsule) {
    const Vec3 nearest = m_endA + std::clamp(s, 0.0, length) * axis;
    const Vec3 w = p - nearest;
    const double r = w.norm();
    out.distance = r - radius;
    // On the axis (r = 0) any direction normal to it will do; take the frame's.
    out.normal = r > 0.0 ? Vec3(w / r) : Vec3(frameFromTangent(axis).col(1));
    return out;
  }
  // Cylinder: the box distance in the (radial, axial) half plane.
  const Vec3 w = p - m_endA - s * axis;
  const double r = w.norm();
  const Vec3 radial = r > 0.0 ? Vec3(w / r) : Vec3(frameFromTangent(axis).col(1));
  const Vec3 axial = s < 0.5 * length ? Vec3(-axis) : axis;
  const double dr = r - radius;
  const double da = std::max(-s, s - length);
  if (dr > 0.0 || da > 0.0) {
    const double er = std::max(dr, 0.0), ea = std::max(da, 0.0);
    out.distance = std::hypot(er, ea);
    out.normal = (er * radial + ea * axial) / out.distance;
  } else if (dr > da) {
    out.distance = dr;
    out.normal = radial;
  } else {
    out.distance = da;
    out.normal = axial;
  }
  return out;
}

std::vector<Vec3> HullShape::surfacePoints(double spacing) const {
  if (!(spacing > 0.0)) throw Error("hull shape: the spacing of surface points must be > 0");
  std::vector<Vec3> out;
  if (m_kind == Kind::Box) {
    const Vec3 h = 0.5 * m_size;
    // The 12 edges: along each axis a, the four edges at the corners (+-h_b, +-h_c); corners once (the
    // edges along x carry them, the others leave out their end points).
    for (int a = 0; a < 3; ++a) {
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      const int n = intervals(m_size[a], spacing);
      for (int sb = -1; sb <= 1; sb += 2)
        for (int sc = -1; sc <= 1; sc += 2)
          for (int i = (a == 0 ? 0 : 1); i <= (a == 0 ? n : n - 1); ++i) {
            Vec3 q;
            q[a] = -h[a] + m_size[a] * i / n;
            q[b] = sb * h[b];
            q[c] = sc * h[c];
            out.push_back(m_centre + q);
          }
    }
    return out;
  }
  const Vec3 d = m_endB - m_endA;
  const double length = d.norm();
  const Mat3 frame = frameFromTangent(length > 0.0 ? Vec3(d / length) : Vec3(Vec3::UnitZ()));
  const double radius = 0.5 * m_size.x();
  const int ring = ringCount(m_size.x(), spacing);
  // Rings at both ends and generators between them (the rings' points are the generators' ends).
  const int n = length > 0.0 ? intervals(length, spacing) : 0;
  for (int i = 0; i <= n; ++i)
    addRing(out, m_endA + (n > 0 ? static_cast<double>(i) / n : 0.0) * d, frame, radius, ring);
  if (m_kind == Kind::Cylinder) {
    // The end faces: concentric rings down to the centre.
    const int radial = intervals(radius, spacing);
    for (const Vec3& end : {m_endA, m_endB}) {
      out.push_back(end);
      for (int j = 1; j < radial; ++j)
        addRing(out, end, frame, radius * j / radial,
                std::max(8, ringCount(2.0 * radius * j / radial, spacing)));
    }
    return out;
  }
  // Capsule: the hemispheres as latitude rings and the poles.
  const int latitudes = std::max(2, intervals(0.5 * std::numbers::pi * radius, spacing));
  for (int e = 0; e < 2; ++e) {
    const Vec3 end = e == 0 ? m_endA : m_endB;
    const Vec3 outward = (e == 0 ? -1.0 : 1.0) * frame.col(0);
    for (int j = 1; j < latitudes; ++j) {
      const double phi = 0.5 * std::numbers::pi * j / latitudes;  // from the equator
      const double r = radius * std::cos(phi);
      addRing(out, end + radius * std::sin(phi) * outward, frame, r, ringCount(2.0 * r, spacing));
    }
    out.push_back(end + radius * outward);
  }
  return out;
}

double HullShape::reach(const Vec3& c) const {
  if (m_kind == Kind::Box) return (c - m_centre).cwiseAbs().norm() + 0.5 * m_size.norm();
  // A cylinder's or capsule's surface is within r of its axis segment, whose points are no further from c
  // than its farther end (triangle inequality, convexity).
  return std::max((m_endA - c).norm(), (m_endB - c).norm()) + 0.5 * m_size.x();
}

double HullShape::volume() const {
  const double r = 0.5 * m_size.x();
  switch (m_kind) {
    case Kind::Box:
      return m_size.prod();
    case Kind::Cylinder:
      return std::numbers::pi * r * r * m_size.y();
    case Kind::Capsule:
      return std::numbers::pi * r * r * (m_size.y() + 4.0 / 3.0 * r);
  }
  return 0.0;
}

std::string HullShape::describe() const {
  if (m_kind == Kind::Box)
    return fmt::format("box {:.3g} x {:.3g} x {:.3g} m centred at ({:.3g}, {:.3g}, {:.3g}) m", m_size.x(),
                       m_size.y(), m_size.z(), m_centre.x(), m_centre.y(), m_centre.z());
  return fmt::format("{} of diameter {:.3g} m from ({:.3g}, {:.3g}, {:.3g}) to ({:.3g}, {:.3g}, {:.3g}) m",
                     kindName(), m_size.x(), m_endA.x(), m_endA.y(), m_endA.z(), m_endB.x(), m_endB.y(),
                     m_endB.z());
}

}  // namespace tangle::geometry
