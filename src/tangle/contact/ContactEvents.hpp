#pragma once
/// @file ContactEvents.hpp
/// Contact events for the clash report: one physical contact between two lines is one event, whether
/// it is a point (a crossing), a length (lines along each other) or both, and however its contact points
/// move from element to element or come and go inside it.
///
/// The rule (docs/theory.md 9.9):
/// - At every committed state the contact spots of a line pair (point contacts and line-to-line Gauss
///   points with a positive force) are grouped into patches: spots closer along line 1 than the reach
///   (two elements plus the sum of the radii) belong to one patch.
/// - A patch continues the open event of the same pair whose extent, grown by the reach, it overlaps on
///   both lines; otherwise it opens a new event.
/// - An open event that no patch continues closes when the surfaces in its extent are apart by more than
///   kSeparationFraction of the sum of the radii (a bounce, a separation), or when it has had no contact
///   force for `contact.event_separation_time`; until then (a resting contact that breathes) it stays
///   open with zero force.
/// - An event is an impact when its first approach speed v0 exceeds `contact.impact_velocity_threshold`
///   in a dynamic run; it is sustained when it lasts longer than kSustainedDurations contact durations
///   pi sqrt(m / k) (or is a static contact). The clash statistics are over impacts only.
/// - Impact energy (docs/theory.md 9.10): where the contact is a point on lines long enough for the
///   impact not to see their ends, the mesh-free estimate from the lines' point impedance
///   (ContinuumImpactMass.hpp: what the impact engages does not depend on the elements); elsewhere the
///   paper's Eq. 5 taken over the impact phase only, from first
///   contact until the relative normal velocity has reversed (the surfaces stop approaching), the event
///   turned sustained, or it ended: m_eq5 = impulse of the phase / change of the relative normal
///   velocity over it, energy 1/2 m_eq5 v0^2. Beside it an independent estimate from energy, the work
///   the contact force did against the relative normal motion over the same phase (the kinetic energy
///   of approach the contact absorbed): equal for two rigid bodies, and a warning when the two differ by
///   more than a factor of 2, or when the mass lies outside [one element of each line, the whole lines
///   with added mass] (reduced pair masses). The paper's Eq. 5 over the whole event stays available
///   (eventEq5Mass), as the paper defines it.

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "tangle/core/Types.hpp"

namespace tangle::contact {

/// Sum of the radii fraction by which the surfaces must part to close an event [-].
inline constexpr double kSeparationFraction = 0.05;
/// Contact durations after which an event counts as sustained [-].
inline constexpr double kSustainedDurations = 10.0;
/// Factor beyond which the Eq. 5 and the work estimates of an impact energy are said to disagree [-].
inline constexpr double kEnergyAgreement = 2.0;

/// One contact spot at a committed state (built by LineContact).
struct ContactSpot {
  int lineA = 0, lineB = 0;
  double arcA = 0.0, arcB = 0.0;    ///< [m]
  Vec3 position = Vec3::Zero();     ///< point on line A's centreline [m]
  Vec3 normal = Vec3::UnitZ();      ///< from B to A
  double force = 0.0;               ///< normal force [N] (a Gauss point: force per length x length)
  /// Friction force on line A [N] (a Gauss point's: per length x length; 0 for the point formulation's
  /// spots): its part along the patch's mean normal takes part in stopping the approach (impact phase).
  Vec3 friction = Vec3::Zero();
  double length = 0.0;              ///< contact length it stands for [m] (0 for a point contact)
  /// Weight of the spot's relative normal velocity in its patch's [N]: the law's elastic force, without the
  /// restitution's rate factor (distributed), which would lean the mean towards the approaching spots; < 0:
  /// the force.
  double velocityWeight = -1.0;
  double forcePerLength = 0.0;      ///< [N/m] (line-to-line Gauss points only)
  double approachSpeed = 0.0;       ///< relative normal speed before the step it touched in [m/s] (>= 0)
  double gap = 0.0;                 ///< [m]
  double pairMass = 0.0;            ///< [kg]: effective mass of a point contact, reduced mass per length x length for a Gauss point
  double stiffness = 0.0;           ///< [N/m] (a Gauss point: per length x length)
  /// A Gauss point's lumped FE pair mass at its two points [kg] and its pair's point stiffness k [N/m]
  /// (docs/theory.md 9.11): the scale of a crossing's contact duration, which the reduced mass and the
  /// stiffness per length (above) do not give (a bar across a light wire carrying a lump: 0.01 kg/m).
  double lumpedPairMass = 0.0, pointStiffness = 0.0;
  double jumpImpulse = 0.0;         ///< velocity-jump impulse of the impulse model applied at this state [N s]
  Vec3 velocityA = Vec3::Zero(), velocityB = Vec3::Zero();  ///< of the contact points [m/s]
  Vec3 velocityBeforeA = Vec3::Zero(), velocityBeforeB = Vec3::Zero();  ///< before an impulse-model jump [m/s]
  double radii = 0.0;               ///< sum of the contact radii [m]
  double minRadius = 0.0;           ///< the smaller contact radius [m]
  double elementLength = 0.0;       ///< the larger element length at the spot [m]
  double elementPairMass = 0.0;     ///< reduced structural mass of the two elements at the spot [kg]
  double linePairMass = 0.0;        ///< reduced mass of the two whole lines, added mass included [kg]
};

/// A contact event (open or closed).
struct ContactEvent {
  int lineA = 0, lineB = 0;
  double startTime = 0.0, endTime = 0.0;  ///< [s]
  double arcAStart = 0.0, arcBStart = 0.0;  ///< where it began along each line (force centroid) [m]
  Vec3 positionStart = Vec3::Zero();      ///< where it began, on line 1 (force centroid) [m]
  double arcAMin = 0.0, arcAMax = 0.0, arcBMin = 0.0, arcBMax = 0.0;  ///< extent over the event [m]
  std::vector<std::array<double, 3>> path;  ///< (time, arcA, arcB) force centroids along the event
  double peakForce = 0.0;  ///< largest total normal force of the patch over the event, on the mesh [N]
  double peakForcePerLength = 0.0; ///< largest line-to-line force per unit length [N/m]
  double maxContactLength = 0.0;   ///< longest contact length [m]
  /// The impact's peak force [N] on the impact energy's basis (energyMassBasis): the continuum estimate's
  /// (continuumPeakForce) where the energy is the continuum's, else the mesh's over the impact phase
  /// (phasePeakForce); 0 for an event that is not an impact; NaN for an impact the impulse model resolved
  /// by a velocity jump on the mesh's basis (no force: the jump is the impact). The peak force that goes
  /// with the impact energy: on a mesh coarser than the length of line an impact engages, the simulated
  /// force is that of the element's lumped mass on the contact law, as the mesh energy is (docs/theory.md
  /// 9.10).
  double impactPeakForce = 0.0;
  double phasePeakForce = 0.0;     ///< largest total normal force over the impact phase, on the mesh [N]
  /// The mesh's impact peak force [N]: phasePeakForce for an impact, 0 for an event that is not one, NaN
  /// where the impulse model's velocity jump acted in the phase (events.csv's mesh_impact_peak_force_N).
  double meshImpactPeakForce = 0.0;
  bool phaseJumped = false;        ///< the impulse model's velocity jump acted within the impact phase
  double impulse = 0.0;            ///< integral of the total force over time [N s]
  double impactVelocity = 0.0;     ///< relative normal approach speed at first contact [m/s]
  double impactEnergy = 0.0;       ///< 1/2 energyMass impactVelocity^2 [J]
  double energyMass = 0.0;         ///< mass used for the impact energy [kg]
  /// "continuum" (the lines' point impedance, where it holds: continuumNote empty), else the mesh's:
  /// "eq5" (impact phase), "work" (2 W / v0^2 where the phase changed the velocity by less than 5 % of
  /// v0), "lumped" (FE pair mass at the point: no work either).
  std::string energyMassBasis;
  /// What the simulated impact engaged on its mesh (basis meshMassBasis: eq5, work or lumped) [kg] and the
  /// energy 1/2 meshMass v0^2 [J]: the impact energy where the continuum estimate does not hold.
  double meshMass = 0.0, meshEnergy = 0.0;
  std::string meshMassBasis;
  // The mesh-free estimate (ContinuumImpactMass.hpp, docs/theory.md 9.10), from the state at first contact.
  double continuumMass = 0.0;       ///< reduced participating mass of the pair [kg] (NaN: none)
  double continuumEnergy = 0.0;     ///< 1/2 continuumMass v0^2 [J] (NaN: none)
  double continuumLengthA = 0.0;    ///< length of line A whose mass takes part [m] (NaN: none)
  double continuumLengthB = 0.0;    ///< [m]
  double continuumDuration = 0.0;   ///< the impact's half period pi / omega [s]
  double continuumPeakForce = 0.0;  ///< peak force of the estimate [N]
  /// Empty where the estimate holds (the impact energy is then the continuum's), else why it does not (a
  /// slack line, a contact along a length, waves that reach an end, support, lump or section change).
  std::string continuumNote;
  // Impact phase (see the file comment).
  double phaseEndTime = 0.0;         ///< end of the impact phase [s]
  std::string phaseEnd;              ///< "reversed", "separated", "sustained", "run end", or "no approach" (no impact phase)
  double phaseImpulse = 0.0;         ///< impulse of the contact force over the phase [N s]
  double phaseVelocityChange = 0.0;  ///< change of the relative normal velocity over the phase [m/s]
  double phaseWork = 0.0;            ///< work of the contact force against the relative normal motion [J]
  double eq5Mass = 0.0;              ///< phaseImpulse / phaseVelocityChange [kg] (NaN if not measurable)
  double workMass = 0.0;             ///< 2 phaseWork / v0^2 [kg] (NaN without approach speed)
  double eventEq5Mass = 0.0;         ///< the paper's Eq. 5 over the whole event [kg]
  double massLowerBound = 0.0;       ///< reduced pair mass of one element of each line at the start [kg]
  double massUpperBound = 0.0;       ///< reduced pair mass of the two whole lines with added mass; +inf if either is held [kg]
  std::string energyWarning;         ///< empty, or why the impact energy is doubtful (file comment)
  double effectiveMassA = 0.0;     ///< Eq. 5: impulse / normal velocity change of line A at the point [kg] (NaN unless an impact)
  double effectiveMassB = 0.0;     ///< Eq. 5 for line B [kg]
  double lumpedMassA = 0.0, lumpedMassB = 0.0;  ///< (unused for line contacts) [kg]
  double maxPenetration = 0.0;     ///< [m]
  bool impact = false;             ///< started with a dynamically significant approach speed
  bool sustained = false;          ///< lasted more than kSustainedDurations contact durations, or static
  bool open = false;               ///< still open at the end of the run
  /// "impact", "impact then sustained" or "sustained".
  std::string kind() const;

  // Tracking data (not reported).
  double pairMass = 0.0;           ///< pair mass at the start [kg]
  double stiffness = 0.0;          ///< [N/m]
  /// Contact duration scale pi sqrt(M / K) at the start [s]: after kSustainedDurations of it an event is
  /// sustained. A point contact's pair mass against its stiffness; a distributed patch's the longer of its
  /// reduced line mass against its stiffness per length (parallel contact) and its strongest Gauss
  /// point's lumped pair mass against the point stiffness (a crossing); 0: none.
  double duration = 0.0;
  double radii = 0.0, minRadius = 0.0, reach = 0.0;  ///< [m]
  double lastAMin = 0.0, lastAMax = 0.0, lastBMin = 0.0, lastBMax = 0.0;  ///< extent at the last contact [m]
  double lastForce = 0.0;          ///< [N]
  double lastPhaseForce = 0.0;     ///< normal force plus friction along the mean normal [N] (impact phase)
  double lastContactTime = 0.0;    ///< last time with contact force [s]
  Vec3 normalStart = Vec3::UnitZ();
  Vec3 startVelocityA = Vec3::Zero(), startVelocityB = Vec3::Zero();
  Vec3 lastVelocityA = Vec3::Zero(), lastVelocityB = Vec3::Zero();
  bool pointStart = true;          ///< the strongest spot at the start was a point contact
  double jumpImpulse = 0.0;        ///< [N s]
  bool phaseOpen = true;           ///< the impact phase has not ended
  double lastPower = 0.0;          ///< contact force x closing speed at the last commit [W]
  double lastRelativeVelocity = 0.0;  ///< force-weighted relative normal velocity at the last commit [m/s]
};

/// One patch of a line pair at a committed state (for the force histories).
struct ContactPatch {
  int lineA = 0, lineB = 0;
  double force = 0.0;              ///< total normal force [N]
  double peakForcePerLength = 0.0; ///< [N/m]
  double length = 0.0;             ///< contact length [m]
  double arcA = 0.0, arcB = 0.0;   ///< force centroid [m]
  double arcAMin = 0.0, arcAMax = 0.0, arcBMin = 0.0, arcBMax = 0.0;  ///< extent [m]
};

/// Follows the events through a run.
class ContactEventTracker {
 public:
  /// @param impactVelocityThreshold events starting faster than this are impacts [m/s]
  /// @param separationTime an event without contact force for this long is closed [s]
  ContactEventTracker(double impactVelocityThreshold = 0.05, double separationTime = 0.2)
      : m_impactVelocity(impactVelocityThreshold), m_separationTime(separationTime) {}

  /// Smallest surface gap [m] between lines A and B over the arc ranges [a0, a1] on A and [b0, b1] on B.
  using GapFunction = std::function<double(int lineA, int lineB, double a0, double a1, double b0, double b1)>;

  /// Fills an impact's continuum estimate (ContactEvent::continuum*) when it opens.
  using ContinuumFunction = std::function<void(ContactEvent&)>;

  /// Updates the events with the spots of a committed state at `time` reached with step dt (0 in statics).
  void update(double time, double dt, bool dynamic, const std::vector<ContactSpot>& spots,
              const GapFunction& gapIn, const ContinuumFunction& continuum = {});
  /// Closes the open events at the end of the run.
  void finish(double time);
  /// Closed events in the order they closed (after finish(): all of them, by start time).
  const std::vector<ContactEvent>& events() const { return m_closed; }
  /// Open events.
  const std::vector<ContactEvent>& openEvents() const { return m_open; }
  /// Patches at the last update.
  const std::vector<ContactPatch>& patches() const { return m_patches; }

 private:
  void close(std::size_t openIndex, double time, double closingImpulse, const char* phaseEnd);
  /// Ends the impact phase of an event at `time` with the relative normal velocity u [m/s] reached, and
  /// measures the impact (measureImpact).
  static void endPhase(ContactEvent& e, double time, double u, const char* why);
  /// The impact phase's masses, its energy and the warning about them, from the phase's impulse, velocity
  /// change and work (see the file comment).
  static void measureImpact(ContactEvent& e);

  double m_impactVelocity, m_separationTime;
  std::vector<ContactEvent> m_open, m_closed;
  std::vector<ContactPatch> m_patches;
};

}  // namespace tangle::contact
