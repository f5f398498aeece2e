#include "tangle/time/SeabedPredictor.hpp"

#include <algorithm>
#include <cmath>

namespace tangle::time {

namespace {
/// Above this ratio of a beam node's bending stiffness to its seabed spring the node is left out.
constexpr double kSoftBeamRatio = 0.1;

/// The nodes the predictor may move: free in their three translations, and cable nodes or beam nodes whose
/// bending holds them far less than the seabed spring does. The correction balances a node's inertia against
/// its seabed reaction alone, so it is only right where nothing else of the node's stiffness is of that
/// order. A beam node's bending stiffness against a transverse move, its rotations held, is 12 EI / L^3 per
/// adjacent element (a clamped-clamped beam); summed over both elements and set against the seabed's k L:
///  - a steel riser (examples/scr-fatigue: EI 2.2e7 N m^2, 2.5 m elements) has 1.7e7 N/m per node against
///    2.5e5 N/m of seabed: left out (with its beam nodes corrected it took 10 % more residual evaluations);
///  - an 8 in flexible (examples/flexibles-at-touchdown: EI 3e4 N m^2, 10 m elements) has 720 N/m against
///    1e6 N/m: moved like a cable node (6.25 -> 5.50 residual evaluations per step over its first 30 s).
std::vector<char> movableNodes(const model::Model& model) {
  const model::DofMap& dofs = model.dofs();
  const auto count = static_cast<std::size_t>(dofs.nodeCount());
  std::vector<double> bending(count, 0.0);  // sum of 12 EI / L^3 of the beam elements at each node [N/m]
  for (const model::LineElement& element : model.elements()) {
    if (!element.isBeam()) continue;
    const double length = element.restLength;
    const double stiffness = 12.0 * element.type->bendingStiffness / (length * length * length);
    bending[static_cast<std::size_t>(element.node1)] += stiffness;
    bending[static_cast<std::size_t>(element.node2)] += stiffness;
  }
  const double seabed = model.environment().seabed.normalStiffness;  // [N/m/m]
  std::vector<char> movable(count, 0);
  for (int node = 0; node < dofs.nodeCount(); ++node) {
    const auto i = static_cast<std::size_t>(node);
    const int d = dofs.firstDof(node);
    if (dofs.equation(d) < 0 || dofs.equation(d + 1) < 0 || dofs.equation(d + 2) < 0) continue;
    movable[i] =
        !dofs.hasRotations(node) ||
        (model.lineOfNode(node) >= 0 && bending[i] <= kSoftBeamRatio * seabed * model.tributaryLength()[i]);
  }
  return movable;
}
}  // namespace

SeabedPredictor::SeabedPredictor(solver::Assembler& assembler)
    : m_assembler(&assembler),
      m_bed(assembler.model().environment().seabed, assembler.model().sharedSeabedSurface()),
      m_movable(movableNodes(assembler.model())) {}

void SeabedPredictor::updateMass(const model::State& start) {
  const model::Model& model = m_assembler->model();
  const model::DofMap& dofs = model.dofs();
  const int nfull = dofs.fullDofCount();
  m_direction.setZero(nfull);
  m_cachedNormal.assign(static_cast<std::size_t>(dofs.nodeCount()), Vec3::Zero());
  for (int node = 0; node < dofs.nodeCount(); ++node) {
    if (!m_movable[static_cast<std::size_t>(node)]) continue;
    const int d = dofs.firstDof(node);
    const Vec3 n = m_bed.normalAt(start.position[static_cast<std::size_t>(node)]);
    m_cachedNormal[static_cast<std::size_t>(node)] = n;
    m_direction.segment<3>(d) = n;
  }
  m_massAlong.setZero(nfull);
  m_assembler->addMass(start, 0.0, nullptr, &m_direction, &m_massAlong);
  const double k = model.environment().seabed.normalStiffness;
  m_largestOmegaSquared = 0.0;
  for (int node = 0; node < dofs.nodeCount(); ++node) {
    const auto i = static_cast<std::size_t>(node);
    const double mass = m_cachedNormal[i].dot(m_massAlong.segment<3>(dofs.firstDof(node)));
    if (mass > 0.0)
      m_largestOmegaSquared = std::max(m_largestOmegaSquared, k * model.tributaryLength()[i] / mass);
  }
  m_massAge = kMassAge;
}

bool SeabedPredictor::resolves(const model::State& start, double dt) {
  if (m_massAge <= 0 || m_massAlong.size() != m_assembler->model().dofs().fullDofCount()) updateMass(start);
  return m_largestOmegaSquared * dt * dt < 1.0;
}

int SeabedPredictor::correct(const model::State& start, const PredictorCoefficients& c, double dt,
                             const std::vector<double>& allowed, VecX& dq) {
  const model::Model& model = m_assembler->model();
  const model::DofMap& dofs = model.dofs();
  const auto& tributary = model.tributaryLength();
  const auto& diameter = model.nodeContactDiameter();
  const VecX& v0 = start.velocity;
  const VecX& a0 = start.acceleration;
  const double inverseBetaDt2 = 1.0 / (c.beta * dt * dt);

  // The nodes' mass along the normal, M n . n (structural and added mass; with a consistent mass the row's
  // neighbours count too, a fair estimate for a predictor), for every cable node free in its translations at
  // once, along the normal under it then. Kept for kMassAge steps (the added mass turns with the elements,
  // slowly on the seabed), and made again when a node's normal has changed (a node that moved on a sloping or
  // uneven seabed): a mass pass per step cost 2-3 % of the mooring example's time. With it the largest
  // k L / m of those nodes: a step that resolves every node's seabed oscillation skips the rest (the scan
  // of the nodes cost 2 % of a coupled host's run at dt 0.01 s, where nothing is corrected).
  const double stiffness = model.environment().seabed.normalStiffness;  // [N/m/m]
  if (m_massAge <= 0 || m_massAlong.size() != dofs.fullDofCount()) updateMass(start);
  --m_massAge;
  if (m_largestOmegaSquared * dt * dt < 1.0) return 0;

  // The nodes free in their three translations that touch the seabed at the start or where predicted.
  m_nodes.clear();
  m_normal.clear();
  for (int node = 0; node < dofs.nodeCount(); ++node) {
    if (!m_movable[static_cast<std::size_t>(node)]) continue;
    const int d = dofs.firstDof(node);
    const auto i = static_cast<std::size_t>(node);
    const double radius = 0.5 * diameter[i];
    const Vec3 predicted = start.position[i] + dq.segment<3>(d);
    const bool before = m_bed.penetration(start.position[i], radius) > 0.0;
    if (!before && m_bed.penetration(predicted, radius) <= 0.0) continue;
    m_nodes.push_back(node);
    m_normal.push_back(m_bed.normalAt(before ? start.position[i] : predicted));
  }
  if (m_nodes.empty()) return 0;

  bool stale = false;
  for (std::size_t j = 0; j < m_nodes.size() && !stale; ++j)
    stale = (m_cachedNormal[static_cast<std::size_t>(m_nodes[j])] - m_normal[j]).squaredNorm() > 1e-8;
  if (stale) updateMass(start);

  constexpr double kNegligible = 0.1;
  int corrected = 0;
  for (std::size_t k = 0; k < m_nodes.size(); ++k) {
    const int node = m_nodes[k];
    const auto i = static_cast<std::size_t>(node);
    const int d = dofs.firstDof(node);
    const Vec3& n = m_normal[k];
    const double mass = m_cachedNormal[static_cast<std::size_t>(node)].dot(m_massAlong.segment<3>(d));
    if (!(mass > 0.0)) continue;
    const double radius = 0.5 * diameter[i];
    const double length = tributary[i];
    // Only where the step does not resolve the node's oscillation on the seabed spring (omega dt >= 1 with
    // omega^2 = k L / m): below that the constant-acceleration predictor follows it to O((omega dt)^4) and
    // the correction did not pay (mooring example at dt 0.01 and 0.02 s: 0 % and +6 % CPU time).
    if (stiffness * length * dt * dt < mass) continue;
    const Vec3 x0 = start.position[i];
    const Vec3 xp = x0 + dq.segment<3>(d);
    // Predicted velocity (Newmark, from the predicted increment) and its change per unit of e.
    const Vec3 ap = (dq.segment<3>(d) - dt * v0.segment<3>(d) - dt * dt * (0.5 - c.beta) * a0.segment<3>(d)) *
                    inverseBetaDt2;
    const Vec3 vp = v0.segment<3>(d) + dt * ((1.0 - c.gamma) * a0.segment<3>(d) + c.gamma * ap);
    const double velocityPerE = c.gamma / (c.beta * dt);
    const double inertia = c.inertiaWeight * mass * inverseBetaDt2;  // [N/m]
    const double reaction0 =
        m_bed.normalLaw(m_bed.penetration(x0, radius), n.dot(v0.segment<3>(d)), length, true).force;
    // Along n the penetration falls by e (exactly on a plane) and the normal velocity rises by
    // gamma e / (beta dt). g(e) = inertia e - W (N(e) - N0), strictly increasing:
    // g' = inertia + W (kn + c gamma / (beta dt)).
    const double penetrationP = m_bed.penetration(xp, radius);
    const double normalVelocityP = n.dot(vp);
    const auto evaluate = [&](double e, double& slope) {
      const seabed::Seabed::NormalLaw law =
          m_bed.normalLaw(penetrationP - e, normalVelocityP + velocityPerE * e, length, true);
      slope = inertia + c.forceWeight * (law.stiffness + velocityPerE * law.damping);
      return inertia * e - c.forceWeight * (law.force - reaction0);
    };
    double slope = 0.0;
    const double g0 = evaluate(0.0, slope);
    // A reaction that changes by less than a tenth of what the node may be out of balance: nothing to gain
    // (most of a laid line's nodes, every step).
    if (std::abs(g0) <= kNegligible * allowed[i]) continue;
    ++corrected;
    // A bracket [low, high] of the root. g(0) < 0 (the reaction grew): the root lies between 0 and the lift
    // off, where N = 0 and g = inertia e + W N0 > 0. g(0) > 0 (the reaction fell, so N0 > 0): at
    // e = -W N0 / inertia, g = -W N(e) <= 0.
    double low = 0.0, high = 0.0;
    if (g0 < 0.0) {
      high = std::max(penetrationP, 1e-6);
      double s = 0.0;
      for (int grow = 0; grow < 60 && evaluate(high, s) < 0.0; ++grow) high *= 2.0;
    } else {
      low = -c.forceWeight * reaction0 / inertia;
    }
    // Newton's method safeguarded by bisection.
    double e = g0 < 0.0 ? std::min(-g0 / slope, high) : std::max(-g0 / slope, low);
    for (int iteration = 0; iteration < 60; ++iteration) {
      const double g = evaluate(e, slope);
      if (g == 0.0) break;
      (g < 0.0 ? low : high) = e;
      double next = e - g / slope;
      if (!(next > low && next < high)) next = 0.5 * (low + high);
      const bool done = std::abs(next - e) <= 1e-12 + 1e-9 * std::abs(e) || high - low <= 1e-12;
      e = next;
      if (done) break;
    }
    dq.segment<3>(d) += e * n;
  }
  return corrected;
}

}  // namespace tangle::time
