#include "tangle/vessel/HullImpacts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "tangle/core/OutputFile.hpp"

namespace tangle::vessel {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void close(HullImpact& e, double time, double reboundSpeed, bool open) {
  e.endTime = time;
  e.open = open;
  e.reboundVelocity = open ? kNaN : reboundSpeed;
  const double change = e.impactVelocity + e.reboundVelocity;
  e.eq5Mass = open || !(change > 0.0) ? kNaN : e.impulse / change;
  const double mass = e.lineOnHull || !std::isfinite(e.bodiesMass) ? e.eq5Mass : e.bodiesMass;
  e.impactEnergy = e.impact && std::isfinite(mass) ? 0.5 * mass * e.impactVelocity * e.impactVelocity : 0.0;
}

}  // namespace

void HullImpacts::commit(double time, double dt, const std::vector<HullPairReading>& readings) {
  for (std::size_t p = 0; p < m_pairs.size(); ++p) {
    const HullPairReading& now = readings[p];
    const HullPairReading& before = m_last[p];
    const bool touching = now.force > 0.0;
    int& open = m_open[p];
    if (open >= 0) {
      HullImpact& e = m_events[static_cast<std::size_t>(open)];
      // Trapezoidal impulse of the total normal force between the two accepted states.
      e.impulse += 0.5 * (before.force + now.force) * dt;
      e.peakForce = std::max(e.peakForce, now.force);
      e.maxPenetration = std::max(e.maxPenetration, now.penetration);
      if (!touching) {
        close(e, time, now.separationSpeed, false);
        open = -1;
      }
    } else if (touching) {
      HullImpact e = m_pairs[p];
      e.startTime = time;
      e.position = now.position;
      // The approach before the touch (the state before it, when the pair was within reach then).
      e.impactVelocity = std::max(0.0, before.near ? before.approachSpeed : now.approachSpeed);
      e.impact = e.impactVelocity > m_threshold && dt > 0.0;
      e.bodiesMass = now.bodiesMass;
      e.peakForce = now.force;
      e.maxPenetration = now.penetration;
      e.impulse = 0.5 * now.force * dt;  // the force rose from zero within the step
      open = static_cast<int>(m_events.size());
      m_events.push_back(e);
    }
    m_last[p] = now;
  }
}

void HullImpacts::finish(double time) {
  for (int& open : m_open) {
    if (open < 0) continue;
    close(m_events[static_cast<std::size_t>(open)], time, 0.0, true);
    open = -1;
  }
}

int HullImpacts::impactCount() const {
  return static_cast<int>(
      std::count_if(m_events.begin(), m_events.end(), [](const HullImpact& e) { return e.impact; }));
}

void HullImpacts::write(const std::filesystem::path& folder) const {
  core::OutputFile f(folder / "hull_impacts.csv");
  f.write(
      "body_a,body_b,kind,start_time_s,end_time_s,x_m,y_m,z_m,impact_velocity_m_s,rebound_velocity_m_s,"
      "restitution,peak_force_N,impulse_Ns,max_penetration_m,bodies_effective_mass_kg,eq5_mass_kg,"
      "impact_energy_J,open_at_end\n");
  const auto number = [](double v, const char* format) {
    return std::isfinite(v) ? fmt::format(fmt::runtime(format), v) : std::string();
  };
  for (const HullImpact& e : m_events) {
    const double ratio = e.impactVelocity > 0.0 ? e.reboundVelocity / e.impactVelocity : kNaN;
    f.write(fmt::format(
        "\"{}\",\"{}\",{},{:.4f},{:.4f},{:.3f},{:.3f},{:.3f},{:.5f},{},{},{:.6g},{:.6g},{:.5g},{},{},{},{}\n",
        e.bodyA, e.bodyB,
        e.impact ? (e.lineOnHull ? "line_impact" : "hull_impact")
                 : (e.lineOnHull ? "line_contact" : "hull_contact"),
        e.startTime, e.endTime, e.position.x(), e.position.y(), e.position.z(), e.impactVelocity,
        number(e.reboundVelocity, "{:.5f}"), number(ratio, "{:.4f}"), e.peakForce, e.impulse,
        e.maxPenetration, number(e.bodiesMass, "{:.6g}"), number(e.eq5Mass, "{:.6g}"),
        e.impact ? number(e.impactEnergy, "{:.6g}") : std::string(), e.open ? "yes" : "no"));
  }
  f.close();
}

std::string HullImpacts::terminalSummary() const {
  const HullImpact* largest = nullptr;
  for (const HullImpact& e : m_events)
    if (e.impact && (!largest || e.impactEnergy > largest->impactEnergy)) largest = &e;
  if (!largest)
    return fmt::format("hull contacts: {} event(s), no impact above {} m/s (dynamics/hull_impacts.csv)\n",
                       m_events.size(), m_threshold);
  return fmt::format(
      "hull impacts: {} (dynamics/hull_impacts.csv); largest {:.4g} J: {} '{}' on '{}' at t = {:.2f} s, "
      "{:.3f} m/s, rebound {:.3f} m/s, peak force {:.4g} N, mass {:.4g} kg\n",
      impactCount(), largest->impactEnergy, largest->lineOnHull ? "line" : "vessel", largest->bodyA,
      largest->bodyB, largest->startTime, largest->impactVelocity, largest->reboundVelocity,
      largest->peakForce,
      largest->lineOnHull || !std::isfinite(largest->bodiesMass) ? largest->eq5Mass : largest->bodiesMass);
}

}  // namespace tangle::vessel
