/// @file RaoMotion.cpp
/// First-order vessel motion from RAOs (see RaoMotion.hpp and docs/theory.md (section 10)).

#include "tangle/vessel/RaoMotion.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "tangle/core/Error.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/vessel/HeadingTable.hpp"

namespace tangle::vessel {
namespace {

/// Angle wrapped into (-pi, pi] [rad].
double wrapPi(double angle) {
  double a = wrapTwoPi(angle);
  if (a > kPi) a -= 2.0 * kPi;
  return a;
}

/// Bracket of x in an ascending axis: indices i0, i1 and weight w of i1.
struct Bracket {
  std::size_t i0 = 0;
  std::size_t i1 = 0;
  double w = 0.0;
};

/// Linear bracket, clamped outside [axis.front(), axis.back()].
Bracket clampedBracket(const std::vector<double>& axis, double x) {
  Bracket b;
  const std::size_t n = axis.size();
  if (n == 1 || x <= axis.front()) return b;
  if (x >= axis.back()) {
    b.i0 = b.i1 = n - 1;
    return b;
  }
  const auto it = std::upper_bound(axis.begin(), axis.end(), x);
  b.i1 = static_cast<std::size_t>(it - axis.begin());
  b.i0 = b.i1 - 1;
  b.w = (x - axis[b.i0]) / (axis[b.i1] - axis[b.i0]);
  return b;
}

/// Periodic bracket over [0, 2 pi) (wrap-around between the last and the first heading).
Bracket periodicBracket(const std::vector<double>& axis, double heading) {
  Bracket b;
  const std::size_t n = axis.size();
  if (n == 1) return b;
  double x = wrapTwoPi(heading);
  if (x < axis.front() || x >= axis.back()) {
    b.i0 = n - 1;
    b.i1 = 0;
    if (x < axis.front()) x += 2.0 * kPi;
    b.w = (x - axis.back()) / (axis.front() + 2.0 * kPi - axis.back());
    return b;
  }
  const auto it = std::upper_bound(axis.begin(), axis.end(), x);
  b.i1 = static_cast<std::size_t>(it - axis.begin());
  b.i0 = b.i1 - 1;
  b.w = (x - axis[b.i0]) / (axis[b.i1] - axis[b.i0]);
  return b;
}

void validate(const model::RaoTable& t) {
  const std::size_t np = t.period.size();
  const std::size_t nh = t.heading.size();
  if (np == 0 || nh == 0) throw Error("RAO table: at least one period and one heading are needed");
  for (std::size_t i = 0; i < np; ++i) {
    if (!std::isfinite(t.period[i]) || t.period[i] <= 0.0) {
      throw Error(fmt::format("RAO table: period {} = {} s must be finite and > 0", i, t.period[i]));
    }
    if (i > 0 && !(t.period[i] > t.period[i - 1])) {
      throw Error(fmt::format("RAO table: periods must be strictly ascending (period {} = {} s follows {} s)", i,
                              t.period[i], t.period[i - 1]));
    }
  }
  for (std::size_t i = 0; i < nh; ++i) {
    const double h = t.heading[i];
    if (!std::isfinite(h) || h < 0.0 || h >= 2.0 * kPi) {
      throw Error(fmt::format("RAO table: heading {} = {} rad is outside [0, 2 pi)", i, h));
    }
    if (i > 0 && !(h > t.heading[i - 1])) {
      throw Error(fmt::format("RAO table: headings must be strictly ascending (heading {} = {} rad follows {} rad)",
                              i, h, t.heading[i - 1]));
    }
  }
  const auto checkGrid = [&](const std::vector<std::vector<std::array<double, 6>>>& g, const char* what) {
    if (g.size() != np) throw Error(fmt::format("RAO table: {} has {} period rows, expected {}", what, g.size(), np));
    for (std::size_t p = 0; p < np; ++p) {
      if (g[p].size() != nh) {
        throw Error(fmt::format("RAO table: {} row {} has {} headings, expected {}", what, p, g[p].size(), nh));
      }
      for (const auto& row : g[p]) {
        for (double v : row) {
          if (!std::isfinite(v)) throw Error(fmt::format("RAO table: {} row {} has a non-finite value", what, p));
        }
      }
    }
  };
  checkGrid(t.amplitude, "amplitude");
  checkGrid(t.phase, "phase");
}

}  // namespace

RaoMotion::RaoMotion(const model::RaoTable& raos, double vesselHeading, std::vector<Component> components)
    : m_raos(raos),
      m_empty(raos.period.empty() && raos.heading.empty() && raos.amplitude.empty() && raos.phase.empty()),
      m_rotation(Eigen::AngleAxisd(vesselHeading, Vec3::UnitZ()).toRotationMatrix()),
      m_components(std::move(components)) {
  if (!std::isfinite(vesselHeading)) throw Error("RaoMotion: the vessel heading is not finite");
  if (!m_empty) validate(m_raos);
  for (std::size_t i = 0; i < m_components.size(); ++i) {
    const Component& c = m_components[i];
    if (!std::isfinite(c.omega) || c.omega <= 0.0) {
      throw Error(fmt::format("RaoMotion: wave component {} has omega = {} rad/s (must be > 0)", i, c.omega));
    }
    if (!std::isfinite(c.amplitude) || c.amplitude < 0.0) {
      throw Error(fmt::format("RaoMotion: wave component {} has amplitude = {} m (must be >= 0)", i, c.amplitude));
    }
    if (!std::isfinite(c.waveNumber) || !std::isfinite(c.azimuth) || !std::isfinite(c.phase)) {
      throw Error(fmt::format("RaoMotion: wave component {} has a non-finite wave number, azimuth or phase", i));
    }
    if (m_empty) continue;
    ComponentResponse r{};
    r.amplitude = c.amplitude;
    r.omega = c.omega;
    r.kx = c.waveNumber * std::cos(c.azimuth);
    r.ky = c.waveNumber * std::sin(c.azimuth);
    r.phase = c.phase;
    interpolateRao(2.0 * kPi / c.omega, c.azimuth - vesselHeading, r.rao, r.lag);
    m_responses.push_back(r);
  }
}

void RaoMotion::interpolateRao(double period, double relativeHeading, std::array<double, 6>& amplitude,
                               std::array<double, 6>& phaseLag) const {
  amplitude.fill(0.0);
  phaseLag.fill(0.0);
  if (m_empty) return;
  const Bracket bp = clampedBracket(m_raos.period, period);
  const Bracket bh = periodicBracket(m_raos.heading, relativeHeading);
  const auto lerpAngle = [](double a, double b, double w) { return a + w * wrapPi(b - a); };
  for (int j = 0; j < 6; ++j) {
    const auto& a = m_raos.amplitude;
    const auto& p = m_raos.phase;
    const double a0 = (1.0 - bp.w) * a[bp.i0][bh.i0][j] + bp.w * a[bp.i1][bh.i0][j];
    const double a1 = (1.0 - bp.w) * a[bp.i0][bh.i1][j] + bp.w * a[bp.i1][bh.i1][j];
    amplitude[j] = (1.0 - bh.w) * a0 + bh.w * a1;
    const double p0 = lerpAngle(p[bp.i0][bh.i0][j], p[bp.i1][bh.i0][j], bp.w);
    const double p1 = lerpAngle(p[bp.i0][bh.i1][j], p[bp.i1][bh.i1][j], bp.w);
    phaseLag[j] = lerpAngle(p0, p1, bh.w);
  }
}

RaoMotion::Motion RaoMotion::at(double t, const Vec3& referencePoint, double ramp) const {
  Motion m;
  if (m_empty || ramp == 0.0) return m;
  Vec6 q = Vec6::Zero();
  Vec6 dq = Vec6::Zero();
  Vec6 ddq = Vec6::Zero();
  for (const ComponentResponse& r : m_responses) {
    const double chi = r.omega * t - r.kx * referencePoint.x() - r.ky * referencePoint.y() + r.phase;
    for (int j = 0; j < 6; ++j) {
      const double amp = r.amplitude * r.rao[j];
      const double arg = chi - r.lag[j];
      const double c = std::cos(arg);
      q(j) += amp * c;
      dq(j) -= amp * r.omega * std::sin(arg);
      ddq(j) -= amp * r.omega * r.omega * c;
    }
  }
  const auto toGlobal = [&](const Vec6& v) {
    Vec6 g;
    g.head<3>() = ramp * (m_rotation * v.head<3>());
    g.tail<3>() = ramp * (m_rotation * v.tail<3>());
    return g;
  };
  m.displacement = toGlobal(q);
  m.velocity = toGlobal(dq);
  m.acceleration = toGlobal(ddq);
  return m;
}

Vec3 RaoMotion::pointDisplacement(const Motion& m, const Mat3& rotation, const Vec3& offset) {
  return m.displacement.head<3>() + m.displacement.tail<3>().cross(rotation * offset);
}

Vec3 RaoMotion::pointVelocity(const Motion& m, const Mat3& rotation, const Vec3& offset) {
  return m.velocity.head<3>() + m.velocity.tail<3>().cross(rotation * offset);
}

Vec3 RaoMotion::pointAcceleration(const Motion& m, const Mat3& rotation, const Vec3& offset) {
  return m.acceleration.head<3>() + m.acceleration.tail<3>().cross(rotation * offset);
}

}  // namespace tangle::vessel
