#include "tangle/time/PrescribedMotion.hpp"

#include <algorithm>
#include <cmath>

#include "tangle/time/Ramp.hpp"

namespace tangle::time {

MotionValue PrescribedMotion::at(double t) const {
  MotionValue m;
  if (!m_spec.enabled) return m;
  if (!m_spec.table.empty()) {
    const auto& tab = m_spec.table;
    if (t <= tab.front()[0]) {
      m.displacement = Vec3(tab.front()[1], tab.front()[2], tab.front()[3]);
      return m;
    }
    if (t >= tab.back()[0]) {
      m.displacement = Vec3(tab.back()[1], tab.back()[2], tab.back()[3]);
      return m;
    }
    const auto it = std::upper_bound(tab.begin(), tab.end(), t,
                                     [](double x, const std::array<double, 4>& row) { return x < row[0]; });
    const auto& b = *it;
    const auto& a = *(it - 1);
    const double h = b[0] - a[0];
    const double f = (t - a[0]) / h;
    const Vec3 pa(a[1], a[2], a[3]);
    const Vec3 pb(b[1], b[2], b[3]);
    m.displacement = pa + f * (pb - pa);
    m.velocity = (pb - pa) / h;  // piecewise constant; acceleration zero inside a segment
    return m;
  }
  const double w = 2.0 * kPi / m_spec.period;
  const double s = std::sin(w * t + m_spec.phase);
  const double c = std::cos(w * t + m_spec.phase);
  const RampValue r = ramp(t, m_rampTime);
  // x = r(t) A sin(wt + phi): product rule for the derivatives.
  m.displacement = r.value * s * m_spec.amplitude;
  m.velocity = (r.rate * s + r.value * w * c) * m_spec.amplitude;
  m.acceleration = (r.accel * s + 2.0 * r.rate * w * c - r.value * w * w * s) * m_spec.amplitude;
  return m;
}

}  // namespace tangle::time
