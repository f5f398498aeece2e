#include "tangle/model/PrescribedMotion.hpp"

#include <algorithm>
#include <cmath>

#include "tangle/core/Ramp.hpp"

namespace tangle::model {

namespace {
Vec3 rowOffset(const std::array<double, 4>& row) { return Vec3(row[1], row[2], row[3]); }
}  // namespace

PrescribedMotion::PrescribedMotion(const EndMotionSpec& spec, double rampTime)
    : m_spec(spec), m_rampTime(rampTime) {
  const auto& tab = m_spec.table;
  const std::size_t n = tab.size();
  if (!m_spec.cubic || n < 2) return;
  // Clamped spline (zero end slopes): tridiagonal system for the second derivatives M_i, solved by the
  // Thomas algorithm (diagonally dominant: no pivoting needed).
  std::vector<double> lower(n, 0.0), diag(n, 0.0), upper(n, 0.0);
  std::vector<Vec3> rhs(n, Vec3::Zero());
  auto h = [&](std::size_t i) { return tab[i + 1][0] - tab[i][0]; };
  auto slope = [&](std::size_t i) { return Vec3((rowOffset(tab[i + 1]) - rowOffset(tab[i])) / h(i)); };
  diag[0] = 2.0 * h(0);
  upper[0] = h(0);
  rhs[0] = 6.0 * slope(0);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    lower[i] = h(i - 1);
    diag[i] = 2.0 * (h(i - 1) + h(i));
    upper[i] = h(i);
    rhs[i] = 6.0 * (slope(i) - slope(i - 1));
  }
  lower[n - 1] = h(n - 2);
  diag[n - 1] = 2.0 * h(n - 2);
  rhs[n - 1] = -6.0 * slope(n - 2);
  for (std::size_t i = 1; i < n; ++i) {
    const double f = lower[i] / diag[i - 1];
    diag[i] -= f * upper[i - 1];
    rhs[i] -= f * rhs[i - 1];
  }
  m_second.assign(n, Vec3::Zero());
  m_second[n - 1] = rhs[n - 1] / diag[n - 1];
  for (std::size_t i = n - 1; i-- > 0;) m_second[i] = (rhs[i] - upper[i] * m_second[i + 1]) / diag[i];
}

MotionValue PrescribedMotion::tableAt(double t) const {
  MotionValue m;
  const auto& tab = m_spec.table;
  if (t <= tab.front()[0]) {
    m.displacement = rowOffset(tab.front());
    return m;
  }
  const bool cubic = !m_second.empty();
  if (t > tab.back()[0] || (cubic && t == tab.back()[0])) {
    m.displacement = rowOffset(tab.back());
    return m;
  }
  // Segment [a, b] with a < t <= b (left-continuous velocity at the rows, see the header).
  const auto it = std::lower_bound(tab.begin(), tab.end(), t,
                                   [](const std::array<double, 4>& row, double x) { return row[0] < x; });
  const std::size_t ib = static_cast<std::size_t>(it - tab.begin());
  const std::size_t ia = ib - 1;
  const Vec3 pa = rowOffset(tab[ia]);
  const Vec3 pb = rowOffset(tab[ib]);
  const double h = tab[ib][0] - tab[ia][0];
  const double fb = (t - tab[ia][0]) / h;  // weight of b
  const double fa = 1.0 - fb;
  if (!cubic) {
    m.displacement = fa * pa + fb * pb;
    m.velocity = (pb - pa) / h;
    return m;
  }
  const Vec3& ma = m_second[ia];
  const Vec3& mb = m_second[ib];
  m.displacement = fa * pa + fb * pb + ((fa * fa * fa - fa) * ma + (fb * fb * fb - fb) * mb) * (h * h / 6.0);
  m.velocity = (pb - pa) / h - (3.0 * fa * fa - 1.0) / 6.0 * h * ma + (3.0 * fb * fb - 1.0) / 6.0 * h * mb;
  m.acceleration = fa * ma + fb * mb;
  return m;
}

PrescribedMotion::Overshoot PrescribedMotion::tableOvershoot() const {
  Overshoot worst;
  if (m_second.empty()) return worst;
  const auto& tab = m_spec.table;
  constexpr int kSamples = 64;  // per segment: the cubic's extremum within 1e-4 of its height
  for (std::size_t i = 0; i + 1 < tab.size(); ++i) {
    const Vec3 pa = rowOffset(tab[i]), pb = rowOffset(tab[i + 1]);
    for (int k = 1; k < kSamples; ++k) {
      const double t = tab[i][0] + (tab[i + 1][0] - tab[i][0]) * k / kSamples;
      const Vec3 x = tableAt(t).displacement;
      for (int axis = 0; axis < 3; ++axis) {
        const double beyond =
            std::max(x[axis] - std::max(pa[axis], pb[axis]), std::min(pa[axis], pb[axis]) - x[axis]);
        if (beyond > worst.distance) worst = {beyond, t, axis, tab[i][0], tab[i + 1][0]};
      }
    }
  }
  return worst;
}

MotionValue PrescribedMotion::at(double t) const {
  MotionValue m;
  if (!m_spec.enabled) return m;
  if (!m_spec.table.empty()) return tableAt(t);
  const double w = 2.0 * kPi / m_spec.period;
  const double s = std::sin(w * t + m_spec.phase);
  const double c = std::cos(w * t + m_spec.phase);
  const core::RampValue r = core::ramp(t, m_rampTime);
  // x = r(t) A sin(wt + phi): product rule for the derivatives.
  m.displacement = r.value * s * m_spec.amplitude;
  m.velocity = (r.rate * s + r.value * w * c) * m_spec.amplitude;
  m.acceleration = (r.accel * s + 2.0 * r.rate * w * c - r.value * w * w * s) * m_spec.amplitude;
  return m;
}

}  // namespace tangle::model
