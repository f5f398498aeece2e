#pragma once
/// @file LineContact.hpp
/// Line-to-line contact (the seed paper's contact model): any two contact-enabled lines (or the pairs
/// the user lists) may touch anywhere along both; the contact point is found again at every Newton
/// iteration from the closest points of element segments (Eberly's algorithm), so it slides freely
/// along both lines and from element to element.
///
/// Per contact point: gap g = |pA - pB| - (rA + rB); normal force from a penalty spring and a dashpot
/// (ContactLaw.hpp) calibrated to the coefficient of restitution with the effective mass of the pair,
/// which is tracked during each impact with the paper's Eq. 5 (m_eff = integral of F dt / change of the
/// relative normal velocity); optional regularised Coulomb friction; forces go to the element nodes
/// through the linear shape functions. Path-dependent data (impact velocity, impulse, effective mass)
/// follow a trial / commit protocol: addForces() only reads committed data, commitStep() updates it
/// after an accepted step, and a rejected step needs no revert.
///
/// One physical contact is counted once: of the element pairs in contact between two lines, only local
/// minima of the distance over neighbouring pairs are kept, so a contact point crossing a node (where
/// two neighbouring pairs report the same point) gives one force, continuous across the node.

#include <array>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "tangle/contact/BroadPhase.hpp"
#include "tangle/contact/ContactCandidates.hpp"
#include "tangle/contact/ContactEvents.hpp"
#include "tangle/contact/DistributedContact.hpp"
#include "tangle/contact/RadiusProfile.hpp"
#include "tangle/contact/SmoothCentreline.hpp"
#include "tangle/geometry/SegmentDistance.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/solver/Assembler.hpp"

namespace tangle::contact {

/// One contact point at the current (trial) state.
struct ContactPoint {
  int lineA = 0, lineB = 0;           ///< line indices, lineA < lineB (or equal for self contact)
  int elementA = 0, elementB = 0;     ///< global element indices
  double s = 0.0, t = 0.0;            ///< segment parameters of the closest points [-]
  Vec3 pointA, pointB;                ///< closest points on the centrelines [m]
  Vec3 normal;                        ///< unit normal from B to A
  double gap = 0.0;                   ///< distance minus the contact radii [m] (< 0: penetration)
  double gapRate = 0.0;               ///< d(gap)/dt: relative normal velocity [m/s] (< 0 approaching)
  double normalForce = 0.0;           ///< [N], >= 0
  Vec3 frictionForce = Vec3::Zero();  ///< friction force on A [N]
  double arcA = 0.0, arcB = 0.0;      ///< arc length of the contact point along each line [m]
  double lumpedMassA = 0.0, lumpedMassB = 0.0;  ///< instantaneous effective masses at the point [kg]
  double pairMass = 0.0;                        ///< effective mass used by the dashpot [kg]
  double stiffness = 0.0;                       ///< [N/m]
  double damping = 0.0;                         ///< [N s/m]
  int track = -1;                               ///< index of the committed contact it continues, -1 if new
  double sign = 1.0;                ///< -1 when the centrelines have passed each other (normal kept)
  bool sFree = true, tFree = true;  ///< closest point inside the segment (free projection parameter)
  double weight = 1.0;              ///< point-to-point weight of the ABC blending [-]
  /// Closest points on the smooth (C1) centrelines (SmoothCentreline.hpp): s, t above are its
  /// parameters (a little outside [0, 1] near an interior node), forces go to its stencil nodes.
  CentrelineDistance curve;
};

/// A Gauss point of the line-to-line (Gauss-point-to-segment) part at the current (trial) state: a point
/// of a slave element of line A and its orthogonal projection on a master element of line B.
struct LineSample {
  int lineA = 0, lineB = 0;
  int elementA = 0, elementB = 0;
  double xi = 0.0, t = 0.0;       ///< parameters on the slave and master element [-]
  Vec3 normal;                    ///< unit normal from B to A (closest-point direction)
  double gap = 0.0;               ///< surface gap [m] (< 0 in contact)
  double gapRate = 0.0;           ///< [m/s]
  double length = 0.0;            ///< integration weight: Gauss weight x Jacobian x (1 - ptp weight) [m]
  double lineForce = 0.0;         ///< normal force per unit length [N/m] (spring + dashpot, >= 0)
  double slope = 0.0;             ///< d lineForce / d penetration [N/m^2]
  double damping = 0.0;           ///< dashpot per unit length [N s/m^2]
  double arcA = 0.0, arcB = 0.0;  ///< [m]
};

/// Elastic-stick friction state of the contact of one slave element with one master line.
struct FrictionAnchor {
  double arcA = 0.0, arcB = 0.0;  ///< material points on A and B it refers to [m]
  Vec3 offset = Vec3::Zero();     ///< x_A(arcA) - x_B(arcB) - elastic tangential offset, at commit [m]
};

/// Line-to-line friction of one slave element with one master line at the trial state.
struct FrictionPatch {
  int lineA = 0, lineB = 0, elementA = 0;
  double length = 0.0;      ///< contact length [m]
  double normalLoad = 0.0;  ///< mean normal force per unit length [N/m]
  Vec3 normal = Vec3::UnitZ();
  Vec3 force = Vec3::Zero();  ///< total friction force on A [N]
  bool slipping = false;
  bool point = false;    ///< the friction of a point contact (statics), not of a line-to-line patch
  int elementB = -1;     ///< a point contact's element of line B (its anchor's key with elementA)
  FrictionAnchor trial;  ///< anchor after the return map (committed by commitIncrement/commitStep)
  int nodeA[2] = {0, 0}, nodeB[2] = {0, 0};
  double wA = 0.0, wB = 0.0;    ///< parameters of the anchor points on their elements
  Vec3 elastic = Vec3::Zero();  ///< trial tangential offset delta_t [m]
};

/// A contact followed through time (committed data).
struct TrackedContact {
  int lineA = 0, lineB = 0;
  double arcA = 0.0, arcB = 0.0;      ///< last arc lengths [m]
  double startTime = 0.0;             ///< [s]
  double impactVelocity = 0.0;        ///< relative normal approach speed at first contact [m/s] (>= 0)
  double impulse = 0.0;               ///< integral of the normal force over time so far [N s]
  double pairMass = 0.0;              ///< effective pair mass used by the dashpot [kg]
  double firstPairMass = 0.0;         ///< the lumped pair mass at first contact [kg]
  double peakForce = 0.0;             ///< [N]
  double lastForce = 0.0;             ///< force at the last committed state [N]
  double lastGapRate = 0.0;           ///< [m/s]
  Vec3 lastVelocityA = Vec3::Zero();  ///< velocity of the contact point on A at the last commit [m/s]
  Vec3 lastVelocityB = Vec3::Zero();
  Vec3 startVelocityA = Vec3::Zero();  ///< velocity of the point on A at impact [m/s]
  Vec3 startVelocityB = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();  ///< normal at impact
  double lumpedMassA = 0.0, lumpedMassB = 0.0;
  std::vector<std::array<double, 3>> path;  ///< (time, arcA, arcB) samples along the event
  double minGap = 0.0;                      ///< deepest penetration (most negative gap) [m]
  double jumpImpulse = 0.0;                 ///< impulse of the impulse-model velocity jump [N s]
};

/// The contact model, as a load contributor of the assembler.
class LineContact final : public solver::LoadContributor {
 public:
  /// @param timeStep nominal time step [s] (sets the broad-phase margin)
  LineContact(const model::Model& model, const model::ContactSpec& spec, double timeStep);

  void addForces(const model::State& state, const solver::AssemblyRequest& request, VecX& force,
                 solver::SystemMatrix* matrix) override;
  void beginStep() override;
  /// Parts of the model away from every candidate pair leave contact out: it marks the nodes of the
  /// candidate elements and of their neighbours (the smooth centreline's stencils reach one node further).
  /// The candidates are this step's (found at its first, whole, assembly), and no contact arises outside
  /// them within the step.
  bool supportsParts() const override { return true; }
  bool markLoadedNodes(std::vector<char>& mark) const override;
  bool coupledInParts() const override { return true; }
  bool updateActiveSet() override;
  double limitIncrement(const model::State& state, const VecX& fullIncrement) override;
  std::string rejectState(const model::State& state) override;
  void commitIncrement(const model::State& state) override;
  solver::LoadSource source() const override { return solver::LoadSource::Contact; }
  void beginStatic(const model::State& state) override {
    if (m_distributed) {
      m_distributed->beginStep();
      m_distributed->clearCommitted();
    }
    m_reference = state.position;
    m_pendingAnchors.clear();
    m_pendingPointAnchors.clear();
  }

  /// Whether a converged static increment (commitIncrement) has carried a contact force since
  /// clearTouched(): a static path that engaged contact, where Simulation tries dynamic relaxation first
  /// when the path stalls (contact switches and slides make the path non-smooth; the damped dynamics
  /// follow the physics through them).
  bool touched() const { return m_touched; }
  void clearTouched() { m_touched = false; }

  /// Gauss points of the line-to-line part at the last addForces() call.
  const std::vector<LineSample>& lineSamples() const { return m_samples; }
  /// Line-to-line friction patches at the last addForces() call.
  const std::vector<FrictionPatch>& frictionPatches() const { return m_patches; }
  /// Whether element eA (of its line) and eB may touch (not excluded by a pair, a zone or a shared
  /// connection point).
  bool elementPairAllowed(int eA, int eB) const { return m_search.elementPairAllowed(eA, eB); }
  /// Total contact force on line A from line B [N] at the last assembly, summed over all parts (either
  /// order of the lines: pairForce(b, a) = -pairForce(a, b)).
  Vec3 pairForce(int lineA, int lineB) const;

  /// Contact points of the active set at the last addForces() call (the trial state). During Newton
  /// iterations an active point may pull (normalForce < 0); at a converged state none does.
  const std::vector<ContactPoint>& contacts() const { return m_trial; }
  /// Contacts followed through time (committed).
  const std::vector<TrackedContact>& tracked() const { return m_tracked; }
  /// Finished events (and, after finish(), the open ones): ContactEvents.hpp gives the rule.
  const std::vector<ContactEvent>& events() const { return m_eventTracker.events(); }
  /// Events still open.
  const std::vector<ContactEvent>& openEvents() const { return m_eventTracker.openEvents(); }
  /// Contact patches per line pair at the last commit (total force, peak force per unit length, extent).
  const std::vector<ContactPatch>& patches() const { return m_eventTracker.patches(); }
  /// Smallest surface gap [m] between lines A and B over arc ranges [a0, a1] on A and [b0, b1] on B
  /// (polyline; +inf if no element of either range).
  double gapBetween(const model::State& state, int lineA, int lineB, double a0, double a1, double b0,
                    double b1) const;

  /// Largest step [s] from this state so that no approaching pair closes by more than a fifth of its
  /// contact radii (no tunnelling) and every active impact is resolved in at least 40 steps (kImpactSteps).
  /// Pairs that cannot close to touching within twice `step` are not measured (beyondReach).
  double limitStep(const model::State& state, double step) override;
  /// 1.25 with the distributed formulation while a pair presses or is within the smaller contact radius of
  /// touching (the last limitStep), else the default 2. Its contacts switch the step limit on and off every
  /// few steps as a line rattles on another; steps that doubled after each release and were cut eightfold
  /// at the next touch made generalized-alpha gain energy (a 40-bar wire resting on a taut wire, e = 0.5:
  /// 3.8 kJ of mechanical energy grew to 0.8 MJ within 1.3 s, contact forces doing no net work; a product
  /// of stable one-step maps of different steps need not be stable), and the paper's free fall at e = 0.5
  /// rebounded 2.5 % low with the step doubling as the body left. At 1.25 both are right (DrapeDynamicsTest,
  /// FreeFallRestitutionTest). Apart, the step grows back twofold: held at 1.25 everywhere, steps cut to land
  /// on output times never got back to the nominal one. The point formulation's validation was done at 2.
  double maxStepGrowth() const override { return m_distributed && m_engaged ? 1.25 : 2.0; }
  /// Empty unless the step from `before` to `after` let a pair pass through each other (the normal of a
  /// pair flipped while its closest points stayed inside both segments) or penetrate deeper than half the
  /// contact radii: then the reason (which two lines, where in arc length and position, how deep, and what
  /// the user can change), and the step must be cut.
  std::string rejectStep(const model::State& before, const model::State& after) override;
  bool rejectsSteps() const override { return true; }
  /// The distributed formulation's barrier needs its step filter in dynamics too (limitIncrement), except
  /// while no pair is a candidate: the filter then has no sample and no pair to test (it would return 1),
  /// and the correction need not be spread over the full DOFs for it (0.2 G instructions of the 130 s before
  /// drilling-riser-drift's impact).
  bool limitsDynamicIncrements() const override {
    return m_distributed != nullptr && !(m_lastDynamic && m_search.candidates().empty());
  }
  /// The distributed formulation (contact.formulation: distributed), or null for the point formulation.
  const DistributedContact* distributed() const { return m_distributed.get(); }
  /// Commits the contacts of the accepted state `state` reached with step dt: updates impulses, Eq. 5
  /// effective masses, events. After every accepted step, and once for the static solution with dt = 0.
  /// With the impulse model, new impacts change the velocities of `state` (momentum-conserving jump).
  void commitStep(model::State& state, double dt) override;
  /// Closes the open events at the end of the run (time [s]).
  void finish(double time) override;
  /// Elements have parted (model::PartedElements, lines[].failure): the smooth centrelines next to them end
  /// there from now on, and nothing found before is reused.
  void elementsParted() {
    if (m_distributed) m_distributed->refreshCurves();
  }

  /// The point formulation's contact stiffness between two lines [N/m] (user value or automatic,
  /// 0.1 EA / L of the softer line's shortest element).
  double stiffness(int lineA, int lineB) const;
  /// The contact stiffness k of the formulation in use between two lines [N/m]: the point formulation's
  /// spring (stiffness), or the distributed law's point stiffness (DistributedContact::pointStiffness: a
  /// crossing's dF/dp at the penetration D^2 / (8 (rA + rB)), mesh-free). What contact/summary.json reports.
  double pairStiffness(int lineA, int lineB) const;
  /// Damping ratio of the dashpot [-] for the requested restitution.
  double dampingRatio() const { return m_zeta; }
  /// Whether two lines may touch.
  bool pairAllowed(int lineA, int lineB) const { return m_search.pairAllowed(lineA, lineB); }
  /// Every pair of lines that may touch, as (a, b) with a <= b (a == b: self-contact), in index order.
  std::vector<std::array<int, 2>> allowedPairs() const { return m_search.allowedPairs(); }
  /// How many pairs allowedPairs() would give (ContactCandidates::allowedPairCount).
  std::size_t allowedPairCount() const { return m_search.allowedPairCount(); }
  /// Most line pairs the clearance envelope and the clash report assess one by one: with more allowed
  /// pairs (a model of hundreds of lines with every pair allowed) they assess the pairs that come near.
  static constexpr std::size_t kAssessedPairLimit = 2000;
  /// The line pairs the clearance envelope and the clash report assess at `state` (the static
  /// equilibrium): every allowed pair up to kAssessedPairLimit of them, otherwise the allowed pairs within
  /// the contact's clearance margin of each other (ContactCandidates::nearLinePairs).
  std::vector<std::array<int, 2>> assessedPairs(const model::State& state) const {
    return allowedPairCount() <= kAssessedPairLimit ? allowedPairs()
                                                    : m_search.nearLinePairs(state, m_spec.clearanceMargin);
  }
  /// Minimum clearance between two lines at a state: (clearance [m], arcA [m], arcB [m]). The clearance is
  /// the gap between the surfaces (negative in contact; beams near contact on their smooth centrelines, and
  /// the radius tapered at a change of section, as contact measures them: RadiusProfile); +inf when farther
  /// than the clearance margin.
  std::array<double, 3> clearance(const model::State& state, int lineA, int lineB) const;
  /// clearance() of each pair at one state (the clash report at each output time), the same values as pair
  /// by pair: each line's boxes for the culling made once for all its pairs.
  std::vector<std::array<double, 3>> clearances(const model::State& state,
                                                const std::vector<std::array<int, 2>>& pairs) const;
  const model::ContactSpec& spec() const { return m_spec; }

 private:
  /// A line's elements in blocks of kClearanceBlock, and the blocks in groups of kClearanceBlock: their
  /// bounding boxes and largest contact radii [m] (clearance()'s culling: a group of B beyond the threshold
  /// from a block of A leaves out its blocks at once, a block of A with every block of B beyond it its
  /// elements).
  static constexpr int kClearanceBlock = 8;
  struct ClearanceBlocks {
    std::vector<Vec3> lo, hi;
    std::vector<double> radius;
    std::vector<Vec3> groupLo, groupHi;
    std::vector<double> groupRadius;
    /// Each element's piece of the smooth centreline: how far it lies off its chord at most [m]
    /// (chordDeviationBound; 0 on a chord), and the largest of the line.
    std::vector<double> deviation;
    double largestDeviation = 0.0;
  };
  ClearanceBlocks clearanceBlocks(const model::State& state, int line) const;
  std::array<double, 3> clearance(const model::State& state, int lineA, int lineB, const ClearanceBlocks& blocksA,
                                  const ClearanceBlocks& blocksB) const;
  /// Fills the mesh-free estimate of the impact `e` opening at `state` (ContactEvent::continuum*;
  /// ImpactContinuum.cpp).
  void estimateContinuum(const model::State& state, ContactEvent& e) const;
  /// Finds the contact points at `state`; `trial` (Newton iterations) lets new contacts join the active set.
  void findContacts(const model::State& state, bool dynamic, bool refreshBroadPhase, bool trial);
  /// Broad-phase margin [m] at a state: the largest radius plus what a node can move in 4 nominal steps.
  double broadPhaseMargin(const model::State& state, bool dynamic) const;
  /// Whether two elements' curves cannot close to touching within 2 `step` [s] (limitStep), from their
  /// chords' gap `chordGap` [m] (the chords' distance less the radii) and bounds of the curves' straying and
  /// speeds; false where they may come within `engaged` [m] (the smaller radius) or the curves are not kept.
  bool beyondReach(const model::State& state, int elementA, int elementB, double chordGap, double engaged,
                   double step) const;
  /// Rebuilds the proxies and the candidate pairs with the current margin.
  void refreshCandidates(const model::State& state) { m_search.refresh(state, m_margin); }
  void applyImpulse(model::State& state, const ContactPoint& c, double impulse) const;
  double lumpedMass(int element, double w) const;
  /// Structural mass of an element [kg] (+inf when both its nodes are held).
  double elementMass(int element) const;
  /// Element pairs (A, B) that are the same or adjacent along both lines.
  bool neighbours(const std::pair<int, int>& a, const std::pair<int, int>& b) const;
  /// Where a contact of the active set (or a released one) was: its closest points on both lines [m].
  struct ActiveMark {
    Vec3 pointA = Vec3::Zero(), pointB = Vec3::Zero();
  };
  using ActiveSet = std::map<std::pair<int, int>, ActiveMark>;
  /// Whether an element pair of `set` is a neighbour of `key` along both lines.
  bool inNeighbourhood(const std::pair<int, int>& key, const ActiveSet& set) const;
  /// Whether `set` holds the same physical contact as the point pA, pB of element pair `key`: a neighbour
  /// along both lines (the point slides from pair to pair across nodes) whose points are within half the
  /// radii sum `radii` [m] on both lines. Two distinct minima on neighbouring pairs (the two legs of a
  /// cable folded over a wire) are different contacts: releasing one that pulls must not release the
  /// other, nor make the other pull.
  bool sameContact(const std::pair<int, int>& key, const Vec3& pA, const Vec3& pB, double radii,
                   const ActiveSet& set) const;
  /// The same test against one member of a set.
  bool sameContact(const std::pair<int, int>& key, const Vec3& pA, const Vec3& pB, double radii,
                   const ActiveSet::value_type& member) const;
  double nodeTransverseMass(int node) const;
  /// A per-DOF field (velocity [m/s], acceleration [m/s^2]) at parameter w of an element (linear).
  Vec3 pointValue(const VecX& field, int element, double w) const;
  /// The same field at a smooth-centreline point, and the point's instantaneous effective mass [kg]
  /// (1/m = sum N_k^2 / M_k for lumped node masses M_k).
  Vec3 stencilValue(const VecX& field, const CentrelineStencil& stencil) const;
  double stencilMass(const CentrelineStencil& stencil) const;
  /// Arc length [m] of the point at parameter w of an element of a line.
  double arcOf(int line, int element, double w) const;
  /// Element and parameter of the point at arc length `arc` of a line (clamped to the line).
  std::pair<int, double> pointAtArc(int line, double arc) const;
  /// Line-to-line part: Gauss points on the contact intervals, forces and tangent (LineToLine.cpp).
  void findLineSamples(const model::State& state, bool dynamic);
  void addLineToLineForces(const model::State& state, const solver::AssemblyRequest& request, VecX& force,
                           solver::SystemMatrix* matrix);
  /// Elastic-stick / slip friction of the line-to-line patches (ContactFriction.cpp).
  void addFriction(const model::State& state, const solver::AssemblyRequest& request, VecX& force,
                   solver::SystemMatrix* matrix);
  void commitFriction();
  /// Statics: elastic stick and slip of every point contact (ContactFriction.cpp), appended to m_patches.
  void addPointFriction(const model::State& state, const solver::AssemblyRequest& request, VecX& force,
                        solver::SystemMatrix* matrix);
  /// The stick / slip force of one patch with key `key`, anchored at arc lengths arcA, arcB at first
  /// touch: stick spring kt [N/m per unit patch length], slip limit [N per unit length]; fills `patch`
  /// and adds its force (and tangent) to the nodes.
  void stickSlip(const model::State& state, const solver::AssemblyRequest& request,
                 const std::pair<int, int>& key, double arcA, double arcB, double kt, double limit,
                 const std::map<std::pair<int, int>, FrictionAnchor>& anchors,
                 std::map<std::pair<int, int>, FrictionAnchor>& pending, FrictionPatch& patch, VecX& force,
                 solver::SystemMatrix* matrix) const;
  /// Whether elements A and B passed through each other between two states, from their closest points
  /// before and after (StaticContact.cpp).
  bool passedThrough(int elementA, int elementB, const geometry::SegmentDistanceResult& before,
                     const geometry::SegmentDistanceResult& after) const;
  /// Line-to-line stiffness per unit length [N/m^2] and dashpot [N s/m^2] of two elements.
  double lineStiffness(int eA, int eB) const;
  double lineDamping(int eA, int eB) const;

  const model::Model* m_model;
  model::ContactSpec m_spec;
  double m_timeStep;
  double m_zeta;
  std::vector<double> m_lineStiffness;  // automatic stiffness per line [N/m]
  std::vector<double>
      m_lineMassWithAdded;       // structural + attachment + normal added mass per line, +inf if held [kg]
  std::vector<double> m_radius;  // contact radius per element [m]
  /// The radius along the lines, tapered at a change of section (the clearances measure the surfaces the
  /// distributed contact does).
  RadiusProfile m_profile;
  ContactCandidates m_search;    // which element pairs may touch and are close
  double m_candidateTime = std::numeric_limits<double>::quiet_NaN();
  double m_margin = 0.0;
  bool m_engaged = false;  // distributed: a pair presses or nearly touches (limitStep; maxStepGrowth)
  std::vector<ContactPoint> m_trial;
  ActiveSet m_sticky;    // element pairs active in this step's iterations
  ActiveSet m_released;  // element pairs released in this step (they pulled)
  int m_releaseRounds = 0;
  std::vector<TrackedContact> m_tracked;
  ContactEventTracker m_eventTracker;
  double m_time = 0.0;
  std::vector<LineSample> m_samples;
  std::vector<FrictionPatch> m_patches;
  std::map<std::pair<int, int>, FrictionAnchor>
      m_anchors;  // (slave element, master line) -> committed anchor
  std::map<std::pair<int, int>, FrictionAnchor>
      m_pendingAnchors;  // anchors of patches new in this step / solve
  std::map<std::pair<int, int>, FrictionAnchor> m_pointAnchors;         // point contacts (statics), committed
  std::map<std::pair<int, int>, FrictionAnchor> m_pendingPointAnchors;  // and new in this solve
  /// Positions at the last committed state (statics: its start or last converged increment; dynamics: the
  /// last accepted step). Contact normals point to the side the lines were on there (findContacts).
  std::vector<Vec3> m_reference;
  bool m_debug = false;  // TANGLE_DEBUG_CONTACT set: print the contact search on stderr
  /// Per (lineA, lineB): the elements of the nearest chord pair at the last clearance() call (a first
  /// bound that culls most pairs; a cache, not part of the result).
  mutable std::map<std::pair<int, int>, std::pair<int, int>> m_clearanceHint;
  mutable std::vector<char> m_clearanceFar;  ///< clearance()'s marks of B's blocks (work space)
  /// The element curves clearance() measures beams on with the point formulation (made on first use; the
  /// distributed formulation's own otherwise: curves()).
  mutable std::vector<ElementCurve> m_clearanceCurves;
  std::unique_ptr<DistributedContact> m_distributed;  // contact.formulation: distributed
  bool m_lastDynamic = false;                         // the last assembly was a dynamic one
  bool m_touched = false;                             // touched()
  std::vector<Vec3> m_move;                           // limitIncrement's nodal moves [m] (work space)
  /// The distributed formulation's element curves (DistributedContact::curves) for centrelineDistance, or
  /// null (the point formulation: cables on their chords, the curves made per call).
  const std::vector<ElementCurve>* curves() const {
    return m_distributed ? &m_distributed->curves() : nullptr;
  }
  /// The distributed formulation's parts of addForces, commitStep and limitStep.
  void addDistributedForces(const model::State& state, const solver::AssemblyRequest& request, VecX& force,
                            solver::SystemMatrix* matrix);
  void commitDistributed(const model::State& state, double dt);
};

}  // namespace tangle::contact
