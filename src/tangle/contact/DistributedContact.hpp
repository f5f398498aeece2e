#pragma once
/// @file DistributedContact.hpp
/// The distributed formulation of line-to-line contact (`contact.formulation: distributed`): one code path
/// for crossings, folds, wraps, kinks and parallel contact alike.
///
/// Geometry: every line, cable or beam, is measured on its C1 centreline (SmoothCentreline.hpp, a
/// non-uniform Catmull-Rom curve through the nodes). A fold of a cable at a node is then a tight but smooth
/// bend, and the distance from any point to a line is a C1 function of the positions: no corner acts like
/// a sphere, no closest point hops from element to element, and no fold rule is needed.
///
/// Integration (Gauss-point-to-curve, Meier, Popp & Wall 2016 without the point-to-point blending of
/// Meier, Wall & Popp 2017): for each element of line A near line B, the interval of the element where its
/// centreline is closer to B's centreline than the sum of the radii is found (the minimum of the distance,
/// then the two roots of gap(xi) = 0 on either side by bracketed Newton steps); 4 Gauss points on each piece
/// of that interval between the points where the integrand is not smooth (where the penetration passes
/// the law's p0 and p1) carry the penalty law f(p) per unit length along the
/// closest-point normal to B.
/// The same is done with the roles of A and B exchanged, and each pass gets a share of the weight (a
/// symmetric, unbiased formulation: at a crossing the two passes give the same integral, on parallel lines
/// each integrates the same pressure). The share is half, except where one line is bent on the contact's
/// scale (a fold or a wrap: radius of curvature below twice the contact distance, kappa R >= 1/2) and the
/// other is not: a point of the straight line inside the fold has a nearest point on each leg, and the
/// nearest one changes from leg to leg within an iteration (a force jump: measured 105 N of 5 kN on a wire
/// folded over another), so that pass gets nothing and the pass along the bent line all. Between
/// (1/4 <= kappa R <= 1/2) the shares move continuously: 1/2 + (b_slave - b_master) / 2 with b the
/// bentness (a smoothstep of kappa R), so a share never jumps from step to step as a bend tightens (a jump
/// 0.5 -> 1 pumped a wire folding over another at the minimum step until it passed the barrier's cap). The
/// bentness is taken at the Gauss point and at its projection on the other line (bentnessAt: continuous
/// along each line), so the two passes' shares at one point of contact sum to one; the elements' bentness
/// is decided at their first use in a step or load increment and held through its iterations (beginStep),
/// so Newton sees a smooth force.
/// Coverage (coverUnseen): the pass along a fold samples a cubic that runs fast round the fold, and can miss
/// a narrow dip the other pass sees (RandomSweepTest, seed 67: its samples 4.3 mm and 176 mm either side of a
/// 7.5 mm dip; the wires sank into each other over 20 steps with 40 N between them, then 64 kN pushed them
/// apart and the kinetic energy rose 5 %). So what the bentness took from a pass (d = 1 - 2 s of it, s < 1/2)
/// comes back to it for the part the other pass does not see: s -> s + (1 - s) d (1 - c), c = min(1, F_rev /
/// F_own) with F a pass's integral of the law's force, without the shares, over its samples on the same two
/// elements (+-1). Where the favoured pass sees as much as this one, nothing changes; where it sees less, the
/// pair carries this pass's integral (with s = 0, F_rev + (F_own - F_rev)): the larger of the two. Shares of
/// 1/2 (no line bent) are left as they are: a crossing on a change of section that one pass sees mm before
/// the other keeps a continuous force (giving any unseen pass the whole weight there made it fall 25.8 ->
/// 13.2 kN as the other pass came in). The tangent leaves out dc/du (c < 1 only where the passes disagree).
/// The interval's ends need no
/// linearisation: the regularised law and its slope vanish there (Leibniz's rule leaves no boundary term). At
/// a crossing the integral of the penetration over the short interval gives a force that grows like p^(3/2)
/// (a Hertz-like law); at a fold, a wrap or along a length it is the pressure integrated over the contact
/// length.
///
/// Law: BarrierPenalty (ContactLaw.hpp): regularised at first touch, linear with the stiffness per unit
/// length k_line, and a barrier that grows without bound at half the radii, so the penetration is bounded by
/// construction; Newton increments, and each step's predictor, are filtered (limitIncrement) so no iterate
/// jumps past the barrier.
/// Restitution (dynamics; finishSamples): hysteresis, the law's force scaled by psi(dp/dt) = 1 + a tanh(v /
/// v_s) (HystereticRestitution, ContactLaw.hpp), loading along (1 + a) f, unloading along (1 - a) f, so an
/// impact rebounds at e v0 whatever the law's shape and the forces stay below 2 f at any restitution; v_s
/// per pair of elements (restitutionSpeed), widened by the sliding speed and by the change of rate within
/// a step (finishSamples, docs/theory.md 9.11).
///
/// Friction: elastic stick then Coulomb slip at every Gauss point, in statics and dynamics alike, on the
/// slip u_t: the slip committed at the last converged state (per pair of lines, by arc length along the
/// line integrated along) plus the tangential displacement of the two material points since then. The
/// force -mu_f f_n phi(|u_t|) u_t / |u_t| rises smoothly (phi(r) = 2 r / u_s - (r / u_s)^2) to mu_f f_n at
/// the slip distance u_s = 2 mu_f f_n / k_line (the stick as stiff as the normal law: slipDistance) and
/// stays there; what is committed is held at
/// u_s (the rest has slid), so stick holds for any time and sliding costs no more than stick. Its
/// consistent (symmetric part of the) tangent is assembled.
///
/// Stiffness per unit length k_line = k / D [N/m^2], D = 2 min(rA, rB) the law's scale (contactScale), with
/// k [N/m] contact.stiffness or, automatic, 0.1 EA_min / (kReferenceLengthFactor (rA + rB)) (the point
/// formulation's 0.1 EA / L with the element length L replaced by a length that does not change with the
/// mesh). Why k / D: at a crossing the penetration p(u) = p - u^2 / (2 (rA + rB)) along the line integrates
/// to F = (4/3) k_line sqrt(2 (rA + rB)) p^(3/2), whose slope dF/dp = 2 k_line sqrt(2 (rA + rB) p) equals k
/// at p = D^2 / (8 (rA + rB)) ((rA + rB) / 8 for equal radii): a crossing is as stiff as a point contact of
/// stiffness k within the linear range of the law; a parallel contact of length L is k L / D stiff.

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "tangle/contact/ContactCandidates.hpp"
#include "tangle/contact/ContactEvents.hpp"
#include "tangle/contact/ContactLaw.hpp"
#include "tangle/contact/RadiusProfile.hpp"
#include "tangle/contact/SmoothCentreline.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/solver/LoadContributor.hpp"

namespace tangle::contact {

/// Reference contact length as a multiple of the sum of the radii [-] (see the file comment).
inline constexpr double kReferenceLengthFactor = 20.0;
/// Damping ratio of the elastic stick in dynamics [-] (critical: finishSamples).
inline constexpr double kStickDampingRatio = 1.0;

/// A Gauss point of the distributed contact at the current (trial) state: a point of line A's centreline
/// (the line integrated along) and its closest point on line B's.
struct ContactSample {
  int lineA = 0, lineB = 0;             ///< line integrated along, line measured against
  int elementA = 0, elementB = 0;       ///< element of the Gauss point; master element of its closest point
  double xi = 0.0, t = 0.0;             ///< parameters on them [-]
  CentrelineDistance curve;             ///< the Gauss point (held) and its projection (stencils, points)
  Vec3 normal = Vec3::UnitZ();          ///< unit normal from B to A
  double gap = 0.0;                     ///< surface gap [m] (< 0: penetration)
  double gapRate = 0.0;                 ///< d gap / dt [m/s] (< 0 approaching)
  double gapAcceleration = 0.0;         ///< n . (a_A - a_B) [m/s^2] (the normal's turning left out)
  double length = 0.0;                  ///< integration weight: share x Gauss weight x rest length [m]
  double share = 0.5;                   ///< this pass's share of the contact [-] (in [0, 1]: file comment)
  double fullLength = 0.0;              ///< Gauss weight x rest length, before the share [m]
  double lineForce = 0.0;               ///< normal force per unit length [N/m] (spring + dashpot, >= 0)
  double slope = 0.0;                   ///< d spring / d penetration [N/m^2]
  double damping = 0.0;                 ///< d lineForce / d (dp/dt) per unit length [N s/m^2] (finishSamples)
  double rateFactor = 1.0;              ///< restitution's factor psi(dp/dt) on the spring [-] (finishSamples)
  double rateSpeed = 0.0;               ///< restitution's smoothing speed v_s [m/s] (0: none; finishSamples)
  double spring = 0.0;                  ///< the law's force per unit length f(p) [N/m]
  double pairMass = 0.0;                ///< lumped pair mass at the two points [kg] (+inf if both are held)
  Vec3 relative = Vec3::Zero();         ///< slip of A against B that friction resists [m] (addSample)
  Vec3 slipRate = Vec3::Zero();         ///< velocity of A's point against B's [m/s] (friction's power)
  Vec3 friction = Vec3::Zero();         ///< friction force per unit length on A [N/m]
  double slipLimit = 0.0;               ///< slip distance u_s at which friction is mu f_n [m] (slipDistance)
  double slipDelay = 0.0;               ///< tau of the stick's dashpot: friction acts on slip + tau rate [s]
  Mat3 frictionTangent = Mat3::Zero();  ///< d friction / d (slip + tau rate), symmetric part [N/m^2]
  double arcA = 0.0, arcB = 0.0;        ///< arc lengths of the two points [m]
  double radii = 0.0;                   ///< sum of the contact radii [m]
  double sine = 1.0;                    ///< |t_A x t_B| of the unit centreline tangents at the two points [-]
  /// The master's radius slope dr_B/dt and curvature d2r_B/dt2 at t [m] (non-zero only in a shoulder where
  /// line B changes section): the gap is d - r_A(xi) - r_B(t) with t the projection, free.
  double radiusSlope = 0.0, radiusCurvature = 0.0;
};

/// The distributed contact (see the file comment). Owned by LineContact, which keeps the candidates, the
/// events and the trial / commit protocol.
class DistributedContact {
 public:
  /// @param radius contact radius per element [m]
  DistributedContact(const model::Model& model, const model::ContactSpec& spec,
                     const std::vector<double>& radius);

  /// Stiffness per unit length between two lines [N/m^2] (file comment).
  double lineStiffness(int lineA, int lineB) const;
  /// The point stiffness k between two lines [N/m]: contact.stiffness or the automatic one (file comment);
  /// a crossing's stiffness at the penetration D^2 / (8 (rA + rB)) (file comment).
  double pointStiffness(int lineA, int lineB) const;
  /// What the constructor stores for pointStiffness, nodeMass and massPerLength.
  double computePointStiffness(int lineA, int lineB) const;
  double computeNodeMass(int node) const;
  double computeMassPerLength(int element) const;
  /// The law between two elements.
  BarrierPenalty law(int elementA, int elementB) const;
  /// a of the restitution by hysteresis [-] (loading along (1 + a) f).
  double hysteresis() const { return m_hysteresis; }
  /// Smoothing speed v_s [m/s] of the restitution between two elements (0: none, both held):
  /// 0.1 omega p0, with omega = sqrt(k / m) of the pair's point stiffness k (pointStiffness) against the
  /// reduced mass m of the reference contact length 20 (rA + rB) (kReferenceLengthFactor), and p0 the law's
  /// regularisation depth: omega p0 is about the speed of an impact that just reaches the linear law. Fixed
  /// per pair of elements: from the patch's own K and M it changed as Gauss points joined a patch, psi with
  /// it where |v| ~ v_s, and Newton cycled at the minimum step (RandomSweepTest, seeds 1-3).
  double restitutionSpeed(int elementA, int elementB) const;
  /// Reduced mass per unit length of two elements' lines at a point [kg/m] (+inf if both are held).
  double pairMassPerLength(int elementA, int elementB) const;

  /// The smooth centrelines again (elements parted: SmoothCentreline's elementCurve ends a line there); the
  /// next findSamples searches afresh.
  void refreshCurves() {
    m_curves = elementCurves(*m_model, true);
    m_found.valid = false;
  }
  /// Every element's C1 centreline data (elementCurves(model, true), kept up to date with parted elements):
  /// for the other searches of the distributed formulation's curves (centrelineDistance's `curves`).
  const std::vector<ElementCurve>& curves() const { return m_curves; }
  /// A step, load increment or retry starts: the passes' shares are decided again at the next findSamples.
  void beginStep() {
    for (const int e : m_bentElements) m_bent[static_cast<std::size_t>(e)] = kNotBent;
    m_bentElements.clear();
    m_found.valid = false;
  }

  /// Finds the Gauss points of every candidate pair at `state`; `reference`: the positions of the last
  /// converged state (statics friction). Dynamic: dashpot and velocity friction.
  void findSamples(const model::State& state, const ContactCandidates& search, bool dynamic, bool relaxation,
                   const std::vector<Vec3>& reference);
  /// The time scale of the step being solved [s]: kf / cf of the assembly (about dt / 2 for the
  /// generalized-alpha method; 0 in statics), for the restitution's smoothing (finishSamples).
  void setStepScale(double seconds) {
    if (seconds != m_stepScale) m_found.valid = false;
    m_stepScale = seconds;
  }
  /// Adds the forces (and tangent) of the samples found by the last findSamples.
  void addForces(const model::State& state, const solver::AssemblyRequest& request, VecX& force,
                 solver::SystemMatrix* matrix) const;
  const std::vector<ContactSample>& samples() const { return m_samples; }

  /// The largest fraction in (0, 1] of the increment `move` (per node [m]) from `state` such that no Gauss
  /// point of the last findSamples (at `state`) closes by more than 80 % of what is left to the barrier's
  /// limit (linearised: the step filter of a barrier method, no iterate jumps past the singularity), and no
  /// pair of `pairs` (indices into the proxies of `search`) passes through or its chords close by more
  /// than a quarter of the radii.
  /// strict (statics): the chord tests are halved until they hold; otherwise (dynamics) a chord test no
  /// fraction down to 1/1024 satisfies is left out.
  double limitIncrement(const model::State& state, const std::vector<Vec3>& move,
                        const ContactCandidates& search, const std::vector<CandidatePair>& pairs,
                        bool strict) const;
  /// Empty, or why the samples' state is not admissible (a Gauss point beyond the barrier's cap).
  std::string rejectSamples() const;
  /// Largest step [s] that resolves every moving contact patch with kImpactSteps steps (its duration from
  /// the patch's stiffness, the barrier's slope included, and its mass, patchMass).
  double impactStepLimit() const;
  /// Duration [s] of an impact of mass `mass` [kg] on a contact of stiffness `stiffness` [N/m]: twice the
  /// loading half (restitution by hysteresis loads at (1 + a) K).
  double impactDuration(double stiffness, double mass) const;
  /// Event spots of the samples at a committed state reached with step dt.
  std::vector<ContactSpot> spots(const model::State& state, double dt, bool dynamic) const;
  /// Total force on line A from line B [N] of the samples, both passes.
  Vec3 pairForce(int lineA, int lineB) const;
  /// Keeps the samples found at a converged state (the last findSamples): their slip for friction from
  /// there on (the elastic stick, at most the slip distance: file comment), and where they touch for
  /// crossedSinceCommit; and the crossings struck hard (impactStepLimit). dt: the step just taken [s] (0 in
  /// statics).
  void commitSamples(double dt = 0.0);
  /// True when a sample pressed at the last commitSamples.
  bool pressing() const { return !m_pairAcceleration.empty(); }
  /// Forgets what was committed (a new analysis).
  void clearCommitted() {
    m_slip.clear();
    m_committed.clear();
    m_found.valid = false;
  }
  /// Empty, or why `state` is not admissible: a point in contact at the last commit whose separation from
  /// the same piece of the other line has reversed (the lines passed through each other there).
  std::string crossedSinceCommit(const model::State& state) const;

 private:
  /// Slip at which friction is fully mobilised at a sample [m]: 2 mu f_n / k_line, so the stick spring is
  /// as stiff as the normal law (a fixed thousandth of the radii made it up to 1e4 times stiffer in an
  /// impact: a wire dropped across another with friction stopped in Newton at the minimum step; the law's
  /// regularisation depth, 1 mm for a 10 cm rod, let a rod bouncing onto an incline creep 5 mm).
  /// Its dependence on f_n is left out of the tangent.
  double slipDistance(const ContactSample& smp) const;
  /// Arc length [m] of the point at parameter w of an element.
  double arcOf(int element, double w) const;
  /// The projection of slave element e's point at xi on master element f, started at t0.
  CentrelineDistance project(const model::State& state, int slave, double xi, int master, double t0) const;
  /// Projected Newton on V(t) = |x - c(t)|^2 / 2 over master element f's parameter t in [0, 1], started at
  /// t0: the parameter of the point of its piece nearest x [-] (project's and projectPoint's).
  double nearestParameter(const model::State& state, const Vec3& x, int master, double t0) const;
  /// What the interval search needs of project (the same numbers, without the stencils' derivative weights:
  /// 89 of a search's 140 projections).
  struct Projection {
    double t = 0.0;                                     ///< master's parameter [-]
    Vec3 pointA = Vec3::Zero(), pointB = Vec3::Zero();  ///< the slave's point and the nearest point [m]
    double distance = 0.0;                              ///< |pointA - pointB| [m]
    Vec3 tangentA = Vec3::Zero();                       ///< dc_A/dxi at xi [m] (with `slope`)
  };
  Projection projectPoint(const model::State& state, int slave, double xi, int master, double t0,
                          bool slope) const;
  /// A contact interval of a slave element's parameter, with the points inside it where the integrand is
  /// not smooth (where the penetration passes the law's p0 and p1).
  struct Interval {
    double lo = 0.0, hi = 0.0;
    std::vector<double> cuts;
    /// Cuts at ridges between two dips, each with its weight in [0, 1] (contactIntervals): the interval is
    /// integrated with and without each, the sums blended by the weights.
    std::vector<std::pair<double, double>> ridges;
  };
  /// The intervals of slave element e whose centreline lies within the radii of master element f's, one
  /// per dip of the gap, in increasing xi; false if none.
  bool contactIntervals(const model::State& state, int slave, int master,
                        std::vector<Interval>& intervals) const;
  /// A candidate pair's pass (findSamples): the slave element, the master's line and element.
  struct PatchVisit {
    int slave, line, master;
  };
  /// findSamples' work space, kept from call to call.
  struct FindWork {
    std::vector<PatchVisit> visits;
    std::vector<int> masters;
    std::vector<Interval> intervals, found, merged;
    std::vector<std::pair<double, double>> ridges;
    std::vector<double> fixedEnds, ends;
  };
  /// chordDeviationBound of an element's piece at the state findSamples is searching [m] (contactIntervals
  /// and addSample, called by findSamples only): computed once per element and search, into m_chordBound,
  /// which findSamples resets (a master element's bound was computed again for every Gauss point before).
  double chordBound(const model::State& state, int element) const;
  /// Contact radius of element e at parameter t of its piece [m]: its own, except in a shoulder where its
  /// line changes section (m_shoulders).
  double radiusAt(int element, double t) const;
  /// The radius and its first two derivatives in the piece's parameter, (r, dr/dt, d2r/dt2) [m].
  std::array<double, 3> radiusProfile(int element, double t) const;
  void addSample(const model::State& state, int slave, double xi, double weight,
                 const std::vector<int>& masters, const std::vector<Vec3>& reference);
  /// Lumped mass of a node [kg] (+inf if it is held).
  double nodeMass(int node) const { return m_nodeMass[static_cast<std::size_t>(node)]; }
  /// Mass per unit length of an element's line [kg/m] (+inf if both its nodes are held).
  double massPerLength(int element) const { return m_massPerLength[static_cast<std::size_t>(element)]; }
  /// The dashpots per contact patch, the normal forces and the friction of the samples just found.
  void finishSamples(bool dashpot);
  /// Instantaneous effective mass of a centreline point with lumped node masses [kg].
  double stencilMass(const CentrelineStencil& stencil) const;
  /// The samples grouped in contact patches: one pair of lines, Gauss points of both passes within four
  /// radii of each other along the lower-index line (indices into m_samples).
  std::vector<std::vector<int>> patches() const;
  /// Mass taking part in a patch's normal motion [kg] (finishSamples).
  double patchMass(const std::vector<int>& patch) const;

  /// The committed slip [m] of line A against line B at arc length arcA of A [m] (commitSlip): linear
  /// between committed points, zero farther than `reach` [m] from all of them.
  Vec3 committedSlip(int lineA, int lineB, double arcA, double reach) const;
  /// Committed slip of a Gauss point of the pass along lineA against lineB.
  struct SlipRecord {
    double arc = 0.0;          ///< arc length of the point on line A [m]
    Vec3 slip = Vec3::Zero();  ///< tangential slip of A against B, |slip| <= u_s [m]
  };
  std::map<std::pair<int, int>, std::vector<SlipRecord>> m_slip;  ///< per (lineA, lineB), by arc
  /// Per pair of lines (lower index first): the largest |relative normal acceleration| of its Gauss points in
  /// contact at the last converged state [m/s^2] (commitSamples; the restitution's smoothing).
  std::map<std::pair<int, int>, double> m_pairAcceleration;
  /// The normal motion of a pair of lines where it presses, from the current samples (impactStepLimit).
  struct PairMotion {
    double stiffness = 0.0;      ///< sum of the Gauss points' slopes x lengths [N/m]
    double mass = 0.0;           ///< lumped pair mass at the deepest point [kg]
    double patchMass = 0.0;      ///< the largest of its patches' masses (patchMass) [kg]
    double speed = 0.0;          ///< largest |d gap / dt| [m/s]
    double slowest = 0.0;        ///< smallest |d gap / dt| [m/s]
    double acceleration = 0.0;   ///< largest |relative normal acceleration| [m/s^2]
    double rateSpeed = 0.0;      ///< largest restitution smoothing speed v_s [m/s]
    double deepest = 0.0;        ///< smallest surface gap [m] (< 0)
    double deepestRate = 0.0;    ///< d gap / dt there [m/s] (< 0 approaching)
    double scale = 0.0;          ///< the law's p0 there [m]
    double lineStiffness = 0.0;  ///< the law's k there [N/m per m]
    double sine = 1.0;           ///< the crossing's sine there [-]
    double radii = 0.0;          ///< sum of the contact radii there [m]
    double limit = 0.0;          ///< the law's pmax there [m]
  };
  /// Of the samples as they are (kept while m_samplesVersion is unchanged: the commit and the next step's
  /// limit ask about the same samples; 0.1 G instructions of drilling-riser-drift's run made twice).
  const std::map<std::pair<int, int>, PairMotion>& pairMotions() const;
  /// Counts the changes of m_samples (findSamples's new search, finishSamples) [-].
  std::uint64_t m_samplesVersion = 0;
  mutable std::uint64_t m_motionsVersion = ~std::uint64_t{0};  ///< the samples' version of m_motions
  mutable std::map<std::pair<int, int>, PairMotion> m_motions;
  /// Whether a pair's approach carries its crossing a further p0 deeper (impactStepLimit).
  bool crossingApproach(const PairMotion& motion) const;
  /// The time a crossing struck now takes to load and unload at e = 1 [s] (impactStepLimit).
  double crossingLoadingTime(const PairMotion& motion) const;
  /// A pair whose crossing was struck (crossingApproach at a commit) stays an impact (commitSamples) until
  /// it lets go, turns to separate, or three times the impact's estimated duration has passed.
  struct StruckCrossing {
    double remaining = 0.0;  ///< time left [s]
    double step = 0.0;       ///< the step that resolves it: its time at e = 1 over kImpactSteps [s]
  };
  std::map<std::pair<int, int>, StruckCrossing> m_struck;
  double m_stepScale = 0.0;  ///< setStepScale [s]
  /// A Gauss point in contact at the last commit: its piece of each line and the normal from B to A.
  struct CommittedContact {
    int elementA = 0, elementB = 0;
    double xi = 0.0, t = 0.0;
    Vec3 normal = Vec3::UnitZ();
  };
  std::vector<CommittedContact> m_committed;

  const model::Model* m_model;
  model::ContactSpec m_spec;
  std::vector<double> m_radius;
  double m_hysteresis;                       // a of HystereticRestitution, from contact.restitution [-]
  std::vector<double> m_lineAxialStiffness;  ///< smallest EA per line [N]
  // Constants of the model, made once by the constructor (every sample asked them again: with their map
  // and element look-ups 0.25 G instructions of drilling-riser-drift's run).
  std::vector<double> m_pointStiffness;  ///< pointStiffness per pair of lines, row-major [N/m]
  std::vector<double> m_nodeMass;        ///< nodeMass per node [kg]
  std::vector<double> m_massPerLength;   ///< massPerLength per element [kg/m]
  std::vector<ContactSample> m_samples;
  /// The Gauss points of the last findSamples that the bentness gave no share (their pass's force integral
  /// counts in coverUnseen; those it gives a share join m_samples).
  std::vector<ContactSample> m_unshared;
  /// Bentness per element, held through a step (beginStep clears it): kNotBent where not asked yet, and the
  /// elements asked (a vector and not a map: three look-ups per Gauss point, 0.1 G instructions of
  /// drilling-riser-drift's run in the map).
  static constexpr double kNotBent = -1.0;
  std::vector<double> m_bent;
  std::vector<int> m_bentElements;
  std::vector<ElementCurve> m_curves;  ///< every element's C1 centreline data (SmoothCentreline.hpp)
  /// The radius along the lines (RadiusProfile.hpp): where a line changes section (a lazy wave's buoyancy:
  /// 0.175 -> 0.45 m) it tapers over |r1 - r2| of arc: without it a Gauss point whose projection crossed the
  /// node saw the sum of the radii, and the gap, jump by the difference, a force step no time step resolves
  /// (two lazy waves relaxing into contact stopped at steps of 1e-5 s). The master's slope dr/dt enters the
  /// gap's gradient, so the force and its tangent are those of the law's potential (addForces).
  RadiusProfile m_profile;
  mutable std::vector<double> m_chordBound;  ///< chordBound per element [m] (NaN: not yet in this search)
  /// What the last findSamples was asked (its samples are kept while nothing else changed): a step's
  /// converged state is sampled by its last assembly, by LineContact::rejectStep and by commitDistributed
  /// alike; searched once, not three times (risers side by side: 2.08 s against 0.30 s wall for point
  /// contact before).
  struct FoundAt {
    bool valid = false;
    bool dynamic = false, relaxation = false;
    std::vector<Vec3> position, reference;
    VecX velocity, acceleration;
    std::vector<CandidatePair> candidates;
  };
  FoundAt m_found;
  FindWork m_work;
  /// How bent an element's C1 piece is on the scale of the contact distance R [m], in [0, 1]: 0 where its
  /// largest kappa R <= 1/4, 1 where >= 1/2 (a fold or a wrap), a smoothstep between.
  double bentness(const model::State& state, int element, double radii) const;
  /// The bentness along a line at parameter w in [0, 1] of an element: linear between its nodes' values,
  /// a node's the larger of its elements' (held through the step: m_bent), so it is continuous along the
  /// line and the two passes' shares at one point of contact sum to one (addSample).
  double bentnessAt(const model::State& state, int element, double w, double radii);
  /// Gives a pass the part of a contact that the pass the bentness favours did not see (file comment):
  /// the share s of a sample that the bentness lowered below 1/2 becomes s + (1 - s) d (1 - c), d = 1 - 2 s
  /// and c = min(1, r), r the reverse pass's force integral over this one's on the same elements (+-1).
  void coverUnseen();
};

}  // namespace tangle::contact
