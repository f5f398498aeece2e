#pragma once
/// @file ModelSpec.hpp
/// The model as the user wrote it (one struct per YAML block), before meshing. The reader
/// (io::ModelReader) fills it and checks it; model::Model builds the finite-element mesh from it.
/// Every field carries its unit; angles are stored in radians (input files give degrees).

#include <array>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tangle/core/Types.hpp"
#include "tangle/geometry/HullShape.hpp"
#include "tangle/seabed/SeabedSpec.hpp"
#include "tangle/seabed/SeabedSurface.hpp"
#include "tangle/section/LineType.hpp"

// The current grid the reader builds (hydro is a layer above model: the spec only carries it; io reads it and
// hydro evaluates it).
namespace tangle::hydro {
class CurrentGrid;
}

namespace tangle::model {


/// One level of a piecewise-linear current profile.
struct CurrentLevel {
  double z = 0.0;        ///< level [m], z = 0 at still water level, negative below
  double speed = 0.0;    ///< current speed [m/s]
  double azimuth = 0.0;  ///< direction the current flows towards, anticlockwise from +x [rad]
};

/// Kind of wave train.
enum class WaveKind { None, Airy, Jonswap, Components };

/// How wave kinematics are taken above and below the still water level (z = 0) under a finite wave.
enum class WaveStretching {
  None,           ///< linear theory as is, evaluated at the point's z and cut off above z = 0
  Wheeler,        ///< Wheeler: z is mapped to z' = d (z - eta) / (d + eta), kinematics at z' (default)
  Extrapolation   ///< vertical extrapolation: below z = 0 linear theory, above it the z = 0 values up to eta
};

/// Wave input.
struct WaveSpec {
  WaveKind kind = WaveKind::None;
  double height = 0.0;          ///< regular wave height H [m] (Airy)
  double period = 0.0;          ///< regular wave period T [s] (Airy)
  double significantHeight = 0.0;  ///< Hs [m] (JONSWAP)
  double peakPeriod = 0.0;      ///< Tp [s] (JONSWAP)
  double gamma = 3.3;           ///< JONSWAP peak enhancement factor [-]
  int components = 100;         ///< number of JONSWAP components [-]
  unsigned seed = 1;            ///< random seed of the JONSWAP phases [-]
  double azimuth = 0.0;         ///< direction of travel, anticlockwise from +x [rad]
  double phase = 0.0;           ///< phase of the regular wave [rad]
  /// `type: components`: each component's period [s], amplitude [m], phase [rad] and direction of travel
  /// [rad] (hydro::ComponentSea: eta_i = a cos(k (x cos(beta) + y sin(beta)) - 2 pi t / T + phase)).
  std::vector<std::array<double, 4>> componentTable;
  WaveStretching stretching = WaveStretching::Wheeler;  ///< kinematics above/below z = 0
};

/// The current at one time of a current that changes in time (environment.current.history).
struct CurrentSnapshot {
  double time = 0.0;                 ///< [s]
  std::vector<CurrentLevel> levels;  ///< its profile
};

/// Environment: water, gravity, seabed, current and waves.
struct EnvironmentSpec {
  /// Depth of the seabed below still water level [m]: everywhere for a flat seabed, under the origin for a
  /// plane; the waves' depth (dispersion, attenuation) in every case.
  double waterDepth = 100.0;
  double waterDensity = 1025.0;   ///< sea water density [kg/m^3]
  double gravity = 9.80665;       ///< gravitational acceleration [m/s^2]
  ::tangle::seabed::SeabedSpec seabed;  // (qualified: the member shares the namespace's name)
  /// The seabed's shape (a slope, a bathymetry grid); null: flat at z = -waterDepth.
  std::shared_ptr<const ::tangle::seabed::SeabedSurface> seabedSurface;
  std::vector<CurrentLevel> current;  ///< empty: no current
  /// A current that changes in time (environment.current.history; MoorDyn's Currents 2): profiles at
  /// increasing times, interpolated linearly between them, the first before its time and the last after its
  /// own; `current` is then the first profile (the statics' current). Empty: steady.
  std::vector<CurrentSnapshot> currentHistory;
  /// A current on a grid in space and time (environment.current.grid; MoorDyn's Currents 5); null: none. With
  /// it, `current` and `currentHistory` are empty.
  std::shared_ptr<const ::tangle::hydro::CurrentGrid> currentGrid;
  WaveSpec waves;
  double windSpeed = 0.0;         ///< wind speed at 10 m [m/s]
  double windAzimuth = 0.0;       ///< direction the wind blows towards [rad]
  double airDensity = 1.225;      ///< [kg/m^3]
};

/// How a vessel moves.
enum class VesselMode {
  Fixed,       ///< does not move
  Prescribed,  ///< follows a harmonic motion or a time history about its initial position
  Free         ///< 6-DOF rigid body solved together with its lines (same implicit solve)
};

/// The model file's name of a vessel mode ("fixed", "prescribed", "free").
inline const char* vesselModeName(VesselMode mode) {
  switch (mode) {
    case VesselMode::Fixed:
      return "fixed";
    case VesselMode::Prescribed:
      return "prescribed";
    case VesselMode::Free:
      return "free";
  }
  return "?";
}

/// A coefficient table against relative heading (OCIMF style): per heading, surge, sway and yaw coefficients.
struct HeadingTable {
  std::vector<double> heading;  ///< relative heading of the flow in vessel axes, ascending, in [0, 2 pi) [rad]
  std::vector<Vec3> values;     ///< (x, y, yaw) values at each heading (meaning depends on the table)
};

/// Response amplitude operators of the first-order wave motion of a vessel.
struct RaoTable {
  std::vector<double> period;   ///< wave periods, ascending [s]
  std::vector<double> heading;  ///< relative wave headings in vessel axes, ascending in [0, 2 pi) [rad]
  /// amplitude[p][h][dof]: motion amplitude per unit wave amplitude: surge, sway, heave [m/m], roll, pitch,
  /// yaw [rad/m]; phase[p][h][dof]: phase lag relative to the wave crest at the reference point [rad].
  std::vector<std::vector<std::array<double, 6>>> amplitude;
  std::vector<std::vector<std::array<double, 6>>> phase;
};

/// A floating unit (6-DOF rigid body).
struct VesselSpec {
  std::string name;
  VesselMode mode = VesselMode::Fixed;
  Vec3 position = Vec3::Zero();   ///< reference point at t = 0, global axes [m]
  double heading = 0.0;           ///< heading of the vessel x axis, anticlockwise from global +x [rad]
  double mass = 0.0;              ///< [kg]
  Vec3 inertia = Vec3::Zero();    ///< roll, pitch, yaw moments of inertia about the reference point [kg m^2]
  std::array<double, 6> addedMass{};  ///< diagonal added mass: surge, sway, heave [kg]; roll, pitch, yaw [kg m^2]
  std::array<double, 6> linearDamping{};     ///< [N s/m] and [N m s/rad]
  std::array<double, 6> quadraticDamping{};  ///< [N s^2/m^2] and [N m s^2/rad^2]
  std::array<double, 6> hydrostaticStiffness{};  ///< diagonal: heave [N/m], roll, pitch [N m/rad] (others 0)
  HeadingTable currentCoefficients;  ///< force = 1/2 rho_water V^2 (Cx A_x, Cy A_y, Cmz A_y L): coefficients
  Vec3 currentAreas = Vec3::Zero();  ///< A_x [m^2], A_y [m^2], L [m] for the current coefficients
  HeadingTable windCoefficients;     ///< same form with air density and wind speed
  Vec3 windAreas = Vec3::Zero();     ///< A_x, A_y [m^2], L [m] above water
  HeadingTable waveDrift;            ///< mean drift force per unit wave amplitude squared [N/m^2], yaw [N m/m^2]
  RaoTable raos;                     ///< first-order motions (superposed on the solved/prescribed motion)
  std::array<double, 6> motionAmplitude{};  ///< prescribed harmonic motion: x, y, z [m], roll, pitch, yaw [rad]
  std::array<double, 6> motionPhase{};      ///< [rad]
  double motionPeriod = 10.0;               ///< [s]
  bool heldInStatics = false;  ///< a free vessel held at its position in statics (a DP unit on station), released at t = 0
  /// A free vessel whose reference point is held (at `position`, or where a host moves it:
  /// analysis::CoupledRun) while its rotations are solved: a buoy on a swivel, a pendulum, MoorDyn's
  /// CoupledPinned body.
  bool pinned = false;
  /// A submerged body (vessels[].displaced_volume; OrcaFlex 6D buoy, MoorDyn body), free vessels only: its
  /// weight M g at the reference point (its centre of gravity) and its buoyancy rho g V at centreOfBuoyancy
  /// act on it, constant at any depth [m^3]. NaN: a floating unit, whose weight its displacement balances at
  /// the initial position (hydrostaticStiffness restores it about there).
  double displacedVolume = std::numeric_limits<double>::quiet_NaN();
  Vec3 centreOfBuoyancy = Vec3::Zero();  ///< from the reference point, vessel axes [m]
  /// Solids of its hull that lines and other hulls touch (vessels[].hull), vessel axes; empty: none.
  std::vector<geometry::HullShape> hull;
  int sourceLine = 0;
};

/// A line end hung from a vessel through a tensioner (constant tension over a stroke).
struct TensionerSpec {
  bool enabled = false;
  double tension = 0.0;      ///< nominal tension [N]
  double stroke = 10.0;      ///< total stroke, centred on the initial position [m]
  double stopStiffness = 1e8;  ///< stiffness of the end stops [N/m]
  double stiffness = 0.0;      ///< gas-spring stiffness within the stroke [N/m] (0: constant tension)
};

/// A rotational spring between a vessel and a line end (flex joint).
struct FlexJointSpec {
  bool enabled = false;
  double stiffness = 0.0;  ///< rotational stiffness [N m/rad]
};

/// How a line end is held.
enum class EndKind {
  Anchored,  ///< position fixed (on or above the seabed); rotations free
  Fixed,     ///< position and rotation fixed
  Pinned,    ///< position fixed, rotations free (same as Anchored, not necessarily on the seabed)
  Free,      ///< nothing fixed
  Vessel,    ///< attached to a vessel (see vessel)
  Point      ///< joined at a free point with the other line ends there (see point; `points`)
};

/// Prescribed harmonic motion of a line end about its initial position (dynamics):
/// x(t) = x0 + ramp(t) * amplitude * sin(2 pi t / period + phase).
struct EndMotionSpec {
  bool enabled = false;
  Vec3 amplitude = Vec3::Zero();  ///< displacement amplitude along global x, y, z [m]
  double period = 10.0;           ///< [s]
  double phase = 0.0;             ///< [rad]
  std::vector<std::array<double, 4>> table;  ///< optional time history rows (t [s], x, y, z [m] offsets)
  bool cubic = false;  ///< table interpolation: false piecewise linear, true natural cubic spline (smooth velocity)
};

/// A line end.
struct EndSpec {
  EndKind kind = EndKind::Anchored;
  Vec3 position = Vec3::Zero();  ///< global position [m] (vessel axes [m] for kind Vessel)
  std::string vessel;            ///< vessel name, for kind Vessel
  std::string point;             ///< point name, for kind Point (the end starts at the point's position)
  EndMotionSpec motion;          ///< prescribed motion (dynamics), for Fixed/Pinned/Anchored ends
  TensionerSpec tensioner;       ///< for vessel ends: vertical tensioner instead of a rigid connection
  FlexJointSpec flexJoint;       ///< for vessel ends of beam lines: rotational spring (else pinned)
  std::array<bool, 3> release{false, false, false};  ///< global translations x, y, z left free at a held end (roller)
  int sourceLine = 0;            ///< line of the input file that defined this end (for messages)
};

/// A section of a line: a length of one line type, meshed with equal elements.
struct SectionSpec {
  std::string lineType;  ///< name of a line type
  double length = 0.0;   ///< unstretched length [m]
  int elements = 1;      ///< number of elements [-]
  /// Density of this section's contents [kg/m^3] (sections[].contents_density), instead of the line's
  /// (LineSpec::contents); NaN: the line's. A flooded or empty stretch of a line with contents.
  double contentsDensity = std::numeric_limits<double>::quiet_NaN();
};

/// What fills the bore of a line's pipe sections (lines[].contents; docs/theory.md 5.3).
struct ContentsSpec {
  double density = 0.0;   ///< contents density rho_c [kg/m^3]
  /// Internal pressure p_ref at the reference level [Pa] (gauge above the atmosphere, as the external
  /// hydrostatic pressure rho g (-z) is).
  double pressure = 0.0;
  /// Reference level z_ref of the pressure [m]; NaN: the higher of the line's two ends at t = 0. The pressure
  /// at a point of the line is p_ref plus the contents' head between z_ref and the point.
  double referenceZ = std::numeric_limits<double>::quiet_NaN();
};

/// `lines[].failure`: the line parts during the run (docs/model-format.md "Line failure", docs/theory.md
/// 8.7). It parts in one element: that element stops carrying any force (axial, bending, torsion, axial
/// damping) and leaves the contact; its mass, weight and buoyancy stay lumped at its two nodes, which become
/// the free ends of the two pieces. The first trigger reached parts it; it parts once.
struct FailureSpec {
  /// Where the line parts.
  enum class Where {
    Trigger,  ///< where the trigger is reached: the element of the highest tension over its threshold, or
              ///< the element a clash's impact started on
    Arc,      ///< in the element holding arcLength
    EndA,     ///< in the first element (a connection at end A parting, an anchor dragged out)
    EndB      ///< in the last element
  };
  bool enabled = false;
  /// Time of the dynamics at which it parts [s]; NaN: no time trigger. 0: parted before the statics (the
  /// damaged static equilibrium of an accidental limit state).
  double time = std::numeric_limits<double>::quiet_NaN();
  /// Effective tension at which an element parts [N]; 0: no tension trigger (see tensionIsBreakingLoad).
  double tension = 0.0;
  /// `tension: mbl`: each element's threshold is its line type's minimum breaking load.
  bool tensionIsBreakingLoad = false;
  /// Impact energy of a clash on the line at which it parts [J] (contact events, Eq. 5); 0: none.
  double clashEnergy = 0.0;
  Where where = Where::Trigger;
  double arcLength = 0.0;  ///< unstretched arc length from end A of the parting point [m] (Where::Arc)
};

/// A lumped mass or buoy attached at an arc length along a line.
struct AttachmentSpec {
  /// Unstretched arc length from end A [m]; snapped to the nearest node, or shared between the two nodes of
  /// its element when `shared`.
  double arcLength = 0.0;
  double mass = 0.0;       ///< [kg]
  double volume = 0.0;     ///< displaced volume [m^3]
  double dragArea = 0.0;   ///< Cd * A for drag [m^2]
  double addedMass = 0.0;  ///< added mass [kg]
  /// One of a row of modules (attachments[].pitch, count): shared between the two nodes of its element by
  /// the lever rule (the same resultant and moment about either node), so that a row of buoyancy modules on
  /// any mesh loads the line evenly instead of lumping two modules on some nodes and one on others.
  bool shared = false;
};

/// A free point where line ends meet (`points`): a bridle's apex, a triplate, a 3D buoy or a clump joining
/// any number of lines (OrcaFlex 3D buoy, MoorDyn free point, RIFLEX free supernode). Translations only: the
/// line ends are pinned to it (docs/theory.md 2.5).
struct PointSpec {
  std::string name;
  Vec3 position = Vec3::Zero();  ///< initial position, the starting guess of statics [m]
  /// Its mass [kg], displaced volume [m^3], drag area Cd A [m^2] and added mass [kg] (arcLength unused).
  AttachmentSpec body;
  int sourceLine = 0;
};

/// An intermediate point of a line's starting shape (`lines[].start_shape`).
struct StartPoint {
  Vec3 position = Vec3::Zero();  ///< global position [m]
  /// Unstretched arc length from end A at which the line passes through the point [m]; NaN when not
  /// given (then the points share the line's length in proportion to the polyline's chords).
  double arcLength = std::numeric_limits<double>::quiet_NaN();
};

/// A line: ends, sections from end A to end B, attachments.
struct LineSpec {
  std::string name;
  EndSpec endA;
  EndSpec endB;
  std::vector<SectionSpec> sections;
  std::vector<AttachmentSpec> attachments;
  ContentsSpec contents;  ///< contents and internal pressure of its pipe sections (none by default)
  FailureSpec failure;    ///< how it parts during the run (none by default)
  bool contact = true;  ///< takes part in line-to-line contact
  /// Starting shape of the static solve through these points (end A, the points, end B, straight between
  /// them) instead of the analytic catenary between the ends: a line draped over another, over a guide
  /// or a bollard. Empty: the catenary.
  std::vector<StartPoint> startShape;
};

/// Static solver settings.
struct StaticSpec {
  int maxIterations = 400;       ///< Newton iterations in all [-]
  double tolerance = 1.0e-6;     ///< convergence: max out-of-balance force / reference force [-]
  double displacementTolerance = 1.0e-7;  ///< convergence: max displacement increment / line length [-]
  /// `method: none`: no static solve; the dynamics starts from the start shape at rest (a dropped object, a
  /// body let go from where it is: OrcaFlex's statics method "None").
  bool skip = false;
};

/// Time integration scheme.
enum class IntegratorKind { GeneralizedAlpha, Hht, Newmark };

/// Dynamic analysis settings.
/// How each dynamic step's Newton iteration is solved (`dynamics.solver`, docs/theory.md 8.2). The defaults
/// are the fast path; the plainest choice (full Newton, whole assembly, whole refresh) is the reference the
/// fast path is checked against. Whatever is chosen, a step that fails is retried with a whole refresh and then
/// with full Newton before it is cut (GeneralizedAlpha::step).
struct DynamicSolverSpec {
  /// newton: `modified` (the factorised iteration matrix is kept while the residual falls fast) or `full`
  /// (refreshed at every iteration).
  bool modifiedNewton = true;
  /// assembly: `parts` (an iteration re-evaluates only the part of the model its correction moved) or
  /// `whole` (every iteration on the whole model, every independent block solved).
  bool partIterations = true;
  /// refresh: `blocks` (slow independent blocks and stretches refreshed on their own) or `whole`.
  bool blockRefresh = true;
  /// matrix_refresh: `renewal` (the kept matrix is also refreshed when keeping it costs more iterations
  /// than a refresh, the renewal rule of theory 8.2) or `when_slow` (only when a step converges slowly).
  bool renewalRule = true;
  /// predictor: `seabed` (the constant-acceleration predictor corrected at nodes on or onto the seabed for
  /// the change of their seabed reaction within the step, time::SeabedPredictor) or `extrapolated` (not
  /// corrected).
  bool seabedPredictor = true;
  /// step_change: `rescale` (after a converged step, a kept matrix made for another step length is made for
  /// the new one with the mass matrix at the step's start and factorised again, without an assembly,
  /// solver::NewtonIteration::startAttempt) or `refresh` (assembled and factorised again).
  bool stepChangeRescale = true;

  /// One key of `dynamics.solver`: its name, the names of its two values and the member it sets. The reader,
  /// the run log and summary.json all name the choices from this table.
  struct Choice {
    const char* key;
    const char* whenTrue;
    const char* whenFalse;
    bool DynamicSolverSpec::*member;
  };
  /// The six keys, in the order of docs/model-format.md.
  static constexpr std::array<Choice, 6> kChoices{{
      {"newton", "modified", "full", &DynamicSolverSpec::modifiedNewton},
      {"assembly", "parts", "whole", &DynamicSolverSpec::partIterations},
      {"refresh", "blocks", "whole", &DynamicSolverSpec::blockRefresh},
      {"matrix_refresh", "renewal", "when_slow", &DynamicSolverSpec::renewalRule},
      {"predictor", "seabed", "extrapolated", &DynamicSolverSpec::seabedPredictor},
      {"step_change", "rescale", "refresh", &DynamicSolverSpec::stepChangeRescale},
  }};
  /// The name of the value chosen for `choice`.
  const char* valueOf(const Choice& choice) const { return this->*choice.member ? choice.whenTrue : choice.whenFalse; }
};

struct DynamicSpec {
  bool enabled = false;
  double duration = 0.0;        ///< simulated time [s]
  double timeStep = 0.01;       ///< time step [s]
  double minTimeStep = 1.0e-5;  ///< smallest step the step controller may cut to [s]
  double rampTime = 5.0;        ///< smooth ramp of loads and motions at the start [s]
  double outputInterval = 0.1;  ///< time between result records [s]
  IntegratorKind integrator = IntegratorKind::GeneralizedAlpha;
  double spectralRadius = 0.8;  ///< rho_infinity of generalized-alpha / HHT [-]
  bool lumpedMass = true;       ///< lumped (true) or consistent (false) structural mass
  double rayleighAlpha = 0.0;   ///< mass-proportional Rayleigh damping [1/s]
  double rayleighBeta = 0.0;    ///< stiffness-proportional Rayleigh damping [s]
  int maxIterations = 20;       ///< Newton iterations per step [-]
  double tolerance = 1.0e-6;    ///< residual tolerance relative to the reference force [-]
  /// Largest strain a cable (bar) element may gain in one step beyond max(its strain, 0) [-]; 0: no limit.
  /// Resolves slack-to-taut snaps in time (see time/CableSnapLimit.hpp).
  double maxCableStrainStep = 1.0e-4;
  /// Error-controlled steps: largest local error per step relative to the step's displacement increment
  /// (Zienkiewicz & Xie 1991 estimate, docs/theory.md 8.3) [-]; 0: fixed steps of timeStep (default).
  double errorTolerance = 0.0;
  /// Largest step with error control [s] (0: the output interval).
  double maxTimeStep = 0.0;
  DynamicSolverSpec solver;  ///< dynamics.solver
};

/// How an impact between lines is resolved.
enum class ImpactModel {
  Penalty,  ///< penalty spring + dashpot tuned to the coefficient of restitution (default)
  Impulse   ///< the seed paper's impulse model: velocity jump from momentum + restitution at impact,
            ///< elastic penalty spring for sustained contact
};

/// Line-to-line contact settings.
/// How line-to-line contact is formulated (docs/theory.md section 9).
enum class ContactFormulation {
  Point,       ///< closest points of element pairs, blended with line-to-line by the crossing angle
  Distributed  ///< Gauss points along both lines against the other's C1 centreline, barrier-bounded
};

struct ContactSpec {
  bool enabled = false;          ///< contact block present
  /// contact.formulation: distributed by default; the reader picks point for `model: impulse` (a point model)
  ContactFormulation formulation = ContactFormulation::Distributed;
  std::vector<std::pair<std::string, std::string>> pairs;  ///< line pairs that may touch (empty: all pairs)
  bool selfContact = false;      ///< a line may touch itself
  double stiffness = 0.0;        ///< penalty stiffness per contact point [N/m]; 0: automatic from line properties
  double restitution = 0.5;      ///< coefficient of restitution e in [0, 1] [-]
  ImpactModel model = ImpactModel::Penalty;
  double frictionCoefficient = 0.0;  ///< Coulomb friction between lines [-]
  double frictionVelocity = 0.01;    ///< friction regularisation velocity [m/s]
  double clearanceMargin = 50.0;     ///< clearances larger than this are reported as "> margin" [m]
  std::vector<std::pair<std::string, std::string>> exclude;  ///< line pairs that never touch
  /// A length of a line [from, to] (arc length from end A [m]) excluded from contact, with one other
  /// line (`other` non-empty) or with all lines.
  struct ExclusionZone {
    std::string line;
    double from = 0.0, to = 0.0;
    std::string other;
  };
  std::vector<ExclusionZone> exclusionZones;
  bool excludeConnections = true;    ///< exclude lines near a shared connection point automatically
  double impactVelocityThreshold = 0.05;  ///< an event is an impact if it starts faster than this [m/s]
  double eventSeparationTime = 0.2;  ///< an event ends after this long without contact [s]
  /// Clash damage (analysis/ClashDamage.hpp): impacts binned along each line in bins of this length [m].
  double damageBinLength = 1.0;
  /// Impacts with an energy above this are counted per bin (DNV-RP-F203's tolerable impact energy) [J].
  double damageEnergyThreshold = 0.0;

  /// True when contact measures cables, as beams, on their C1 centrelines (the distributed formulation
  /// of an enabled contact, contact/SmoothCentreline.hpp); otherwise a cable is its chords. The clash
  /// report and the clearance envelope measure on the same curve as the contact.
  bool smoothCables() const { return enabled && formulation == ContactFormulation::Distributed; }
};

/// Wake interference of one upstream line on one downstream line (docs/theory.md sec. 12): the steady
/// current seen by the downstream line is reduced in the wake of the upstream one (hydro/WakeModel.hpp).
struct WakeSpec {
  enum class Model { Huse, Blevins };
  std::string upstream;    ///< line whose wake acts
  std::string downstream;  ///< line that sees the reduced current
  Model model = Model::Huse;
  double k1 = 0.25, k2 = 1.0, k3 = 0.693;  ///< Huse coefficients [-]
  double a1 = 1.0, a2 = 4.5, a3 = -10.6;   ///< Blevins coefficients [-]
  /// Drag coefficient of the upstream line for its wake [-]; 0: the upstream line type's drag_normal.
  double upstreamDragCoefficient = 0.0;
};

/// The no-collision check of DNV-RP-F203 (contact/ClearanceEnvelope.hpp).
struct ClearanceSpec {
  double required = 0.0;  ///< required surface-to-surface clearance [m]
  std::vector<std::pair<std::string, std::string>> pairs;  ///< line pairs checked (empty: see ClearanceEnvelope)
  /// The dynamic minima are kept up to this clearance [m]; unset: contact.clearance_margin. The envelope
  /// uses the larger of it and `required` (ClearanceEnvelope).
  std::optional<double> margin;
  /// Pairs designed to touch (DNV-RP-F203 sec. 4, "collision allowed": a riser laid across a flowline, lines
  /// resting on each other): their clearances are still measured and written, but they are assessed by their
  /// impacts (the clash report's events) instead of against `required`.
  std::vector<std::pair<std::string, std::string>> collisionAllowed;
  /// The largest impact energy a collision-allowed pair tolerates [J] (the lines' capacity, from their
  /// designer): a pair passes when none of its impacts carries more; unset: the impacts are reported, not
  /// assessed.
  std::optional<double> allowedImpactEnergy;
};

/// Contact of lines and hulls with hulls (hull_contact; vessel::HullContact): one law for all of it, the
/// elastic penalty with hysteretic restitution of the distributed line contact
/// (contact::HystereticRestitution).
struct HullContactSpec {
  /// Hull to hull: stiffness of each surface point of one hull inside the other [N/m].
  double stiffness = 1.0e7;
  /// Line on hull: stiffness per metre of line inside a hull [N/m per m].
  double lineStiffness = 1.0e6;
  double restitution = 0.5;        ///< coefficient of restitution e in [0, 1] [-]
  double friction = 0.0;           ///< Coulomb friction coefficient [-] (dynamics)
  double frictionVelocity = 0.01;  ///< friction regularisation velocity [m/s]
  /// Spacing of a hull's surface points (hull to hull) and of the points along a line's elements [m].
  double pointSpacing = 1.0;
  /// A line tied to a vessel touches that vessel's hull too (its points inside the hull at the start are
  /// left out); false: it passes through it (a riser through a moonpool).
  bool ownLines = false;
  /// Pairs [line or vessel, vessel] that never touch.
  std::vector<std::pair<std::string, std::string>> exclude;
  int sourceLine = 0;
};

/// An S-N curve of the fatigue analysis as numbers (analysis::SnCurve; DNV-RP-C203 (2021) section 2.4):
/// log10 N = log10 a - m log10(S (t / t_ref)^k), S in MPa, the second slope beyond the knee.
struct SnCurveSpec {
  std::string name;
  double m1 = 3.0, logA1 = 12.164;   ///< slope [-] and log10 a [-] up to the knee
  double m2 = 5.0, logA2 = 15.606;   ///< beyond the knee
  double kneeCycles = 1e7;           ///< [-]
  double thicknessExponent = 0.0;    ///< k [-]
  double referenceThickness = 0.025; ///< t_ref [m]
  bool singleSlope = false;
};

/// A T-N curve of chain or rope as numbers (analysis::TnCurve): API RP 2SK (2005) 7.5, N R^m = K with R the
/// tension range over the reference breaking strength; or DNV-OS-E301 (2021) Ch.2 Sec.2 [6], N = a_D s^-m
/// with s the nominal stress range [MPa].
struct TnCurveSpec {
  std::string name;
  bool stressBased = false;  ///< DNV's form (a_D on stress) instead of API's (K on the ratio to the MBS)
  double m = 3.0;            ///< [-]
  double intercept = 1000.0; ///< K [-] (API) or a_D [MPa^m] (DNV)
};

/// Fatigue properties of the lines of one line type.
struct FatigueSectionSpec {
  std::string lineType;      ///< the line type these apply to
  std::string curve;         ///< name of an S-N curve (stress) or a T-N curve (tension)
  bool tensionCurve = false; ///< `curve` is a T-N curve
  double outerDiameter = 0.0;   ///< steel outer diameter [m] (S-N)
  double wallThickness = 0.0;   ///< steel wall thickness [m] (S-N; also the thickness of the thickness correction)
  double stressConcentration = 1.0;  ///< SCF on the stress range [-]
  int points = 16;              ///< points round the circumference (S-N; 1 for a line without bending)
  bool innerSurface = false;    ///< bending stress at the inner instead of the outer surface
  bool wallTension = true;      ///< axial stress from the wall tension (true) or the effective tension
  double breakingStrength = 0.0;  ///< reference breaking strength [N] (API T-N)
  double nominalArea = 0.0;       ///< nominal area for the stress of a DNV T-N curve [m^2]
};

/// Fatigue analysis of the dynamics (analysis/FatigueDamage.hpp, docs/theory.md section 13).
struct FatigueSpec {
  bool enabled = false;
  std::vector<SnCurveSpec> snCurves;
  std::vector<TnCurveSpec> tnCurves;
  std::vector<FatigueSectionSpec> sections;
  /// Time from which cycles are counted [s] (negative: the dynamics' ramp time).
  double startTime = -1.0;
  /// Fraction of a year the simulated sea state stands for [-]: annual damage = run damage x fraction x
  /// one year / counted duration.
  double occurrence = 1.0;
  double designFactor = 1.0;  ///< design fatigue factor DFF [-]: life = 1 / (DFF x annual damage)
};

/// Result output settings.
/// Files that hold the time histories of a dynamic run (docs/results-hdf5.md).
enum class ResultFormat {
  Auto,  ///< both while the CSV time histories stay under OutputSpec::kAutoCsvLimit, else HDF5 only
  Csv,   ///< CSV files only
  Hdf5,  ///< results.h5 (+ results.xdmf); the small CSV tables (statics, ranges, end forces) stay
  Both   ///< both
};

/// The time histories along the lines a dynamic run writes at its output times (`output.time_histories`;
/// CSV files dynamics/<line>/<quantity>.csv and results.h5 series). End forces, range graphs, extremes
/// and statistics are written whatever the selection.
struct TimeHistorySelection {
  bool position = true;             ///< x_m, y_m, z_m / position
  bool effectiveTension = true;     ///< effective_tension_N / effective_tension
  bool bendingMoment = true;        ///< bending_moment_Nm / bending_moment
  bool bendingMomentVector = true;  ///< bending_moment_{x,y,z}_Nm / bending_moment_vector
  bool curvature = true;            ///< curvature_1_per_m / curvature
  bool torque = true;               ///< torque_Nm / torque
  /// wall_tension_N / wall_tension: lines with a bore only (LineSnapshot::wallTension), whose CSV and series
  /// valuesPerNode leaves out (few lines are pipes; the estimate it serves is of the bulk).
  bool wallTension = true;
  /// Values per node and output time (the CSV columns: 3 for a vector).
  int valuesPerNode() const {
    return 3 * position + effectiveTension + bendingMoment + 3 * bendingMomentVector + curvature + torque;
  }
};

struct OutputSpec {
  /// Estimated CSV time-history volume above which `auto` writes HDF5 only [bytes].
  static constexpr double kAutoCsvLimit = 100e6;
  ResultFormat format = ResultFormat::Auto;
  bool vtk = true;   ///< write a ParaView .pvd/.vtu series
  double vtkInterval = 1.0;  ///< time between ParaView frames in dynamics [s]
  bool plots = true; ///< write PNG plots (needs python3 with matplotlib)
  /// Energy account of the dynamics (dynamics/energy.csv, analysis/EnergyAccount): costs about two extra
  /// assemblies per step, so it is asked for.
  bool energy = false;
  /// Storm duration of the extreme statistics of the dynamics (dynamics/statistics.csv): the most probable
  /// maximum is that of stormDuration / Tz peaks [s] (3 h, DNV-OS-E301 and API RP 2SK's storm).
  double stormDuration = 10800.0;
  TimeHistorySelection timeHistories;
};

/// The whole model as read from the file.
struct ModelSpec {
  std::string sourceFile;  ///< path of the model file, for messages
  std::string title;
  EnvironmentSpec environment;
  std::map<std::string, section::LineType> lineTypes;
  std::vector<VesselSpec> vessels;
  std::vector<PointSpec> points;  ///< free points joining line ends (`points`), input order
  std::vector<LineSpec> lines;
  StaticSpec statics;
  DynamicSpec dynamics;
  ContactSpec contact;
  HullContactSpec hullContact;  ///< used when a vessel has a hull
  std::vector<WakeSpec> wakes;  ///< wake interference pairs (empty: none)
  ClearanceSpec clearance;
  OutputSpec output;
  FatigueSpec fatigue;
  /// Plausibility warnings of the reader (value legal but likely a unit or typing mistake), each naming
  /// the file, line and key; printed by `check` and `run`.
  std::vector<std::string> warnings;
};

}  // namespace tangle::model
