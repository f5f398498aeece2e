#include "tangle/solver/Assembler.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tangle/core/Error.hpp"
#include "tangle/core/ForEachIndex.hpp"
#include "tangle/core/PendingSum.hpp"
#include "tangle/seabed/Seabed.hpp"

namespace tangle::solver {

namespace {
/// Fraction of a segment between heights z1 and z2 [m] that lies below still water (z = 0).
double submergedFraction(double z1, double z2) {
  if (z1 <= 0.0 && z2 <= 0.0) return 1.0;
  if (z1 >= 0.0 && z2 >= 0.0) return 0.0;
  const double below = z1 < 0.0 ? -z1 : -z2;
  return below / std::abs(z2 - z1);
}
}  // namespace

Assembler::Assembler(const model::Model& model) : m_model(&model), m_visco(model) {
  const auto& env = model.environment();
  std::vector<double> submerged(model.lines().size(), 0.0), air(model.lines().size(), 0.0);
  for (const auto& el : model.elements()) {
    const double w = std::abs(el.type->submergedWeight(env.waterDensity, env.gravity)) * el.restLength;
    const double wAir = el.type->totalMassPerLength() * env.gravity * el.restLength;
    m_roundoffForce = std::max(m_roundoffForce, 1e-14 * el.type->axialStiffness);
    submerged[el.line] += w;
    air[el.line] += wAir;
    // Half of the element's weight in air and of its buoyancy when submerged, per node (constants of the
    // model: not looked up per element and assembly: docs/performance.md).
    m_halfWeight.push_back(0.5 * wAir);
    m_halfBuoyancy.push_back(0.5 * env.waterDensity * el.type->displacedAreaPerLength() * env.gravity *
                             el.restLength);
    constexpr double eps = std::numeric_limits<double>::epsilon();
    // Divided by the length (and its square) here, not per element at every step (docs/performance.md).
    m_roundoff.push_back(
        {16.0 * el.type->axialStiffness * eps / el.restLength,
         el.isBeam() ? 16.0 * el.type->bendingStiffness * eps / (el.restLength * el.restLength) : 0.0,
         el.restLength, 10.0 * 1e-14 * el.type->axialStiffness});
  }
  for (const model::NodeAttachment& a : model.attachments()) {
    const int line = model.lineOfNode(a.node);
    if (line < 0) continue;
    submerged[line] += std::abs(a.spec.mass - env.waterDensity * a.spec.volume) * env.gravity;
    air[line] += a.spec.mass * env.gravity;
  }
  for (std::size_t l = 0; l < submerged.size(); ++l)
    m_forceScale = std::max({m_forceScale, submerged[l], 0.1 * air[l]});
  const int n = model.nodeCount();
  m_nodeForceScale.assign(n, m_forceScale);
  for (int node = 0; node < n; ++node) {
    const int line = model.lineOfNode(node);
    if (line < 0) continue;
    const double scale = std::max(submerged[line], 0.1 * air[line]);
    if (scale > 0.0) m_nodeForceScale[node] = scale;
  }
  const model::DofMap& dofs = model.dofs();
  const bool lumped = model.spec().dynamics.lumpedMass;
  m_nodeDiagonalMass.assign(static_cast<std::size_t>(dofs.fullDofCount()), 0.0);
  for (int node = 0; node < n; ++node) {
    const int d = dofs.firstDof(node);
    for (int k = 0; k < 3 && lumped; ++k)
      m_nodeDiagonalMass[static_cast<std::size_t>(d + k)] = model.nodeMass()[node];
    if (dofs.hasRotations(node))
      for (int k = 3; k < 6; ++k)
        m_nodeDiagonalMass[static_cast<std::size_t>(d + k)] = model.nodeRotationalInertia()[node];
  }
  // The axial dampers' c / L0 per element [N s/m] (addElements).
  m_axialDampingRate.reserve(model.elements().size());
  for (const model::LineElement& el : model.elements())
    m_axialDampingRate.push_back(el.type->axialDamping / el.restLength);
  // Submerged weight lumped on each node held in all three translations [N] (addSeabed).
  // With it, the other node's lumped submerged line weight over its tributary length [N/m]: what the seabed
  // carries under that node when it rests (Seabed::carriedFraction).
  m_restingWeightPerLength.assign(static_cast<std::size_t>(n), 0.0);
  for (std::size_t e = 0; e < model.elements().size(); ++e) {
    const model::LineElement& el = model.elements()[e];
    for (const int node : {el.node1, el.node2})
      m_restingWeightPerLength[static_cast<std::size_t>(node)] += m_halfWeight[e] - m_halfBuoyancy[e];
  }
  for (std::size_t node = 0; node < m_restingWeightPerLength.size(); ++node) {
    const double trib = model.tributaryLength()[node];
    m_restingWeightPerLength[node] = trib > 0.0 ? m_restingWeightPerLength[node] / trib : 0.0;
  }
  m_heldNodeShares.assign(static_cast<std::size_t>(n), {});
  for (std::size_t e = 0; e < model.elements().size(); ++e) {
    const model::LineElement& el = model.elements()[e];
    for (const int node : {el.node1, el.node2}) {
      const int d = dofs.firstDof(node);
      const int other = node == el.node1 ? el.node2 : el.node1;
      if (dofs.equation(d) < 0 && dofs.equation(d + 1) < 0 && dofs.equation(d + 2) < 0)
        m_heldNodeShares[static_cast<std::size_t>(node)].push_back(
            {other, m_halfWeight[e] - m_halfBuoyancy[e]});
    }
  }
  m_anchor.assign(n, Vec2::Constant(std::numeric_limits<double>::quiet_NaN()));
  m_trialAnchor = m_anchor;
  // Unknown until the statics begin or a step is committed (NaN: a node touching down before either, as in a
  // dynamics started from the initial shape, anchors where it is).
  m_committedXY.assign(n, Vec2::Constant(std::numeric_limits<double>::quiet_NaN()));
}

const element::CorotationalBeam& Assembler::beamOf(std::size_t e, std::optional<element::CorotationalBeam>& copy) const {
  const model::LineElement& el = m_model->elements()[e];
  if (m_restLength.empty() || std::isnan(m_restLength[e])) return *el.beam;
  return copy.emplace(el.beam->properties(), m_restLength[e]);
}

double Assembler::roundoffFloor(const model::State& state) const {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  double floor = 0.0;
  for (const model::LineElement& el : m_model->elements()) {
    const double x = std::max(state.position[el.node1].cwiseAbs().maxCoeff(), state.position[el.node2].cwiseAbs().maxCoeff()) +
                     el.restLength;
    const double l = el.restLength;
    double f = el.type->axialStiffness * eps * x / l;
    // Moments are compared with forces over a 1 m lever (StaticSolver).
    if (el.isBeam()) f = std::max(f, el.type->bendingStiffness * eps * x / (l * l));
    floor = std::max(floor, f);
  }
  // A node sums a few such terms of either sign; 16 leaves room for the accumulation.
  return 16.0 * floor;
}

void Assembler::nodeRoundoffFloor(const model::State& state, std::vector<double>& floor) const {
  floor.assign(m_model->nodeCount(), 0.0);
  double largest = 0.0;
  const auto& elements = m_model->elements();
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const model::LineElement& el = elements[e];
    const RoundoffConstants& c = m_roundoff[e];
    const double l = c.length;
    const double x = std::max(state.position[el.node1].cwiseAbs().maxCoeff(),
                              state.position[el.node2].cwiseAbs().maxCoeff()) +
                     l;
    double f = c.axialPerLength * x;
    if (c.bendingPerLengthSquared > 0.0) f = std::max(f, c.bendingPerLengthSquared * x);
    f = std::max(f, c.resolution);  // the force resolution of roundoffForce, per element
    floor[el.node1] = std::max(floor[el.node1], f);
    floor[el.node2] = std::max(floor[el.node2], f);
    largest = std::max(largest, f);
  }
  for (int n = 0; n < m_model->nodeCount(); ++n)
    if (m_model->lineOfNode(n) < 0) floor[n] = largest;
  for (const LoadContributor* c : m_contributors) c->raiseRoundoffFloor(state, floor);
}

bool Assembler::roundoffFloorNegligible(const model::State& state, double tolerance) const {
  if (std::any_of(m_contributors.begin(), m_contributors.end(),
                  [](const LoadContributor* c) { return c->raisesRoundoffFloor(); }))
    return false;
  if (!(tolerance == m_negligibleFor)) {
    // An element's floor is max(a (x + l), b (x + l), resolution) with x its nodes' largest coordinate
    // (nodeRoundoffFloor): below a node's allowance tolerance * scale for every x up to
    // (tolerance * scale / max(a, b)) - l when the resolution is below it. A node on no line takes the
    // largest floor of all (bounded by the largest a, b, l and resolution).
    const int n = m_model->nodeCount();
    std::vector<double> slope(static_cast<std::size_t>(n), 0.0), length(static_cast<std::size_t>(n), 0.0),
        resolution(static_cast<std::size_t>(n), 0.0);
    double slopeAll = 0.0, lengthAll = 0.0, resolutionAll = 0.0;
    const auto& elements = m_model->elements();
    for (std::size_t e = 0; e < elements.size(); ++e) {
      const RoundoffConstants& c = m_roundoff[e];
      const double a = std::max(c.axialPerLength, c.bendingPerLengthSquared);
      for (const int node : {elements[e].node1, elements[e].node2}) {
        const auto k = static_cast<std::size_t>(node);
        slope[k] = std::max(slope[k], a);
        length[k] = std::max(length[k], c.length);
        resolution[k] = std::max(resolution[k], c.resolution);
      }
      slopeAll = std::max(slopeAll, a);
      lengthAll = std::max(lengthAll, c.length);
      resolutionAll = std::max(resolutionAll, c.resolution);
    }
    double reach = std::numeric_limits<double>::infinity();
    for (int node = 0; node < n; ++node) {
      const auto k = static_cast<std::size_t>(node);
      const bool onLine = m_model->lineOfNode(node) >= 0;
      // Half the allowance: the factor 2 covers the rounding of this bound.
      const double allowance = 0.5 * tolerance * m_nodeForceScale[k];
      const double a = onLine ? slope[k] : slopeAll, l = onLine ? length[k] : lengthAll;
      const double r = onLine ? resolution[k] : resolutionAll;
      if (!(r < allowance)) {
        reach = -std::numeric_limits<double>::infinity();
        break;
      }
      if (a > 0.0) reach = std::min(reach, allowance / a - l);
    }
    m_negligibleFor = tolerance;
    m_negligibleReach = reach;
  }
  double largest = 0.0;
  for (int node = 0; node < m_model->nodeCount(); ++node)
    largest = std::max(largest, state.position[node].cwiseAbs().maxCoeff());
  return largest < m_negligibleReach;
}

void Assembler::beginStatics(const model::State& state) {
  const seabed::SeabedSurface& bed = m_model->seabedSurface();
  const auto& diameter = m_model->nodeContactDiameter();
  for (int n = 0; n < m_model->nodeCount(); ++n) {
    const Vec3& x = state.position[n];
    m_committedXY[n] = bed.footprint(x);
    const bool touching = bed.gap(x, 0.5 * diameter[n]) < 0.0;
    m_anchor[n] = touching ? m_committedXY[n] : Vec2::Constant(std::numeric_limits<double>::quiet_NaN());
  }
  m_trialAnchor = m_anchor;
  for (LoadContributor* c : m_contributors) c->beginStatic(state);
}

int Assembler::lineSlidingAsAWhole(const model::State& state) const {
  const auto& env = m_model->environment();
  if (env.seabed.frictionCoefficient <= 0.0) return -1;
  const seabed::Seabed bed(env.seabed, m_model->sharedSeabedSurface());
  const auto& trib = m_model->tributaryLength();
  const auto& diameter = m_model->nodeContactDiameter();
  const model::DofMap& dofs = m_model->dofs();
  const auto& lines = m_model->lines();
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const model::Line& line = lines[l];
    if (line.spec->endA.kind != model::EndKind::Free || line.spec->endB.kind != model::EndKind::Free)
      continue;
    // The resultant of the friction on the line against the sum of its nodes' caps mu N: the line is free,
    // so the resultant balances every other load on it; at the sum of the caps the friction of every node
    // is at its cap and points the same way, and no larger load in that direction can be held.
    Vec3 resultant = Vec3::Zero();
    double capacity = 0.0;
    bool laid = line.nodeCount > 0;
    for (int n = line.firstNode; laid && n <= line.lastNode(); ++n) {
      const int d = dofs.firstDof(n);
      const Vec3& x = state.position[n];
      laid = dofs.equation(d) >= 0 && dofs.equation(d + 1) >= 0 && dofs.equation(d + 2) >= 0 &&
             bed.penetration(x, 0.5 * diameter[n]) > 0.0;
      if (!laid) break;
      const seabed::SeabedNodeReaction r = bed.reaction(x, Vec3::Zero(), trib[n], 0.5 * diameter[n], false);
      const Vec2 anchor = frictionAnchor(n, x);
      resultant += bed.staticFriction(x, anchor, r.normalForce, r.normalStiffness, trib[n], Vec3::Zero(), 0.0,
                                      r.normal)
                       .force;
      capacity += env.seabed.frictionCoefficient * r.normalForce;
    }
    // 99 %: the continuation's converged increments approach the capacity from below and stop short of it.
    if (laid && capacity > 0.0 && resultant.norm() >= 0.99 * capacity) return static_cast<int>(l);
  }
  return -1;
}

void Assembler::commitStep(model::State& state, double dt) {
  // The anchors of the elastic seabed friction at the accepted state become the committed ones; a
  // rejected step never gets here, so its trial anchors are dropped. They are evaluated here, at that
  // state, for every node: the last assembly of the step may have been at an earlier iterate, or of a
  // part only (Newton on parts leaves the converged blocks out), whose anchors would be stale. The static
  // solution's were committed with its last increment.
  const auto& seabed = m_model->environment().seabed;
  if (dt > 0.0 && seabed.frictionCoefficient > 0.0 && seabed.elasticFriction) {
    AssemblyRequest request;
    request.time = state.time;
    request.dynamic = true;
    request.wantMatrix = false;
    thread_local VecX scratch;
    scratch.setZero(m_model->dofs().fullDofCount());
    addSeabed(state, request, scratch, nullptr, nullptr);
    commitAnchors(state);
  }
  m_visco.commit(state);
  for (LoadContributor* c : m_contributors) c->commitStep(state, dt);
}

std::string Assembler::rejectState(const model::State& state) {
  for (LoadContributor* c : m_contributors) {
    std::string why = c->rejectState(state);
    if (!why.empty()) return why;
  }
  return {};
}

double Assembler::limitStep(const model::State& state, double step) {
  double limit = std::numeric_limits<double>::infinity();
  for (LoadContributor* c : m_contributors) limit = std::min(limit, c->limitStep(state, step));
  return limit;
}

double Assembler::maxStepGrowth() const {
  double growth = 2.0;
  for (const LoadContributor* c : m_contributors) growth = std::min(growth, c->maxStepGrowth());
  return growth;
}

std::string Assembler::rejectStep(const model::State& before, const model::State& after) {
  for (LoadContributor* c : m_contributors) {
    std::string why = c->rejectStep(before, after);
    if (!why.empty()) return why;
  }
  return {};
}

void Assembler::finish(double time) {
  for (LoadContributor* c : m_contributors) c->finish(time);
}

void Assembler::commitAnchors(const model::State& state) {
  const seabed::SeabedSurface& bed = m_model->seabedSurface();
  for (int n = 0; n < m_model->nodeCount(); ++n) m_committedXY[n] = bed.footprint(state.position[n]);
  m_anchor = m_trialAnchor;
}

void Assembler::commitIncrement(const model::State& state) {
  commitAnchors(state);
  for (LoadContributor* c : m_contributors) c->commitIncrement(state);
}

void Assembler::assemble(const model::State& state, const AssemblyRequest& request, VecX& force,
                         SystemMatrix* matrix) {
  force.setZero(m_model->dofs().fullDofCount());
  // The matrix is cleared only when it is assembled (an assembly for the out-of-balance alone leaves the
  // last one as it is: zeroing its values at every iteration is not free: docs/performance.md).
  SystemMatrix* const assembled = request.wantMatrix ? matrix : nullptr;
  if (assembled) assembled->clear();
  addAll(state, request, force, assembled, nullptr);
  m_loadedMarkValid = false;  // the contributors' loaded nodes may have changed (contact candidates)
}

void Assembler::addAll(const model::State& state, const AssemblyRequest& request, VecX& force,
                       SystemMatrix* matrix, const AssemblyPart* part) {
  // One sequence for the whole model and for a part: each entry of a part's nodes then sums the same
  // terms in the same order as in a whole assembly (assemblePart's contract: bit for bit).
  addElements(state, request, force, matrix, part ? &part->elements : nullptr);
  addWeight(state, request, force, part ? &part->elements : nullptr, part ? &part->attachments : nullptr,
            matrix);
  addSeabed(state, request, force, matrix, part ? &part->nodes : nullptr);
  const bool coupled = part && holdsCoupled(*part);
  for (LoadContributor* c : m_contributors) {
    if (!part)
      c->addForces(state, request, force, matrix);
    else if (!c->coupledInParts())
      c->addPartForces(state, request, *part, force, matrix);
    else if (coupled)
      c->addForces(state, request, force, matrix);  // its terms outside the part are discarded
  }
}

void Assembler::addTerm(Term term, const model::State& state, const AssemblyRequest& request, VecX& force) {
  static const std::vector<int> none;
  switch (term) {
    case Term::Elements: addElements(state, request, force, nullptr); break;
    case Term::Weight: addWeight(state, request, force, nullptr, &none); break;
    case Term::Attachments: addWeight(state, request, force, &none, nullptr); break;
    case Term::Seabed: addSeabed(state, request, force, nullptr); break;
  }
}

namespace {
/// Places one element's force `f` and tangent `k` (N DOFs, at the global DOFs `map`) into F and H, with the
/// stiffness-proportional Rayleigh damping beta K v added to the force and (kf + cf beta) K to H: the element
/// kernel gives f and K once, the assembler gathers, damps and scatters them the same way for every element
/// type (Chrono's one call for K, C, M of an element).
template <int N>
void scatterElement(const int (&map)[N], Eigen::Matrix<double, N, 1>& f, const Eigen::Matrix<double, N, N>& k,
                    const model::State& state, double beta, const AssemblyRequest& request, VecX& force,
                    SystemMatrix* matrix) {
  if (beta > 0.0) {
    Eigen::Matrix<double, N, 1> v;
    for (int i = 0; i < N; ++i) v[i] = state.velocity[map[i]];
    f += beta * k * v;
  }
  for (int i = 0; i < N; ++i) force[map[i]] += f[i];
  if (matrix) matrix->addBlock(map, N, k, request.kf + request.cf * beta);
}
}  // namespace

void Assembler::addElements(const model::State& state, const AssemblyRequest& request, VecX& force,
                            SystemMatrix* matrix, const std::vector<int>* elements) {
  const model::DofMap& dofs = m_model->dofs();
  const double beta = request.dynamic ? m_model->spec().dynamics.rayleighBeta : 0.0;
  const model::PartedElements& parted = m_model->parted();
  forEachIndex(elements, m_model->elements().size(), [&](std::size_t e) {
    if (parted.parted(e, state.time)) return;  // a parted element carries nothing (lines[].failure)
    const model::LineElement& el = m_model->elements()[e];
    const int d1 = dofs.firstDof(el.node1);
    const int d2 = dofs.firstDof(el.node2);
    std::optional<element::Bar> barCopy;
    const int visco = request.dynamic ? m_visco.index(e) : -1;
    if (visco >= 0 && m_visco.active(state)) {
      addViscoelasticBar(state, el, visco, d1, d2, beta, request, force, matrix);
    } else if (el.bar && !matrix && beta == 0.0) {
      // The force alone (Bar::forceOnNode2: the same arithmetic as compute's, inline), and an axial damper's
      // on the bar's own direction (bit for bit the chord.normalized() the other paths give addAxialDamping,
      // without a second square root and division per element).
      const element::Bar::ForceAndDirection bar =
          barOf(e, barCopy)
              .forceAndDirectionOnNode2(state.position[el.node1], state.position[el.node2],
                                        compressionFactor(el));
      force.segment<3>(d1) -= bar.force;
      force.segment<3>(d2) += bar.force;
      if (request.dynamic && el.type->axialDamping > 0.0)
        addAxialDamping(state, e, bar.direction, d1, d2, request, force, nullptr);
      return;
    } else if (el.bar) {
      Vec6 f;
      Mat6 k;
      const element::Bar& bar = barOf(e, barCopy);
      // A cable carries no compression (chain and wire rope buckle at once; MoorDyn's segments likewise):
      // a slack bar keeps LineType::compressionFactor (1e-6) of its EA, enough to keep the tangent
      // regular, so a compressed straight line is not an equilibrium and statics finds the shape that
      // hangs (or floats) in tension. Statics may raise the factor for a while (m_slackFactor).
      bar.compute(state.position[el.node1], state.position[el.node2], f, matrix || beta > 0.0 ? &k : nullptr,
                  compressionFactor(el));
      const int map[6] = {d1, d1 + 1, d1 + 2, d2, d2 + 1, d2 + 2};
      scatterElement(map, f, k, state, beta, request, force, matrix);
    } else {
      Vec12 f;
      Mat12 k;
      std::optional<element::CorotationalBeam> beamCopy;
      const element::CorotationalBeam& beam = beamOf(e, beamCopy);
      beam.compute(state.position[el.node1], state.triad[el.node1], state.position[el.node2], state.triad[el.node2], f,
                   matrix || beta > 0.0 ? &k : nullptr);
      const int map[12] = {d1, d1 + 1, d1 + 2, d1 + 3, d1 + 4, d1 + 5, d2, d2 + 1, d2 + 2, d2 + 3, d2 + 4, d2 + 5};
      scatterElement(map, f, k, state, beta, request, force, matrix);
    }
    if (request.dynamic && el.type->axialDamping > 0.0)
      addAxialDamping(state, e, (state.position[el.node2] - state.position[el.node1]).normalized(), d1, d2,
                      request, force, matrix);
  });
}

void Assembler::addViscoelasticBar(const model::State& state, const model::LineElement& el, int k, int d1,
                                   int d2, double beta, const AssemblyRequest& request, VecX& force,
                                   SystemMatrix* matrix) const {
  const Vec3 chord = state.position[el.node2] - state.position[el.node1];
  const double l = chord.norm();
  if (!(l > 0.0)) throw Error("Bar: the two nodes coincide (zero current length)");
  const Vec3 e = chord / l;
  const double l0 = el.restLength;
  const double rate = e.dot(state.velocity.segment<3>(d2) - state.velocity.segment<3>(d1)) / l0;
  const ViscoelasticElements::Axial a = m_visco.axial(k, state, (l - l0) / l0, rate, compressionFactor(el));
  Vec6 f;
  f.head<3>() = -a.force * e;
  f.tail<3>() = a.force * e;
  Mat6 kt;
  const Mat3 ee = e * e.transpose();
  const Mat3 k3 = (a.stiffness / l0) * ee + (a.force / l) * (Mat3::Identity() - ee);
  kt << k3, -k3, -k3, k3;
  const int map[6] = {d1, d1 + 1, d1 + 2, d2, d2 + 1, d2 + 2};
  scatterElement(map, f, kt, state, beta, request, force, matrix);
  if (matrix && request.cf != 0.0 && a.damping != 0.0) {
    const Mat3 c = (a.damping / l0) * ee;
    matrix->add3x3(d1, d1, c, request.cf);
    matrix->add3x3(d2, d2, c, request.cf);
    matrix->add3x3(d1, d2, c, -request.cf);
    matrix->add3x3(d2, d1, c, -request.cf);
  }
}

void Assembler::addAxialDamping(const model::State& state, std::size_t element, const Vec3& e, int d1, int d2,
                                const AssemblyRequest& request, VecX& force, SystemMatrix* matrix) const {
  // Structural axial damping: N_d = c * strain rate = c e.(v2 - v1) / L0 (c = LineType::axialDamping [N s]),
  // acting along the chord e (as OrcaFlex's axial damping and MoorDyn's internal damping).
  const double c = m_axialDampingRate[element];
  const double nd = c * e.dot(state.velocity.segment<3>(d2) - state.velocity.segment<3>(d1));
  force.segment<3>(d1) -= nd * e;
  force.segment<3>(d2) += nd * e;
  if (matrix && request.cf != 0.0) {
    const Mat3 ee = c * e * e.transpose();
    matrix->add3x3(d1, d1, ee, request.cf);
    matrix->add3x3(d2, d2, ee, request.cf);
    matrix->add3x3(d1, d2, ee, -request.cf);
    matrix->add3x3(d2, d1, ee, -request.cf);
  }
}

void Assembler::addWeight(const model::State& state, const AssemblyRequest& request, VecX& force,
                          const std::vector<int>* elements, const std::vector<int>* attachments,
                          SystemMatrix* matrix) {
  const model::DofMap& dofs = m_model->dofs();
  const auto& env = m_model->environment();
  const double g = env.gravity;
  const double rho = env.waterDensity;
  // The vertical entries added with the last one held in a register (PendingSum: the chain through memory
  // from one element's second node to the next one's first was most of this loop).
  PendingSum<1> vertical(force.data());
  forEachIndex(elements, m_model->elements().size(), [&](std::size_t e) {
    const model::LineElement& el = m_model->elements()[e];
    const double frac = submergedFraction(state.position[el.node1].z(), state.position[el.node2].z());
    // Out-of-balance force: F = f_int - f_ext, and the external load is -weight/2 * z at each node.
    const double half = (m_halfWeight[e] - m_halfBuoyancy[e] * frac) * request.loadFactor;
    const int z1 = dofs.firstDof(el.node1) + 2, z2 = dofs.firstDof(el.node2) + 2;
    vertical.add(z1, half);
    vertical.add(z2, half);
    if (matrix && frac > 0.0 && frac < 1.0) {
      // An element through the surface: its buoyancy changes with the heights of its nodes, the waterplane
      // stiffness of a float (without it in H the vertical position of a surface-piercing buoy is held by
      // nothing but its lines in the Newton iteration). frac = |z_below| / |z2 - z1|, whichever node is
      // below: d frac / d z1 = -|z2| / (z2 - z1)^2 and d frac / d z2 = -|z1| / (z2 - z1)^2.
      const double za = state.position[el.node1].z(), zb = state.position[el.node2].z();
      const double span2 = (zb - za) * (zb - za);
      const double k = m_halfBuoyancy[e] * request.loadFactor * request.kf;
      const double d1 = -std::abs(zb) / span2, d2 = -std::abs(za) / span2;  // d frac / d z1, d frac / d z2
      matrix->add(z1, z1, -k * d1);
      matrix->add(z1, z2, -k * d2);
      matrix->add(z2, z1, -k * d1);
      matrix->add(z2, z2, -k * d2);
    }
  });
  vertical.flush();
  forEachIndex(attachments, m_model->attachments().size(), [&](std::size_t i) {
    const model::NodeAttachment& a = m_model->attachments()[i];
    const double submerged = state.position[a.node].z() < 0.0 ? 1.0 : 0.0;
    const double weight = (a.spec.mass - rho * a.spec.volume * submerged) * g;
    force[dofs.firstDof(a.node) + 2] += weight * request.loadFactor;
  });
}

void Assembler::addSeabed(const model::State& state, const AssemblyRequest& request, VecX& force,
                          SystemMatrix* matrix, const std::vector<int>* nodes) {
  const model::DofMap& dofs = m_model->dofs();
  const auto& env = m_model->environment();
  seabed::SeabedSpec seabedSpec = env.seabed;
  if (request.dynamic && request.relaxation) seabedSpec.elasticFriction = false;
  const seabed::Seabed bed(seabedSpec, m_model->sharedSeabedSurface());
  const auto& trib = m_model->tributaryLength();
  const auto& diameter = m_model->nodeContactDiameter();
  // The elastic friction (a spring to the node's anchor capped at mu N) in statics, and in dynamics too
  // unless the seabed's friction is viscous (Seabed).
  const bool staticFriction =
      seabedSpec.frictionCoefficient > 0.0 && (!request.dynamic || seabedSpec.elasticFriction);
  forEachIndex(nodes, static_cast<std::size_t>(m_model->nodeCount()), [&](std::size_t node) {
    const int n = static_cast<int>(node);
    const int d = dofs.firstDof(n);
    // A node held in all three translations (an anchor) takes its support from the constraint: a seabed
    // spring there would only add a phantom vertical load to the anchor reaction. Resting on the seabed, the
    // seabed carries its own weight (the line's, lumped on it) where the line lies on the seabed, as it
    // carries the laid nodes next to it: each element's share whose other node rests on the seabed too. The
    // anchor then takes only the line's pull (theory 7.8). A line rising from the anchor hangs from it: that
    // element's share stays on the anchor (a tether's anchor read half an element of weight too little).
    // Between, the share the seabed carries is the fraction of the other node's weight the seabed carries
    // (Seabed::carriedFraction): a node that only just touches holds nothing up, and the anchor's reaction
    // changed by the whole share when it lifted off or landed (a step in a dynamic anchor tension history).
    // Only the reaction changes: the node is held.
    if (dofs.equation(d) < 0 && dofs.equation(d + 1) < 0 && dofs.equation(d + 2) < 0) {
      const std::vector<HeldShare>& shares = m_heldNodeShares[node];
      if (!shares.empty() && request.loadFactor > 0.0 &&
          bed.penetration(state.position[n], 0.5 * diameter[n]) > 0.0)
        for (const HeldShare& share : shares) {
          if (share.weight <= 0.0) continue;
          const auto other = static_cast<std::size_t>(share.other);
          force[d + 2] -= share.weight * request.loadFactor *
                          bed.carriedFraction(state.position[other], 0.5 * diameter[other],
                                              m_restingWeightPerLength[other] * request.loadFactor);
        }
      return;
    }
    // Clear of the seabed (most nodes): no reaction to evaluate (its result, force and two 3x3 blocks,
    // cost to initialise: docs/performance.md).
    if (bed.penetration(state.position[n], 0.5 * diameter[n]) <= 0.0) {
      if (staticFriction) m_trialAnchor[n] = Vec2::Constant(std::numeric_limits<double>::quiet_NaN());
      // A zero block keeps the matrix entries in the same order whether or not the node touches, so
      // SystemMatrix::build reuses its scatter map as the touchdown point moves (the node's diagonal
      // block exists anyway: no new non-zeros).
      if (matrix) {
        matrix->add3x3(d, d, Mat3::Zero());
        if (request.cf != 0.0) matrix->add3x3(d, d, Mat3::Zero());
      }
      return;
    }
    const Vec3 v = state.velocity.segment<3>(d);
    if (!matrix && !staticFriction) {
      force.segment<3>(d) -= bed.reactionForce(state.position[n], v, trib[n], 0.5 * diameter[n], request.dynamic);
      return;
    }
    seabed::SeabedNodeReaction r = bed.reaction(state.position[n], v, trib[n], 0.5 * diameter[n], request.dynamic);
    if (staticFriction) {
      const Vec2 anchor = frictionAnchor(n, state.position[n]);
      // Dynamics: a dashpot beside the stick spring, critical for the node's own mass on it (theory 7.5):
      // undamped, the held laid chain rang on its stick springs (0.26 s period for a chain) and every
      // stick-slip switch fed it.
      const double dashpot =
          request.dynamic ? 2.0 * std::sqrt(bed.shearStiffness() * trib[n] * m_model->nodeMass()[n]) : 0.0;
      const seabed::StaticFrictionResult f = bed.staticFriction(
          state.position[n], anchor, r.normalForce, r.normalStiffness, trib[n], v, dashpot, r.normal);
      m_trialAnchor[n] = f.anchor;
      r.force += f.force;
      r.stiffness += f.stiffness;
      r.damping += f.damping;
    }
    force.segment<3>(d) -= r.force;
    if (matrix) {
      matrix->add3x3(d, d, r.stiffness, request.kf);
      if (request.cf != 0.0) matrix->add3x3(d, d, r.damping, request.cf);
    }
  });
}

void Assembler::addMass(const model::State& state, double mf, SystemMatrix* matrix, const VecX* acceleration,
                        VecX* out) {
  addAllMass(state, mf, matrix, acceleration, out, nullptr);
}

void Assembler::addAllMass(const model::State& state, double mf, SystemMatrix* matrix, const VecX* acceleration,
                           VecX* out, const AssemblyPart* part) {
  // As addAll: one sequence for the whole model and for a part.
  addOwnMass(mf, matrix, acceleration, out, part ? &part->elements : nullptr, part ? &part->nodes : nullptr,
             part ? &part->attachments : nullptr);
  const bool coupled = part && holdsCoupled(*part);
  for (LoadContributor* c : m_contributors) {
    if (!part)
      c->addMass(state, mf, matrix, acceleration, out);
    else if (!c->coupledInParts())
      c->addPartMass(state, *part, mf, matrix, acceleration, out);
    else if (coupled)
      c->addMass(state, mf, matrix, acceleration, out);
  }
}

void Assembler::addOwnMass(double mf, SystemMatrix* matrix, const VecX* acceleration, VecX* out,
                           const std::vector<int>* elements, const std::vector<int>* nodes,
                           const std::vector<int>* attachments) const {
  const model::DofMap& dofs = m_model->dofs();
  const auto& attached = m_model->attachments();
  const bool consistent = !m_model->spec().dynamics.lumpedMass;
  if (consistent) {
    // Consistent translational mass of each element (linear shape functions: m L / 6 [2 1; 1 2],
    // e.g. Cook et al. 2002, "Concepts and applications of FE analysis", sec. 11.3); attachments stay
    // point masses; rotational inertia stays lumped.
    forEachIndex(elements, m_model->elements().size(), [&](std::size_t e) {
      const model::LineElement& el = m_model->elements()[e];
      const double m = el.type->totalMassPerLength() * el.restLength;
      const int d1 = dofs.firstDof(el.node1), d2 = dofs.firstDof(el.node2);
      for (int k = 0; k < 3; ++k) {
        if (matrix) {
          matrix->add(d1 + k, d1 + k, mf * m / 3.0);
          matrix->add(d2 + k, d2 + k, mf * m / 3.0);
          matrix->add(d1 + k, d2 + k, mf * m / 6.0);
          matrix->add(d2 + k, d1 + k, mf * m / 6.0);
        }
        if (out) {
          (*out)[d1 + k] += m / 3.0 * (*acceleration)[d1 + k] + m / 6.0 * (*acceleration)[d2 + k];
          (*out)[d2 + k] += m / 6.0 * (*acceleration)[d1 + k] + m / 3.0 * (*acceleration)[d2 + k];
        }
      }
    });
    forEachIndex(attachments, attached.size(), [&](std::size_t i) {
      const model::NodeAttachment& a = attached[i];
      const int d = dofs.firstDof(a.node);
      for (int k = 0; k < 3; ++k) {
        if (matrix) matrix->add(d + k, d + k, mf * a.spec.mass);
        if (out) (*out)[d + k] += a.spec.mass * (*acceleration)[d + k];
      }
    });
  }
  // The nodes' own diagonal masses (m_nodeDiagonalMass: lumped translational mass, rotational inertia). Their
  // inertia force by DOF: for the whole model one pass over every DOF without branches (every residual of a
  // step; the loop over nodes with its per-node branches cost more: docs/performance.md), a zero
  // mass adding +0; for a part, its nodes' DOFs.
  const double* diagonal = m_nodeDiagonalMass.data();
  if (out) {
    double* f = out->data();
    const double* a = acceleration->data();
    if (!nodes) {
      for (Eigen::Index dof = 0; dof < out->size(); ++dof) f[dof] += diagonal[dof] * a[dof];
    } else {
      for (const int n : *nodes)
        for (int dof = dofs.firstDof(n); dof < dofs.firstDof(n) + dofs.dofCount(n); ++dof)
          f[dof] += diagonal[dof] * a[dof];
    }
  }
  if (matrix) {
    forEachIndex(nodes, static_cast<std::size_t>(m_model->nodeCount()), [&](std::size_t node) {
      const int n = static_cast<int>(node);
      const int d = dofs.firstDof(n);
      for (int k = 0; k < 3 && !consistent; ++k) matrix->add(d + k, d + k, mf * diagonal[d + k]);
      if (dofs.hasRotations(n))
        for (int k = 3; k < 6; ++k) matrix->add(d + k, d + k, mf * diagonal[d + k]);
    });
  }
  forEachIndex(attachments, attached.size(), [&](std::size_t i) {
    const model::NodeAttachment& a = attached[i];
    const int d = dofs.firstDof(a.node);
    for (int k = 0; k < 3; ++k) {
      if (matrix) matrix->add(d + k, d + k, mf * a.spec.addedMass);
      if (out) (*out)[d + k] += a.spec.addedMass * (*acceleration)[d + k];
    }
  });
}

bool Assembler::supportsParts() const {
  return std::all_of(m_contributors.begin(), m_contributors.end(),
                     [](const LoadContributor* c) { return c->supportsParts(); });
}

bool Assembler::selectPart(const std::vector<int>& moved, AssemblyPart& part, bool coupled) {
  const auto& elements = m_model->elements();
  const auto& attached = m_model->attachments();
  const auto nodeCount = static_cast<std::size_t>(m_model->nodeCount());
  if (m_nodeElements.size() != nodeCount) {
    m_nodeElements.assign(nodeCount, {});
    for (std::size_t e = 0; e < elements.size(); ++e) {
      m_nodeElements[static_cast<std::size_t>(elements[e].node1)].push_back(static_cast<int>(e));
      m_nodeElements[static_cast<std::size_t>(elements[e].node2)].push_back(static_cast<int>(e));
    }
  }
  // Marks, then scans in index order (ascending lists without sorting): nodes 1 = of the part, 2 = written
  // only; elements and attachments 1 = of the part. Each scan covers only the index range its marks were
  // set in (a part is about half a line: docs/performance.md).
  m_nodeMark.assign(nodeCount, 0);
  m_elementMark.assign(elements.size(), 0);
  std::size_t nodeLo = nodeCount, nodeHi = 0;  // marked nodes lie in [nodeLo, nodeHi)
  const auto markNode = [&](int node, char mark) {
    const auto n = static_cast<std::size_t>(node);
    m_nodeMark[n] = mark;
    nodeLo = std::min(nodeLo, n);
    nodeHi = std::max(nodeHi, n + 1);
  };
  for (const int n : moved)
    for (const int e : m_nodeElements[static_cast<std::size_t>(n)]) {
      markNode(elements[static_cast<std::size_t>(e)].node1, 1);
      markNode(elements[static_cast<std::size_t>(e)].node2, 1);
    }
  for (const int n : moved) markNode(n, 1);
  part.coupledAllowed = coupled;
  if (coupled) loadedNodes();
  if (coupled && m_coupledCount > 0) {
    // A coupled contributor's nodes (line contact: both lines near a crossing) all in, or none: when the
    // part reaches one, the others join it, since their forces change with it (the other line's side of the
    // contact), and with them their elements (below).
    bool reached = false;
    for (std::size_t n = nodeLo; n < nodeHi && !reached; ++n)
      reached = m_nodeMark[n] == 1 && m_coupledMark[n];
    if (reached)
      for (std::size_t n = 0; n < nodeCount; ++n)
        if (m_coupledMark[n]) markNode(static_cast<int>(n), 1);
  }
  part.nodes.clear();
  std::size_t elementLo = elements.size(), elementHi = 0;  // marked elements lie in [elementLo, elementHi)
  for (std::size_t n = nodeLo; n < nodeHi; ++n) {
    if (m_nodeMark[n] != 1) continue;
    part.nodes.push_back(static_cast<int>(n));
    for (const int e : m_nodeElements[n]) {
      const auto ue = static_cast<std::size_t>(e);
      m_elementMark[ue] = 1;
      elementLo = std::min(elementLo, ue);
      elementHi = std::max(elementHi, ue + 1);
    }
  }
  part.elements.clear();
  for (std::size_t e = elementLo; e < elementHi; ++e) {
    if (!m_elementMark[e]) continue;
    part.elements.push_back(static_cast<int>(e));
    for (const int n : {elements[e].node1, elements[e].node2})
      if (m_nodeMark[static_cast<std::size_t>(n)] == 0) markNode(n, 2);
  }
  part.attachments.clear();
  for (std::size_t a = 0; a < attached.size(); ++a)
    if (m_nodeMark[static_cast<std::size_t>(attached[a].node)] == 1)
      part.attachments.push_back(static_cast<int>(a));
  part.writtenNodes.clear();
  for (std::size_t n = nodeLo; n < nodeHi; ++n)
    if (m_nodeMark[n] != 0) part.writtenNodes.push_back(static_cast<int>(n));
  return partUsable(part);
}

const std::vector<char>& Assembler::loadedNodes() {
  // The marks change only with a whole assembly (line contact's candidates), so they are gathered once
  // after each.
  if (!m_loadedMarkValid) {
    m_anyLoadedMark = false;
    const auto nodeCount = static_cast<std::size_t>(m_model->nodeCount());
    m_strictMark.assign(nodeCount, 0);
    m_coupledMark.assign(nodeCount, 0);
    for (const LoadContributor* c : m_contributors)
      m_anyLoadedMark =
          c->markLoadedNodes(c->coupledInParts() ? m_coupledMark : m_strictMark) || m_anyLoadedMark;
    m_loadedMark.resize(nodeCount);
    m_coupledCount = 0;
    for (std::size_t n = 0; n < nodeCount; ++n) {
      m_loadedMark[n] = m_strictMark[n] || m_coupledMark[n] ? 1 : 0;
      m_coupledCount += m_coupledMark[n] ? 1 : 0;
    }
    m_loadedMarkValid = true;
  }
  return m_loadedMark;
}

bool Assembler::partUsable(const AssemblyPart& part) {
  // Contributors left out of parts: none of their nodes may be in the part; those coupled in parts (made
  // with `coupled`): all of them or none.
  loadedNodes();
  if (!m_anyLoadedMark) return true;
  int coupled = 0;
  for (const int n : part.nodes) {
    const auto u = static_cast<std::size_t>(n);
    if (m_strictMark[u] || (m_coupledMark[u] && !part.coupledAllowed)) return false;
    coupled += m_coupledMark[u] ? 1 : 0;
  }
  return coupled == 0 || coupled == m_coupledCount;
}

bool Assembler::holdsCoupled(const AssemblyPart& part) {
  loadedNodes();
  if (m_coupledCount == 0) return false;
  for (const int n : part.nodes)
    if (m_coupledMark[static_cast<std::size_t>(n)]) return true;
  return false;
}

namespace {
/// Zeroes the entries of `work` at `nodes` (all their DOFs).
void zeroNodes(const model::DofMap& dofs, const std::vector<int>& nodes, VecX& work) {
  for (const int n : nodes) {
    const int d = dofs.firstDof(n);
    const int count = dofs.dofCount(n);
    for (int k = 0; k < count; ++k) work[d + k] = 0.0;
  }
}
/// Copies the entries of `from` at `nodes` into `to`.
void copyNodes(const model::DofMap& dofs, const std::vector<int>& nodes, const VecX& from, VecX& to) {
  for (const int n : nodes) {
    const int d = dofs.firstDof(n);
    const int count = dofs.dofCount(n);
    for (int k = 0; k < count; ++k) to[d + k] = from[d + k];
  }
}
}  // namespace

void Assembler::assemblePart(const model::State& state, const AssemblyRequest& request,
                             const AssemblyPart& part, VecX& force) {
  const model::DofMap& dofs = m_model->dofs();
  // The part's terms are summed into a work vector in the order of assemble(); the entries of part.nodes,
  // which receive every term they receive in assemble(), are then copied. Entries of other written nodes
  // hold only some of their terms and are dropped.
  m_partWork.resize(dofs.fullDofCount());
  zeroNodes(dofs, part.writtenNodes, m_partWork);
  addAll(state, request, m_partWork, nullptr, &part);
  copyNodes(dofs, part.nodes, m_partWork, force);
}

void Assembler::addPartMass(const model::State& state, const AssemblyPart& part, const VecX& acceleration,
                            VecX& out) {
  const model::DofMap& dofs = m_model->dofs();
  m_partWork.resize(dofs.fullDofCount());
  zeroNodes(dofs, part.writtenNodes, m_partWork);
  addAllMass(state, 0.0, nullptr, &acceleration, &m_partWork, &part);
  copyNodes(dofs, part.nodes, m_partWork, out);
}

void Assembler::addPartMatrix(const model::State& state, const AssemblyRequest& request, double mf,
                              const AssemblyPart& part, SystemMatrix& matrix) {
  // The part's terms in the order of assemble() and addMass(), with the matrix; the forces computed on
  // the way are those the last evaluation at `state` gave (the same arithmetic) and are dropped.
  m_partWork.resize(m_model->dofs().fullDofCount());
  addAll(state, request, m_partWork, &matrix, &part);
  addAllMass(state, mf, &matrix, nullptr, nullptr, &part);
}

std::vector<double> Assembler::elementTension(const model::State& state,
                                              std::vector<element::BeamSectionForces>* beamForces) const {
  std::vector<double> t;
  if (beamForces) beamForces->assign(m_model->elements().size(), element::BeamSectionForces{});
  elementTension(state, t, beamForces);
  return t;
}

void Assembler::elementTension(const model::State& state, std::vector<double>& t,
                               std::vector<element::BeamSectionForces>* beamForces,
                               const std::vector<int>* only) const {
  const auto& elements = m_model->elements();
  t.resize(elements.size());
  if (beamForces) beamForces->resize(elements.size());
  const model::PartedElements& parted = m_model->parted();
  forEachIndex(only, elements.size(), [&](std::size_t e) {
    const model::LineElement& el = elements[e];
    if (parted.parted(e, state.time)) {  // lines[].failure: no force of any kind
      t[e] = 0.0;
      if (beamForces) (*beamForces)[e] = element::BeamSectionForces{0.0, 0.0, Vec3::Zero(), Vec3::Zero()};
      return;
    }
    if (const int visco = m_visco.index(e); visco >= 0 && m_visco.active(state)) {
      t[e] = m_visco.tension(visco, state, compressionFactor(el));
    } else if (el.bar) {
      std::optional<element::Bar> barCopy;
      t[e] = barOf(e, barCopy)
                 .axialForce(state.position[el.node1], state.position[el.node2], compressionFactor(el));
    } else {
      std::optional<element::CorotationalBeam> beamCopy;
      const element::BeamSectionForces f =
          beamOf(e, beamCopy)
              .sectionForces(state.position[el.node1], state.triad[el.node1], state.position[el.node2],
                             state.triad[el.node2]);
      t[e] = f.axialForce;
      if (beamForces) (*beamForces)[e] = f;
    }
  });
}

}  // namespace tangle::solver
