/// @file ViscoelasticAxialLaw.cpp
#include "tangle/element/ViscoelasticAxialLaw.hpp"

#include <fmt/format.h>

#include <cmath>

#include "tangle/core/Error.hpp"

namespace tangle::element {

ViscoelasticAxialLaw::ViscoelasticAxialLaw(const ViscoelasticConstants& c) : m_c(c) {
  if (!(c.staticStiffness > 0.0))
    throw Error(fmt::format("viscoelastic law: EA = {} N, expected > 0", c.staticStiffness));
  if (!(c.dynamicStiffness > c.staticStiffness))
    throw Error(fmt::format("viscoelastic law: the dynamic stiffness {} N must exceed the static one {} N",
                            c.dynamicStiffness, c.staticStiffness));
  if (!(c.dynamicStiffnessSlope >= 0.0) || !std::isfinite(c.dynamicStiffnessSlope))
    throw Error(fmt::format("viscoelastic law: the dynamic stiffness slope {} must be >= 0",
                            c.dynamicStiffnessSlope));
  if (!(c.slowDamping > 0.0) || !std::isfinite(c.slowDamping))
    throw Error(fmt::format("viscoelastic law: the slow damping {} N s must be > 0", c.slowDamping));
  if (!(c.dynamicDamping >= 0.0) || !std::isfinite(c.dynamicDamping))
    throw Error(fmt::format("viscoelastic law: the dynamic damping {} N s must be >= 0", c.dynamicDamping));
}

double ViscoelasticAxialLaw::dynamicStiffnessAt(double x) const {
  const double a = m_c.dynamicStiffness, ea = m_c.staticStiffness, beta = m_c.dynamicStiffnessSlope;
  if (beta == 0.0 || x < 0.0) return a;
  const double b = a + ea + beta * ea * x;
  // b^2 - 4 a EA = (a - EA (1 + beta x))^2 + 4 a EA beta x > 0: two real roots; the larger is > EA.
  return 0.5 * (b + std::sqrt(b * b - 4.0 * a * ea));
}

double ViscoelasticAxialLaw::staticBranchStiffnessAt(double x) const {
  const double ea2 = dynamicStiffnessAt(x);
  return ea2 * m_c.staticStiffness / (ea2 - m_c.staticStiffness);
}

ViscoelasticAxialLaw::Step ViscoelasticAxialLaw::step(double strain, double strainRate, double x0,
                                                      double dt) const {
  const double ea2 = dynamicStiffnessAt(x0);
  const double ea1 = ea2 * m_c.staticStiffness / (ea2 - m_c.staticStiffness);
  const double a = ea1 + ea2;
  // Backward Euler: (BA + BA_d) (x - x0) / dt = EA_2 eps - (EA_1 + EA_2) x + BA_d eps', so
  // x - x0 = drive dt / den with drive = EA_2 eps + BA_d eps' - (EA_1 + EA_2) x0, den = BA + BA_d + (EA_1 +
  // EA_2) dt (the increment itself: no cancellation of c x0 / dt against c x / dt when dt is small).
  const double drive = ea2 * strain + m_c.dynamicDamping * strainRate - a * x0;
  const double den = m_c.slowDamping + m_c.dynamicDamping + a * dt;
  const double x = x0 + drive * dt / den;
  // N = EA_1 x + BA (x - x0) / dt = EA_1 x + BA drive / den; dx/d eps = EA_2 dt / den, dx/d eps' = BA_d dt /
  // den.
  const double dNdx = ea1 + m_c.slowDamping / dt;
  return {x, ea1 * x + m_c.slowDamping * drive / den, dNdx * ea2 * dt / den,
          dNdx * m_c.dynamicDamping * dt / den};
}

double ViscoelasticAxialLaw::relaxedSlowStrain(double strain) const {
  // EA_1(x) x = EA eps. Constant EA_d: x = EA eps / EA_1 at once. Load-dependent: EA_1 falls as x grows (EA_2
  // rises), so the fixed point x = EA eps / EA_1(x) converges (its map's slope is below 1 for beta EA x <<
  // EA_2; the iteration stops at round-off or after 100 passes).
  double x = m_c.staticStiffness * strain / staticBranchStiffnessAt(0.0);
  if (m_c.dynamicStiffnessSlope == 0.0) return x;
  for (int k = 0; k < 100; ++k) {
    const double next = m_c.staticStiffness * strain / staticBranchStiffnessAt(x);
    const bool done = std::abs(next - x) <= 1e-15 * std::max(std::abs(x), 1e-300);
    x = next;
    if (done) break;
  }
  return x;
}

}  // namespace tangle::element
