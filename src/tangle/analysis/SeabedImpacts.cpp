#include "tangle/analysis/SeabedImpacts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "tangle/core/OutputFile.hpp"

namespace tangle::analysis {

SeabedImpacts::SeabedImpacts(const model::Model& model, double impactVelocityThreshold)
    : m_model(&model),
      m_seabed(model.environment().seabed, model.sharedSeabedSurface()),
      m_threshold(impactVelocityThreshold) {}

std::vector<SeabedImpacts::NodeContact> SeabedImpacts::contactsOf(const model::State& state, int l) const {
  const model::Model& m = *m_model;
  const model::Line& line = m.lines()[static_cast<std::size_t>(l)];
  const model::DofMap& dofs = m.dofs();
  std::vector<NodeContact> out;
  for (int n = line.firstNode; n <= line.lastNode(); ++n) {
    const std::size_t i = static_cast<std::size_t>(n);
    const double radius = 0.5 * m.nodeContactDiameter()[i];
    if (m_seabed.penetration(state.position[i], radius) <= 0.0) continue;
    const int d = dofs.firstDof(n);
    // A node held in all three translations takes no seabed reaction (Assembler::addSeabed).
    if (dofs.equation(d) < 0 && dofs.equation(d + 1) < 0 && dofs.equation(d + 2) < 0) continue;
    const Vec3 v = state.velocity.segment<3>(d);
    const seabed::SeabedNodeReaction r =
        m_seabed.reaction(state.position[i], v, m.tributaryLength()[i], radius, true);
    if (r.normalForce <= 0.0) continue;
    out.push_back({n, r.normalForce, r.normal.dot(v), r.normal});
  }
  return out;
}

std::size_t SeabedImpacts::patchEnd(const std::vector<NodeContact>& contacts, std::size_t begin) {
  std::size_t k = begin + 1;
  while (k < contacts.size() && contacts[k].node - contacts[k - 1].node <= kReachNodes) ++k;
  return k;
}

void SeabedImpacts::endPhase(SeabedImpact& e, double time, double normalVelocity) {
  e.phaseOpen = false;
  e.phaseEndTime = time;
  e.phaseVelocityChange = normalVelocity - e.startNormalVelocity;
  // Eq. 5 over the phase, when the approach was measurably stopped.
  if (e.phaseVelocityChange > 0.0) {
    e.eq5Mass = e.phaseImpulse / e.phaseVelocityChange;
    if (e.impact) e.impactEnergy = 0.5 * e.eq5Mass * e.impactVelocity * e.impactVelocity;
  }
}

void SeabedImpacts::start(const model::State& state) {
  m_events.clear();
  m_open.clear();
  m_lastVelocity = state.velocity;
  for (int l = 0; l < static_cast<int>(m_model->lines().size()); ++l) {
    const model::Line& line = m_model->lines()[static_cast<std::size_t>(l)];
    const std::vector<NodeContact> contacts = contactsOf(state, l);
    for (std::size_t begin = 0, k = 0; begin < contacts.size(); begin = k) {
      k = patchEnd(contacts, begin);
      // A resting contact (statics): never an impact. Where it is: its first node.
      SeabedImpact e;
      e.line = l;
      e.startTime = e.endTime = e.phaseEndTime = state.time;
      e.firstNode = contacts[begin].node;
      e.lastNode = contacts[k - 1].node;
      e.arcLength = line.arcLength[static_cast<std::size_t>(e.firstNode - line.firstNode)];
      e.position = state.position[static_cast<std::size_t>(e.firstNode)];
      e.phaseOpen = false;
      e.eq5Mass = std::numeric_limits<double>::quiet_NaN();
      double force = 0.0;
      for (std::size_t j = begin; j < k; ++j) force += contacts[j].force;
      e.peakForce = force;
      e.lastForce = force;
      m_open.push_back(static_cast<int>(m_events.size()));
      m_events.push_back(e);
    }
  }
}

void SeabedImpacts::commit(const model::State& state, double dt) {
  const model::Model& m = *m_model;
  const model::DofMap& dofs = m.dofs();
  std::vector<int> stillOpen;
  for (int l = 0; l < static_cast<int>(m.lines().size()); ++l) {
    const model::Line& line = m.lines()[static_cast<std::size_t>(l)];
    const std::vector<NodeContact> contacts = contactsOf(state, l);
    for (std::size_t begin = 0, k = 0; begin < contacts.size(); begin = k) {
      k = patchEnd(contacts, begin);  // one patch: touching nodes at most kReachNodes apart
      const int first = contacts[begin].node, last = contacts[k - 1].node;
      double force = 0.0, weighted = 0.0, work = 0.0, before = 0.0;
      for (std::size_t j = begin; j < k; ++j) {
        const NodeContact& c = contacts[j];
        force += c.force;
        weighted += c.force * c.normalVelocity;
        work += c.force * std::max(0.0, -c.normalVelocity) * dt;
        // The node's normal velocity at the accepted state before (the approach), along today's normal.
        const int d = dofs.firstDof(c.node);
        const Vec3 vBefore =
            m_lastVelocity.size() > d + 2 ? Vec3(m_lastVelocity.segment<3>(d)) : Vec3::Zero();
        before += c.force * c.normal.dot(vBefore);
      }
      const double meanVelocity = weighted / force;
      // The open event of this line it continues, if any.
      SeabedImpact* event = nullptr;
      for (const int o : m_open) {
        SeabedImpact& e = m_events[static_cast<std::size_t>(o)];
        if (e.line == l && first <= e.lastNode + kReachNodes && last >= e.firstNode - kReachNodes) {
          event = &e;
          if (std::find(stillOpen.begin(), stillOpen.end(), o) == stillOpen.end()) stillOpen.push_back(o);
          break;
        }
      }
      if (!event) {
        SeabedImpact e;
        e.line = l;
        e.startTime = state.time;
        e.firstNode = first;
        e.lastNode = last;
        // Where it began: the node of the largest reaction.
        std::size_t strongest = begin;
        for (std::size_t j = begin; j < k; ++j)
          if (contacts[j].force > contacts[strongest].force) strongest = j;
        const int n = contacts[strongest].node;
        e.arcLength = line.arcLength[static_cast<std::size_t>(n - line.firstNode)];
        e.position = state.position[static_cast<std::size_t>(n)];
        e.startNormalVelocity = before / force;
        e.impactVelocity = std::max(0.0, -e.startNormalVelocity);
        e.impact = e.impactVelocity > m_threshold;
        e.phaseOpen = e.impactVelocity > 0.0;
        e.eq5Mass = std::numeric_limits<double>::quiet_NaN();
        // An impact's energy is not known until its phase measures the Eq. 5 mass (endPhase).
        if (e.impact) e.impactEnergy = std::numeric_limits<double>::quiet_NaN();
        stillOpen.push_back(static_cast<int>(m_events.size()));
        m_events.push_back(e);
        event = &m_events.back();
      }
      SeabedImpact& e = *event;
      e.firstNode = std::min(e.firstNode, first);
      e.lastNode = std::max(e.lastNode, last);
      e.endTime = state.time;
      e.peakForce = std::max(e.peakForce, force);
      // The reaction over the step, trapezoidal from the last state's (zero before first contact).
      const double impulse = 0.5 * (force + e.lastForce) * dt;
      e.lastForce = force;
      e.impulse += impulse;
      if (e.phaseOpen) {
        e.phaseImpulse += impulse;
        e.phaseWork += work;
        e.lastNormalVelocity = meanVelocity;
        // The nodes stopped approaching: the impact phase ends.
        if (meanVelocity >= 0.0) endPhase(e, state.time, meanVelocity);
      }
    }
  }
  // Events no patch continued have closed (a bounce, a lift-off).
  for (const int o : m_open)
    if (std::find(stillOpen.begin(), stillOpen.end(), o) == stillOpen.end()) {
      SeabedImpact& e = m_events[static_cast<std::size_t>(o)];
      if (e.phaseOpen) endPhase(e, e.endTime, e.lastNormalVelocity);
    }
  m_open = std::move(stillOpen);
  m_lastVelocity = state.velocity;
}

void SeabedImpacts::finish() {
  for (const int o : m_open) {
    SeabedImpact& e = m_events[static_cast<std::size_t>(o)];
    e.open = true;
    if (e.phaseOpen) endPhase(e, e.endTime, e.lastNormalVelocity);
  }
}

int SeabedImpacts::impactCount() const {
  return static_cast<int>(
      std::count_if(m_events.begin(), m_events.end(), [](const SeabedImpact& e) { return e.impact; }));
}

void SeabedImpacts::write(const std::filesystem::path& dir) const {
  if (m_events.empty()) return;
  core::OutputFile f(dir / "seabed_impacts.csv");
  f.write(
      "line,kind,start_time_s,end_time_s,arc_length_m,x_m,y_m,z_m,impact_velocity_m_s,impact_energy_J,"
      "eq5_mass_kg,impact_phase_end_s,impact_phase_work_J,peak_force_N,impulse_Ns,open_at_end\n");
  for (const SeabedImpact& e : m_events) {
    const std::string& name = m_model->lines()[static_cast<std::size_t>(e.line)].name;
    f.write(fmt::format(
        "\"{}\",{},{:.4f},{:.4f},{:.3f},{:.3f},{:.3f},{:.3f},{:.5f},{},{},{:.4f},{:.6g},{:.6g},{:.6g},{}\n",
        name, e.impact ? "impact" : "contact", e.startTime, e.endTime, e.arcLength, e.position.x(),
        e.position.y(), e.position.z(), e.impactVelocity,
        e.impact && !std::isnan(e.impactEnergy) ? fmt::format("{:.6g}", e.impactEnergy) : std::string(),
        std::isnan(e.eq5Mass) ? std::string() : fmt::format("{:.6g}", e.eq5Mass), e.phaseEndTime, e.phaseWork,
        e.peakForce, e.impulse, e.open ? "yes" : "no"));
  }
  f.close();
}

std::string SeabedImpacts::terminalSummary() const {
  const SeabedImpact* largest = nullptr;
  for (const SeabedImpact& e : m_events)
    if (e.impact && (!largest || e.impactEnergy > largest->impactEnergy || std::isnan(largest->impactEnergy)))
      largest = &e;  // of those measured (an impact whose approach was not stopped has no energy)
  if (!largest) return fmt::format("seabed impacts: none above {} m/s\n", m_threshold);
  if (std::isnan(largest->impactEnergy))
    return fmt::format(
        "seabed impacts: {} (dynamics/seabed_impacts.csv); no impact energy measured (no approach was "
        "stopped "
        "within its impact phase)\n",
        impactCount());
  return fmt::format(
      "seabed impacts: {} (dynamics/seabed_impacts.csv); largest {:.4g} J: line '{}' at {:.1f} m, "
      "t = {:.2f} s, {:.3f} m/s, Eq. 5 mass {:.4g} kg\n",
      impactCount(), largest->impactEnergy, m_model->lines()[static_cast<std::size_t>(largest->line)].name,
      largest->arcLength, largest->startTime, largest->impactVelocity, largest->eq5Mass);
}

}  // namespace tangle::analysis
