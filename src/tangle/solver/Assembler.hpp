#pragma once
/// @file Assembler.hpp
/// Assembles the out-of-balance force F(q, v, t) = f_internal + f_damping - f_external of the whole
/// model and, in one call, the iteration matrix H = kf dF/dq + cf dF/dv (Chrono-style: the caller
/// picks the factors of its integrator; statics uses kf = 1, cf = 0). Inertia is kept apart
/// (addMass) because integrators combine it differently. State gather/scatter is not done here.

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tangle/core/Types.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/model/State.hpp"
#include "tangle/solver/LoadContributor.hpp"
#include "tangle/solver/SystemMatrix.hpp"
#include "tangle/solver/ViscoelasticElements.hpp"

namespace tangle::solver {

/// Structural elements, weight and buoyancy, point attachments and the seabed; plus any number of
/// LoadContributors.
class Assembler {
 public:
  explicit Assembler(const model::Model& model);

  /// Registers an additional force source (the Assembler keeps a non-owning pointer).
  void addContributor(LoadContributor* contributor) { m_contributors.push_back(contributor); }
  /// The registered force sources.
  const std::vector<LoadContributor*>& contributors() const { return m_contributors; }

  // ---- Path-dependent state (LoadContributor's trial / commit protocol): the seabed friction anchors held
  // here, then every contributor's. The solvers call these; nothing else commits.

  /// Statics starts (or restarts, or reverts) from `state`: seabed friction anchors are set at the as-laid
  /// positions of the nodes on the seabed in `state`; forwards LoadContributor::beginStatic.
  void beginStatics(const model::State& state);
  /// Statics: the index of a line that lies wholly on the seabed with both ends free and whose seabed
  /// friction (against the committed anchors: call it after commitIncrement) at `state` has a resultant of
  /// at least 99 % of the sum of its nodes' caps mu N, -1 if none. Such a line is about to slide as a whole:
  /// under a larger load along the same path it has no static equilibrium.
  int lineSlidingAsAWhole(const model::State& state) const;
  /// A statics load increment converged at `state`: commits the friction anchors (the trial ones of the
  /// last assembly) and forwards LoadContributor::commitIncrement.
  void commitIncrement(const model::State& state);
  /// Forwards LoadContributor::rejectState: the first contributor's reason, empty if none.
  std::string rejectState(const model::State& state);
  /// The smallest LoadContributor::limitStep [s] (+inf if none limits).
  double limitStep(const model::State& state, double step);
  /// The smallest LoadContributor::maxStepGrowth [-] (2 if none is stricter).
  double maxStepGrowth() const;
  /// Forwards LoadContributor::rejectStep: the first contributor's reason, empty if none.
  std::string rejectStep(const model::State& before, const model::State& after);
  /// True if any contributor's rejectStep can refuse a step (LoadContributor::rejectsSteps).
  bool rejectsSteps() const {
    return std::any_of(m_contributors.begin(), m_contributors.end(),
                       [](const LoadContributor* c) { return c->rejectsSteps(); });
  }
  /// An accepted dynamic step of `dt` [s] (the seabed friction anchors at `state` become the committed ones),
  /// or with dt = 0 the final static solution (the anchors are those of its last increment); then forwards
  /// LoadContributor::commitStep.
  void commitStep(model::State& state, double dt);
  /// Forwards LoadContributor::finish (end of the dynamics at `time` [s]).
  void finish(double time);

  /// F (full DOFs) and, if request.wantMatrix and matrix is given, H (equations). `force` is resized and
  /// zeroed; `matrix` is cleared and assembled only when request.wantMatrix (else left as it was).
  void assemble(const model::State& state, const AssemblyRequest& request, VecX& force, SystemMatrix* matrix);

  /// The built-in terms of F, one at a time, for the equilibrium audit (analysis/EquilibriumAudit).
  enum class Term {
    Elements,     ///< internal forces of the structural elements (and their axial damping in dynamics)
    Weight,       ///< weight and buoyancy of the elements
    Attachments,  ///< weight and buoyancy of the point masses and buoys
    Seabed        ///< seabed reaction and friction
  };
  /// Adds one term of F (out-of-balance sign: external loads subtracted) at `state` to `force` (full DOFs,
  /// not resized). Seabed: as in assemble, including its side effect on the trial friction anchors (the
  /// same ones a whole assembly at `state` sets).
  void addTerm(Term term, const model::State& state, const AssemblyRequest& request, VecX& force);

  /// True when assemblePart and addPartMass can stand for assemble and addMass: every contributor's
  /// forces are local to elements and nodes (LoadContributor::supportsParts).
  bool supportsParts() const;
  /// The part to re-evaluate after the nodes `moved` (ascending, each once) moved and no other did; false
  /// (part unusable: assemble the whole model) when it holds a node a contributor marks as loaded
  /// (LoadContributor::markLoadedNodes). With `coupled`, a part that holds a node of a contributor coupled
  /// in parts (LoadContributor::coupledInParts: line contact) is given all of that contributor's nodes
  /// and their elements instead (the other line at a crossing), and is refused only for the others'.
  bool selectPart(const std::vector<int>& moved, AssemblyPart& part, bool coupled = false);
  /// Whether a part selectPart made is usable now: no contributor marks one of its nodes as loaded, or (made
  /// with `coupled`) the coupled contributors' marked nodes are in it all or not at all. (Its nodes, elements
  /// and attachments depend on the moved nodes alone; the marks change with each whole assembly: a caller
  /// that assembles the same part again and again asks this instead of selecting it anew.)
  bool partUsable(const AssemblyPart& part);
  /// Per node, 1 where a contributor left out of parts loads it or reads its state (LoadContributor::
  /// markLoadedNodes: near a line contact, the ends tied to a vessel or a free point), as of the last whole
  /// assembly; else 0.
  const std::vector<char>& loadedNodes();
  /// Whether loadedNodes() marks any node.
  bool anyLoadedNode() {
    loadedNodes();
    return m_anyLoadedMark;
  }
  /// Sets the entries of `force` (full DOFs) at part.nodes to what assemble(state, request, force, nullptr)
  /// would give them, bit for bit (the same terms summed in the same order); the other entries are kept.
  /// Correct when `force` holds a full assembly at a state that differs from `state` only at nodes whose
  /// elements are all in the part (the moved nodes of selectPart). Requires supportsParts().
  void assemblePart(const model::State& state, const AssemblyRequest& request, const AssemblyPart& part,
                    VecX& force);
  /// Sets the entries of `out` at part.nodes to those of M * acceleration (addMass with out zeroed),
  /// keeping the others. Requires supportsParts().
  void addPartMass(const model::State& state, const AssemblyPart& part, const VecX& acceleration, VecX& out);
  /// Adds the iteration matrix's terms of a part, H = kf dF/dq + cf dF/dv (as assemble with request.wantMatrix)
  /// and mf M (as addMass), of its elements, nodes and attachments, to `matrix`: with part = whole
  /// independent blocks and `matrix` in a patch of their equations (SystemMatrix::beginPatch), their entries
  /// of a whole assembly at `state` (GeneralizedAlpha's refresh of blocks). Side effects as assemblePart at
  /// `state`. Requires supportsParts().
  void addPartMatrix(const model::State& state, const AssemblyRequest& request, double mf,
                     const AssemblyPart& part, SystemMatrix& matrix);

  /// Statics length continuation: element e is given the unstretched length restLengths[e] [m] instead of
  /// its own (NaN keeps its own); an empty vector restores every element. Weight stays the nominal one.
  void setRestLengths(std::vector<double> restLengths) { m_restLength = std::move(restLengths); }
  /// Unstretched length [m] element e has in assembly now (its own, or the continuation's override).
  double restLengthOf(std::size_t e) const {
    return m_restLength.empty() || std::isnan(m_restLength[e]) ? m_model->elements()[e].restLength
                                                               : m_restLength[e];
  }

  /// A node's lumped submerged line weight over its tributary length [N/m] (its elements' halves, each
  /// type's submerged weight): what the seabed carries under the node where it rests
  /// (Seabed::carriedFraction; addSeabed's share of an anchor, LineResults' end slope).
  double restingWeightPerLength(int node) const {
    return m_restingWeightPerLength[static_cast<std::size_t>(node)];
  }

  /// Lower bound on the fraction of EA a slack cable element keeps [-] (LineType::compressionFactor
  /// applies above it); 0 by default. Statics raises it temporarily (continuation in the cable law).
  void setSlackFactor(double factor) { m_slackFactor = factor; }
  double slackFactor() const { return m_slackFactor; }

  /// Forwards LoadContributor::beginStep to every contributor.
  void beginStep() {
    for (LoadContributor* c : m_contributors) c->beginStep();
  }
  /// True if a contributor filters the Newton corrections of dynamics (LoadContributor::limitsDynamicIncrements).
  bool limitsDynamicIncrements() const {
    return std::any_of(m_contributors.begin(), m_contributors.end(),
                       [](const LoadContributor* c) { return c->limitsDynamicIncrements(); });
  }
  /// The smallest fraction of the correction `fullIncrement` (full DOFs) those contributors accept.
  double limitDynamicIncrement(const model::State& state, const VecX& fullIncrement) {
    double alpha = 1.0;
    for (LoadContributor* c : m_contributors)
      if (c->limitsDynamicIncrements()) alpha = std::min(alpha, c->limitIncrement(state, fullIncrement));
    return std::max(alpha, 0.0);
  }
  /// Forwards LoadContributor::updateActiveSet; true if any contributor changed its active set.
  bool updateActiveSet() {
    bool changed = false;
    for (LoadContributor* c : m_contributors) changed = c->updateActiveSet() || changed;
    return changed;
  }

  /// Adds mf * M to matrix and M * acceleration to out (full DOFs); M is the lumped structural mass
  /// plus whatever mass the contributors add (added mass).
  void addMass(const model::State& state, double mf, SystemMatrix* matrix, const VecX* acceleration, VecX* out);

  /// Effective tension [N] of each element (axial force; with weight applied as submerged weight it is
  /// the effective tension of Sparks 1984).
  /// With `beamForces`, also the section forces of every beam element (resized to the element count;
  /// bar entries left default), computed once for both.
  std::vector<double> elementTension(const model::State& state,
                                     std::vector<element::BeamSectionForces>* beamForces = nullptr) const;
  /// As above, into `tension` (resized to the element count; no allocation once sized: the writer thread's
  /// range graphs take it at every step). `beamForces`, when given, is resized and its beam entries set;
  /// its bar entries are left as they were. With `only`, just the elements it lists are computed (the
  /// other entries are left as they were).
  void elementTension(const model::State& state, std::vector<double>& tension,
                      std::vector<element::BeamSectionForces>* beamForces,
                      const std::vector<int>* only = nullptr) const;

  /// Force scale [N] of the static and dynamic convergence tests, independent of the mesh: the largest over
  /// the lines of the line's submerged weight (absolute, each element), 10 % of its weight in air and the
  /// weight of its attachments, and at least 1 N.
  double forceScale() const { return m_forceScale; }
  /// Force scale [N] of each node for the dynamic convergence test: the scale of its line as in
  /// forceScale() but without the 1 N floor (a 2 g body next to a 2000 t one is tested on its own weight),
  /// forceScale() for nodes on no line (vessels).
  const std::vector<double>& nodeForceScale() const { return m_nodeForceScale; }
  /// Round-off floor [N] of the out-of-balance force of each node at `state` (into `floor`, one per node):
  /// 16 max(EA eps |x| / L, EI eps |x| / L^2, 1e-14 EA) over the elements at the node (see roundoffFloor),
  /// the global roundoffFloor for nodes on no element. Per node, so that a stiff line's round-off does not
  /// become the tolerance of a light one.
  void nodeRoundoffFloor(const model::State& state, std::vector<double>& floor) const;
  /// True when no node's round-off floor at `state` (nodeRoundoffFloor) can reach `tolerance` [-] times its
  /// force scale (nodeForceScale), so that the dynamic convergence test allows every node the tolerance's
  /// out-of-balance and the floors need not be formed: a bound from the largest coordinate of any node (the
  /// floors grow with |x|), with a factor 2 to spare. False when a contributor raises floors.
  bool roundoffFloorNegligible(const model::State& state, double tolerance) const;
  /// Round-off floor [N] of the out-of-balance force at `state`: an element's force is known only to
  /// about EA eps |x| / L (the strain is a difference of coordinates of magnitude |x|), its moments to
  /// EI eps |x| / L^2; a residual cannot be driven below a few times the largest of these.
  double roundoffFloor(const model::State& state) const;
  /// Force resolution [N] set by round-off: out-of-balance forces below it are noise
  /// (about 1e-14 * the largest axial stiffness EA; a residual cannot be driven lower).
  double roundoffForce() const { return m_roundoffForce; }

  const model::Model& model() const { return *m_model; }

 private:
  /// Makes the trial friction anchors of the last assembly the committed ones.
  void commitAnchors(const model::State& state);
  /// The seabed friction's anchor (x, y) [m] of `node` at `position` [m]: its committed (as-laid) anchor,
  /// else for a node that touched down since the last commit its position then, else its footprint now.
  /// (Inline: addSeabed asks at every grounded node of every assembly.)
  Vec2 frictionAnchor(int node, const Vec3& position) const {
    const auto n = static_cast<std::size_t>(node);
    if (!std::isnan(m_anchor[n].x())) return m_anchor[n];
    if (!std::isnan(m_committedXY[n].x())) return m_committedXY[n];
    return m_model->seabedSurface().footprint(position);
  }
  // Every term of F (of M a) in a fixed order, of the whole model or (with `part`) of a part: assemble and
  // assemblePart (addMass and addPartMass) share it.
  void addAll(const model::State& state, const AssemblyRequest& request, VecX& force, SystemMatrix* matrix,
              const AssemblyPart* part);
  void addAllMass(const model::State& state, double mf, SystemMatrix* matrix, const VecX* acceleration,
                  VecX* out, const AssemblyPart* part);
  // The loops of addAll and addAllMass; with lists, over those elements, nodes and attachments only.
  void addElements(const model::State& state, const AssemblyRequest& request, VecX& force,
                   SystemMatrix* matrix, const std::vector<int>* elements = nullptr);
  /// With `matrix`: the waterplane stiffness of elements through the surface.
  void addWeight(const model::State& state, const AssemblyRequest& request, VecX& force,
                 const std::vector<int>* elements = nullptr, const std::vector<int>* attachments = nullptr,
                 SystemMatrix* matrix = nullptr);
  /// Element `element`'s axial damper along its chord direction e [-] (the caller's: the bar's own, or the
  /// chord normalised), between the nodes whose first DOFs are d1 and d2.
  void addAxialDamping(const model::State& state, std::size_t element, const Vec3& e, int d1, int d2,
                       const AssemblyRequest& request, VecX& force, SystemMatrix* matrix) const;
  /// A viscoelastic rope's bar in the dynamics (ViscoelasticElements k): its axial force from the law, the
  /// tangent kf (dN/d eps / L0 e e^T + N / l (I - e e^T)) + cf dN/d eps' / L0 e e^T, Rayleigh damping as a
  /// bar's.
  void addViscoelasticBar(const model::State& state, const model::LineElement& el, int k, int d1, int d2,
                          double beta, const AssemblyRequest& request, VecX& force,
                          SystemMatrix* matrix) const;
  void addSeabed(const model::State& state, const AssemblyRequest& request, VecX& force, SystemMatrix* matrix,
                 const std::vector<int>* nodes = nullptr);
  void addOwnMass(double mf, SystemMatrix* matrix, const VecX* acceleration, VecX* out,
                  const std::vector<int>* elements = nullptr, const std::vector<int>* nodes = nullptr,
                  const std::vector<int>* attachments = nullptr) const;
  /// Element e's bar or beam, or, under the statics length continuation (setRestLengths), a copy with the
  /// overriding unstretched length built in `copy`; no copy in the common case.
  /// (Inline: called for every bar of every assembly.)
  const element::Bar& barOf(std::size_t e, std::optional<element::Bar>& copy) const {
    if (m_restLength.empty() || std::isnan(m_restLength[e])) return *m_model->elements()[e].bar;
    const element::Bar& own = *m_model->elements()[e].bar;
    return copy.emplace(own.axialStiffness(), m_restLength[e], own.tensionStrainCurve());
  }
  const element::CorotationalBeam& beamOf(std::size_t e, std::optional<element::CorotationalBeam>& copy) const;
  /// Fraction of EA a slack cable element keeps: its type's, raised to the statics continuation's bound.
  double compressionFactor(const model::LineElement& el) const {
    return std::max(el.type->compressionFactor, m_slackFactor);
  }

  const model::Model* m_model;
  ViscoelasticElements m_visco;  // the viscoelastic ropes' bars and their internal variables
  std::vector<LoadContributor*> m_contributors;
  double m_forceScale = 1.0;
  std::vector<double> m_nodeForceScale;
  std::vector<double> m_halfWeight;    // half of each element's weight in air [N] (addWeight)
  std::vector<double> m_halfBuoyancy;  // half of its buoyancy fully submerged [N]
  /// A node held in x, y and z: its share of one element's submerged weight [N], that element's other node
  /// and the other node's lumped submerged line weight over its tributary length [N/m].
  struct HeldShare {
    int other = -1;
    double weight = 0.0;
  };
  std::vector<double> m_restingWeightPerLength;          // per node [N/m] (restingWeightPerLength)
  std::vector<std::vector<HeldShare>> m_heldNodeShares;  // per node: its elements' shares if held (else none)
  std::vector<double> m_axialDampingRate;  // each element's axial damping c over its L0 [N s/m]
  // Per full DOF, the node's own diagonal mass term of addOwnMass's node loop: its lumped mass [kg] at a
  // translation (0 with consistent mass, whose translations the element loop adds), its rotational
  // inertia [kg m^2] at a rotation (0 at DOFs the node does not have).
  std::vector<double> m_nodeDiagonalMass;
  // Per element, the constants of nodeRoundoffFloor: 16 EA eps / l and 16 EI eps / l^2 (0 for a bar), the
  // rest length l and the force resolution 10e-14 EA (not looked up per element and step: docs/performance.md).
  struct RoundoffConstants {
    double axialPerLength;           // 16 eps EA / l [N/m]
    double bendingPerLengthSquared;  // 16 eps EI / l^2 [N] (0 for a bar)
    double length;                   // l [m]
    double resolution;               // [N]
  };
  std::vector<RoundoffConstants> m_roundoff;
  // roundoffFloorNegligible's bound, for the tolerance m_negligibleFor: the coordinate [m] below which every
  // node's floor is under half its allowance (-inf: never).
  mutable double m_negligibleFor = std::numeric_limits<double>::quiet_NaN();
  mutable double m_negligibleReach = -std::numeric_limits<double>::infinity();
  // Seabed friction in statics: committed anchor (x, y) per node (NaN: none) and the trial anchors of the
  // last assembly; positions (x, y) at the last commit, anchors of nodes that touch down later.
  std::vector<Vec2> m_anchor;
  std::vector<Vec2> m_trialAnchor;
  std::vector<Vec2> m_committedXY;
  std::vector<double> m_restLength;  // statics length continuation (setRestLengths)
  double m_slackFactor = 0.0;
  double m_roundoffForce = 0.0;
  // Parts: the elements at each node, marks per node and element, and the work space of assemblePart.
  std::vector<std::vector<int>> m_nodeElements;
  std::vector<char> m_nodeMark;
  std::vector<char> m_elementMark;
  std::vector<char> m_loadedMark;  // nodes loaded by contributors left out of parts (markLoadedNodes)
  std::vector<char> m_strictMark;  // of them, by those not coupled in parts (vessels, junctions)
  std::vector<char> m_coupledMark;  // by those coupled in parts (line contact: coupledInParts)
  int m_coupledCount = 0;           // nodes m_coupledMark marks
  /// Whether `part` holds a node of a contributor coupled in parts (their whole terms are then the part's).
  bool holdsCoupled(const AssemblyPart& part);
  bool m_anyLoadedMark = false;    // some contributor marked nodes
  bool m_loadedMarkValid = false;  // m_loadedMark gathered since the last whole assembly
  VecX m_partWork;
};

}  // namespace tangle::solver
