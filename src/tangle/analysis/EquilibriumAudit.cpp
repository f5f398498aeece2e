#include "tangle/analysis/EquilibriumAudit.hpp"

#include <algorithm>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/vessel/VesselSystem.hpp"

namespace tangle::analysis {

namespace {

/// The static loads of the model by source, out-of-balance sign (external loads negative), full DOFs.
struct LoadTerms {
  VecX weight, attachments, seabed, drag, contact, other;
  /// Drag of the attachments at line end nodes, which are at the end, not on the line.
  VecX endAttachmentDrag;
};

bool isLineEnd(const model::Model& model, int node) {
  const int l = model.lineOfNode(node);
  return l >= 0 && (node == model.lines()[static_cast<std::size_t>(l)].firstNode ||
                    node == model.lines()[static_cast<std::size_t>(l)].lastNode());
}

LoadTerms staticLoads(Simulation& simulation) {
  const model::Model& model = simulation.model();
  solver::Assembler& assembler = simulation.assembler();
  const model::State& state = simulation.state();
  const int size = model.dofs().fullDofCount();
  solver::AssemblyRequest request;
  request.time = state.time;
  request.wantMatrix = false;
  const auto term = [&](solver::Assembler::Term t) {
    VecX f = VecX::Zero(size);
    assembler.addTerm(t, state, request, f);
    return f;
  };
  LoadTerms terms;
  terms.weight = term(solver::Assembler::Term::Weight);
  terms.attachments = term(solver::Assembler::Term::Attachments);
  terms.seabed = term(solver::Assembler::Term::Seabed);
  terms.drag = VecX::Zero(size);
  terms.contact = VecX::Zero(size);
  terms.other = VecX::Zero(size);
  terms.endAttachmentDrag = VecX::Zero(size);
  for (solver::LoadContributor* c : assembler.contributors()) {
    // The supports of the line ends: vessels' links and the ties at free points.
    if (c->source() == solver::LoadSource::Vessels || c->source() == solver::LoadSource::Junctions) continue;
    if (c->source() == solver::LoadSource::Hydrodynamic) {
      c->addForces(state, request, terms.drag, nullptr);
      solver::AssemblyPart part;
      for (std::size_t i = 0; i < model.attachments().size(); ++i)
        if (isLineEnd(model, model.attachments()[i].node)) part.attachments.push_back(static_cast<int>(i));
      if (!part.attachments.empty()) c->addPartForces(state, request, part, terms.endAttachmentDrag, nullptr);
    } else if (c->source() == solver::LoadSource::Contact) {
      c->addForces(state, request, terms.contact, nullptr);
    } else {
      c->addForces(state, request, terms.other, nullptr);
    }
  }
  return terms;
}

/// The loads on `node` from its line (weight and buoyancy, drag, seabed, contact, other contributors) and,
/// unless it is a line end, from its attachments [N] (external loads positive).
Vec3 nodeLoad(const model::Model& model, const LoadTerms& t, int node) {
  const int d = model.dofs().firstDof(node);
  Vec3 f = -(t.weight.segment<3>(d) + t.seabed.segment<3>(d) + t.drag.segment<3>(d) + t.contact.segment<3>(d) +
             t.other.segment<3>(d));
  if (isLineEnd(model, node))
    f += t.endAttachmentDrag.segment<3>(d);
  else
    f -= t.attachments.segment<3>(d);
  return f;
}

/// The part of the seabed's vertical reaction at a line's end node `node` that does not carry the line [N]
/// (upward positive): what exceeds the line's own weight lumped on the node. The seabed first carries the
/// line's own weight there; the rest holds up what is at the end (a clump at a free point resting on the
/// seabed), which is not the line's pull. (A node held in x, y and z has no seabed spring: theory 7.8.)
double seabedBeyondLine(const model::Model& model, const LoadTerms& t, int node) {
  const int d = model.dofs().firstDof(node);
  const double reaction = -t.seabed[d + 2];                 // external, upward positive
  const double ownWeight = std::max(t.weight[d + 2], 0.0);  // the line's weight on the node, downward
  return reaction > ownWeight ? reaction - ownWeight : 0.0;
}

Vec3 sumOver(const model::DofMap& dofs, const VecX& force, int first, int last) {
  Vec3 sum = Vec3::Zero();
  for (int node = first; node <= last; ++node) sum -= force.segment<3>(dofs.firstDof(node));
  return sum;
}

/// The sum of the forces the line ends at `endNodes` exert on what holds them (their end forces) [N].
Vec3 endPulls(const model::Model& model, const std::vector<solver::LineSnapshot>& snapshot,
              const std::vector<int>& endNodes) {
  Vec3 pulls = Vec3::Zero();
  for (const int node : endNodes) {
    const auto l = static_cast<std::size_t>(model.lineOfNode(node));
    pulls += node == model.lines()[l].firstNode ? snapshot[l].endTensionForceA : snapshot[l].endTensionForceB;
  }
  return pulls;
}

/// A body's residual (the sum of its terms), its reference force (its largest term, at least 1 N) and the
/// tolerance of a body held by `ends` line ends: what the statics' test allows at 1 + ends nodes.
void closeBodyBalance(solver::ForceBalance& b, std::size_t ends, double nodeBound) {
  b.scale = 1.0;
  for (const auto& term : b.terms) {
    b.residual += term.second;
    b.scale = std::max(b.scale, term.second.norm());
  }
  b.tolerance = static_cast<double>(1 + ends) * nodeBound / b.scale;
}

}  // namespace

void setStaticEndForces(Simulation& simulation, std::vector<solver::LineSnapshot>& lines) {
  const model::Model& model = simulation.model();
  const model::State& state = simulation.state();
  const LoadTerms terms = staticLoads(simulation);
  std::vector<element::BeamSectionForces> beams;
  const std::vector<double> tension = simulation.assembler().elementTension(state, &beams);
  for (std::size_t l = 0; l < model.lines().size(); ++l) {
    const model::Line& line = model.lines()[l];
    solver::LineSnapshot& s = lines[l];
    const auto section = [&](int e) {
      const model::LineElement& el = model.elements()[static_cast<std::size_t>(e)];
      return solver::elementSectionForce(state, el, tension[static_cast<std::size_t>(e)],
                                         el.beam ? &beams[static_cast<std::size_t>(e)] : nullptr);
    };
    const int firstElement = line.firstElement;
    const int lastElement = line.firstElement + line.elementCount - 1;
    // The end node's balance: support S, the line's loads on the node f, the end element's section force
    // (on node A: +T, it pulls the node into the line; on node B: -T). The line pulls its support with -S.
    // The seabed's reaction at the node beyond the line's own weight there is not the line's: it holds up
    // what is at the end, or pushes on a support held into the seabed (seabedBeyondLine).
    const auto beyond = [&](int node) { return Vec3(0.0, 0.0, seabedBeyondLine(model, terms, node)); };
    s.endTensionForceA =
        section(firstElement) + nodeLoad(model, terms, line.firstNode) - beyond(line.firstNode);
    s.endTensionForceB =
        -section(lastElement) + nodeLoad(model, terms, line.lastNode()) - beyond(line.lastNode());
    // The end tension is the axial part: along the line's tangent at a beam's end (its triad's first axis),
    // the whole force at a cable's (which carries no shear).
    const auto axial = [&](const Vec3& force, int node, int element, double towardsLine) {
      const model::LineElement& el = model.elements()[static_cast<std::size_t>(element)];
      const double sign = tension[static_cast<std::size_t>(element)] < 0.0 ? -1.0 : 1.0;
      if (!el.beam) return sign * force.norm();
      return towardsLine * force.dot(state.triad[static_cast<std::size_t>(node)].col(0));
    };
    s.endTensionA = axial(s.endTensionForceA, line.firstNode, firstElement, 1.0);
    s.endTensionB = axial(s.endTensionForceB, line.lastNode(), lastElement, -1.0);
    s.tension.front() = s.endTensionA;
    s.tension.back() = s.endTensionB;
    solver::setWallTension(model, static_cast<int>(l), s);
  }
}

solver::EquilibriumAudit auditStatics(Simulation& simulation, const std::vector<solver::LineSnapshot>& snapshot) {
  const model::Model& model = simulation.model();
  const model::DofMap& dofs = model.dofs();
  const LoadTerms t = staticLoads(simulation);
  // What the static solver's convergence test leaves at one node at most [N] (ForceBalance::tolerance).
  const double nodeBound = model.spec().statics.tolerance * simulation.assembler().forceScale();

  solver::EquilibriumAudit audit;
  for (std::size_t l = 0; l < model.lines().size(); ++l) {
    const model::Line& line = model.lines()[l];
    const solver::LineSnapshot& s = snapshot[l];
    const int first = line.firstNode, last = line.lastNode();
    solver::ForceBalance b;
    b.name = line.name;
    b.scale = simulation.assembler().nodeForceScale()[static_cast<std::size_t>(first)];
    // The seabed's reaction at the end nodes beyond the line's own weight is not the line's: the end forces
    // leave it out (setStaticEndForces), and so does the line's balance.
    const Vec3 bed =
        sumOver(dofs, t.seabed, first, last) -
        Vec3(0.0, 0.0,
             seabedBeyondLine(model, t, first) + (last != first ? seabedBeyondLine(model, t, last) : 0.0));
    // What is attached at an end node is at the end (its pull is in the end force), not on the line.
    Vec3 attached = sumOver(dofs, t.attachments, first + 1, last - 1);
    const Vec3 endAttachmentDrag = -sumOver(dofs, t.endAttachmentDrag, first, first) -
                                   (last != first ? sumOver(dofs, t.endAttachmentDrag, last, last) : Vec3::Zero());
    b.terms = {{"weight and buoyancy", sumOver(dofs, t.weight, first, last)},
               {"attachments", attached},
               {"drag", sumOver(dofs, t.drag, first, last) + endAttachmentDrag},
               {"seabed reaction", Vec3(0.0, 0.0, bed.z())},
               {"seabed friction", Vec3(bed.x(), bed.y(), 0.0)},
               {"contact", sumOver(dofs, t.contact, first, last)},
               {"other", sumOver(dofs, t.other, first, last)},
               // The line pulls its supports with the end forces; they pull it back.
               {"end A", -s.endTensionForceA},
               {"end B", -s.endTensionForceB}};
    for (const auto& term : b.terms) b.residual += term.second;
    b.tolerance = (last - first + 1) * nodeBound / b.scale;
    audit.lines.push_back(std::move(b));
  }

  // Each free point: its body's weight and buoyancy and its drag (the attachment at its carrier node) against
  // the pulls of the line ends there (each line's end force, which the line exerts on its support).
  for (const model::JunctionPoint& p : model.points()) {
    solver::ForceBalance b;
    b.name = p.name;
    // What is attached at the carrier node is at the point (external loads positive).
    const int d = dofs.firstDof(p.node);
    const Vec3 body = -t.attachments.segment<3>(d), drag = -t.endAttachmentDrag.segment<3>(d);
    // The seabed under the line ends at the point beyond their own weight holds up the point's body.
    Vec3 bed = Vec3::Zero();
    for (const int node : p.endNodes) bed.z() += seabedBeyondLine(model, t, node);
    b.terms = {{"weight and buoyancy", body},
               {"drag", drag},
               {"lines", endPulls(model, snapshot, p.endNodes)},
               {"seabed", bed}};
    closeBodyBalance(b, p.endNodes.size(), nodeBound);
    audit.points.push_back(std::move(b));
  }

  if (const vessel::VesselSystem* vessels = simulation.vessels()) {
    solver::AssemblyRequest request;
    request.time = simulation.state().time;
    request.wantMatrix = false;
    for (const auto& r : vessels->loadReadings(simulation.state(), request)) {
      if (!r.free || r.pinned) continue;  // held in translation: the balance is its support's reaction
      solver::ForceBalance b;
      b.name = r.name;
      // Hull contact (vessel::HullContact, the only contact that loads a vessel node), with the sign of an
      // external load; a term only in models with a hull.
      b.terms = {{"body loads", r.body.head<3>()},
                 {"station keeping", r.hold.head<3>()},
                 {"lines", endPulls(model, snapshot, r.endNodes)}};
      Vec3 bed = Vec3::Zero();  // the seabed under the line ends beyond their own weight (seabedBeyondLine)
      for (const int node : r.endNodes) bed.z() += seabedBeyondLine(model, t, node);
      if (bed.z() != 0.0) b.terms.push_back({"seabed", bed});
      if (simulation.hullContact())
        b.terms.push_back({"hull contact", -t.contact.segment<3>(dofs.firstDof(r.node))});
      closeBodyBalance(b, r.endNodes.size(), nodeBound);
      audit.vessels.push_back(std::move(b));
    }
  }
  return audit;
}

}  // namespace tangle::analysis
