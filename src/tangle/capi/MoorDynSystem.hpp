#pragma once
/// @file MoorDynSystem.hpp
/// The C++ object behind a MoorDyn handle of the MoorDyn-compatible C API (include/tangle-moordyn/): a
/// MoorDyn deck converted into a tangle model (io::loadMoorDynCoupling) and run by analysis::CoupledRun,
/// with the deck's lines and points answered in the deck's terms (ids from 1, nodes from end A of each deck
/// line, MoorDyn's signs). Every query throws (InvalidValue, NotImplemented, tangle's own errors); the C
/// functions (MoorDynApi.cpp, MoorDynObjectsApi.cpp, MoorDynV1Api.cpp) turn them into MOORDYN_* codes.
///
/// Deck line l, node i (0 at the deck line's end A) is node firstNode + i (firstNode - i when reversed) of
/// tangle line MoorDynLineMap::tangleLine. Results come from CoupledRun::lineResults() (the state after the
/// last initialize or step); the velocities and accelerations from the simulation's state.
/// Units: SI (m, m/s, m/s^2, N, s).

#include <fstream>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "tangle/analysis/CoupledRun.hpp"
#include "tangle/core/Error.hpp"
#include "tangle/core/Types.hpp"
#include "tangle/io/MoorDynCoupling.hpp"

namespace tangle::capi {

/// A call the API refuses: a NULL output, an index out of range, a call out of order (MOORDYN_INVALID_VALUE).
class InvalidValue : public Error {
 public:
  explicit InvalidValue(const std::string& message) : Error(message) {}
};

/// A function tangle does not implement (MOORDYN_NON_IMPLEMENTED); the message says why.
class NotImplemented : public Error {
 public:
  explicit NotImplemented(const std::string& message) : Error(message) {}
};

class MoorDynSystem;

/// What a MoorDynLine handle points to: a line of the deck (owned by its system).
struct LineHandle {
  MoorDynSystem* system = nullptr;
  int index = 0;  ///< 0-based position in the deck's LINES table (deck id - 1)
};

/// What a MoorDynPoint handle points to: a point of the deck (owned by its system).
struct PointHandle {
  MoorDynSystem* system = nullptr;
  int index = 0;  ///< 0-based position in the deck's POINTS table (deck id - 1)
};

/// What a MoorDynRod handle points to: a rod of the deck (owned by its system).
struct RodHandle {
  MoorDynSystem* system = nullptr;
  int index = 0;  ///< 0-based position in the deck's RODS table (deck id - 1)
};

/// What a MoorDynBody handle points to: a body of the deck (owned by its system).
struct BodyHandle {
  MoorDynSystem* system = nullptr;
  int index = 0;  ///< 0-based position in the deck's BODIES table (deck id - 1)
};

/// MoorDyn's body types (MoorDyn's Body::types), as MoorDyn_GetBodyType returns them.
inline constexpr int kBodyCoupled = -1;
inline constexpr int kBodyFree = 0;
inline constexpr int kBodyFixed = 1;
inline constexpr int kBodyCoupledPinned = 2;

/// MoorDyn's rod types (MoorDyn's Rod::types), as MoorDyn_GetRodType returns them.
inline constexpr int kRodCoupled = -2;
inline constexpr int kRodCoupledPinned = -1;
inline constexpr int kRodFree = 0;
inline constexpr int kRodPinned = 1;
inline constexpr int kRodFixed = 2;

/// MoorDyn's point types (MoorDyn's Point::types), as MoorDyn_GetPointType returns them.
inline constexpr int kPointCoupled = -1;
inline constexpr int kPointFree = 0;
inline constexpr int kPointFixed = 1;

class MoorDynSystem {
 public:
  /// Reads, converts and checks the deck (empty path: "Mooring/lines.txt", as MoorDyn) and sets up the
  /// coupled run. @throws InputError for a deck tangle cannot represent or a model the reader refuses
  explicit MoorDynSystem(const std::string& path);
  ~MoorDynSystem();
  MoorDynSystem(const MoorDynSystem&) = delete;
  MoorDynSystem& operator=(const MoorDynSystem&) = delete;

  /// @name Messages
  /// A message reaches stderr when its level (MOORDYN_*_LEVEL) is at least the verbosity, and the log
  /// file (if open) when at least the log level.
  /// @{
  void setVerbosity(int level) { m_verbosity = level; }
  void setLogLevel(int level) { m_logLevel = level; }
  /// Opens (truncates) the log file. @throws OutputError when it cannot be opened
  void setLogFile(const std::string& path);
  /// Writes `text` as it is (no newline added).
  void log(int level, std::string_view text);
  /// @}

  /// @name The system
  /// @{
  /// Number of coupled DOFs as MoorDyn_NCoupledDOF counts them: 6 per coupled body, 6 per coupled and 3 per
  /// coupled-pinned rod, 3 per coupled point. (MoorDyn v2.7.1 counts 6 for a CoupledPinned body but reads
  /// and writes its 3 translations only: the host's arrays keep the count, the objects after it start 3
  /// later.)
  int coupledDofCount() const;
  /// The DOFs read from and written to the host's arrays (a CoupledPinned body's 3).
  int hostDofCount() const;
  bool initialized() const { return m_run->initialized(); }
  /// CoupledRun::initialize with x [m] and xd [m/s] (coupledDofCount() values each; xd may be null: zero).
  /// @throws InvalidValue when called twice, for a null or non-finite x; ConvergenceError from the statics
  void initialize(const double* x, const double* xd);
  /// Advances by dt [s] (CoupledRun::step) and writes the forces on the coupled points [N] into f and the
  /// time after the step [s] into *t; dt <= 0 only writes them. @throws InvalidValue before initialize or
  /// for null or non-finite input; ConvergenceError when the model cannot be advanced
  void step(const double* x, const double* xd, double* f, double* t, double dt);
  /// The model's time step (dynamics.time_step) [s].
  double timeStep() const { return m_coupling.spec.dynamics.timeStep; }
  /// Sets the model's time step [s] (> 0). @throws NotImplemented after initialize (the analysis is set up
  /// with it), InvalidValue for dt <= 0
  void setTimeStep(double dt);
  /// The model's integrator as the model file names it ("generalized_alpha", "hht", "newmark").
  std::string timeSchemeName() const;
  int lineCount() const { return static_cast<int>(m_lineHandles.size()); }
  int pointCount() const { return static_cast<int>(m_pointHandles.size()); }
  int rodCount() const { return static_cast<int>(m_rodHandles.size()); }
  int bodyCount() const { return static_cast<int>(m_bodyHandles.size()); }
  /// Handles by 1-based deck id; null when out of range. Owned by this system.
  LineHandle* line(unsigned int id);
  PointHandle* point(unsigned int id);
  RodHandle* rod(unsigned int id);
  BodyHandle* body(unsigned int id);
  /// @}

  /// @name Deck bodies (index b = deck id - 1)
  /// @{
  const io::MoorDynBody& deckBody(int b) const { return m_coupling.deck.bodies[static_cast<std::size_t>(b)]; }
  /// kBodyFree, kBodyFixed, kBodyCoupled or kBodyCoupledPinned.
  int bodyType(int b) const;
  /// The body's reference point (the deck's X0, Y0, Z0 moved with it) [m] and its attitude as MoorDyn's XYZ
  /// Euler angles (R = Rx(roll) Ry(pitch) Rz(yaw)) [rad]; the velocity of the reference point [m/s] and the
  /// angular velocity [rad/s], global axes. A free body's from its tangle vessel; a held one's where the deck
  /// puts it, at rest; before MoorDyn_Init the deck's.
  void bodyState(int b, Vec6& position, Vec6& velocity);
  /// What MoorDyn_Step gave the host for a coupled body or rod at the last step (after MoorDyn_Init, at the
  /// initial state): force [N] and moment [N m] about its reference point (a pinned one's moment 0).
  /// @throws NotImplemented for others
  Vec6 bodyForce(int b) const;
  Vec6 rodForce(int r) const;
  /// A free or pinned body's mass matrix about its reference point, global axes [kg, kg m, kg m^2]: tangle's
  /// mass (structural, added and attached, lumped or consistent as the model) of its vessel and the rods
  /// fixed to it, under the six rigid motions about that point (MoorDyn's Body::getM: its own, its points'
  /// and its rods'). @throws NotImplemented for a fixed or coupled body (tangle does not model its mass)
  Mat6 bodyMass(int b);
  /// A moving (pinned or free) rod's mass matrix about its end A, global axes, as bodyMass (MoorDyn's
  /// Rod::getM). @throws NotImplemented for a fixed, coupled or zero-length rod
  Mat6 rodMass(int r);
  /// @}

  /// @name Deck lines (index l = deck id - 1; node i from 0 at the deck line's end A to its segment count)
  /// @{
  const io::MoorDynLine& deckLine(int l) const { return m_coupling.deck.lines[static_cast<std::size_t>(l)]; }
  /// EA of the deck line's type [N].
  double lineAxialStiffness(int l) const;
  Vec3 nodePosition(int l, unsigned int i);
  Vec3 nodeVelocity(int l, unsigned int i);
  /// At the deck line's ends: endForce(); at inner nodes: structural mass times acceleration [N].
  Vec3 nodeForce(int l, unsigned int i);
  /// Tension vector from the deck line's end A towards its end B [N], as MoorDyn's Line::getNodeTen: at
  /// the deck line's ends the tension of its end segment along that segment; elsewhere the node's effective
  /// tension along the chord through the neighbouring nodes of the same deck line. (MoorDyn's includes the
  /// segment's axial damping, tangle's is the elastic tension.)
  Vec3 nodeTension(int l, unsigned int i);
  /// LineSnapshot::curvature at the node [1/m].
  double nodeCurvature(int l, unsigned int i);
  /// Tension of the deck line's end segment at end `end` (0 A, 1 B) [N]: MoorDyn_GetLineFairTen's (end B),
  /// the norm of nodeTension there. (The end tension itself, extrapolated to the end node, is tangle's
  /// LineSnapshot::endTensionA/B in its own results; it differs by about half a segment's weight.)
  double endTension(int l, int end);
  /// Largest norm of nodeTension over the deck line's nodes 0 to N - 1 [N] (MoorDyn_GetLineMaxTen's range).
  double maxTension(int l);
  /// Force the deck line exerts on what holds its end `end` (0 A, 1 B) [N], pointing from the end into the
  /// line: at a tangle line end the end tension force (LineSnapshot::endTensionForceA/B, the end segment's
  /// tension and the end node's own loads), at a junction of two deck lines its end segment's tension.
  Vec3 endForce(int l, int end);
  /// @}

  /// @name External wave kinematics (MoorDyn_ExternalWaveKin*, for a deck with option WaveKin 1)
  /// The points where the host gives the fluid kinematics, in MoorDyn's order (Waves.cpp,
  /// kinematicsForAllNodes): every node of every deck line (0 to N, in deck order), every node of every rod
  /// (0 to NumSegs), every deck point, then MoorDyn's ground body and every body.
  /// @{
  /// Their number; 0 when the deck's WaveKin is not 1 (MoorDyn counts them whatever WaveKin is: tangle
  /// refuses kinematics its model would not use).
  int waveKinematicsPointCount() const;
  /// Their current positions [m], 3 values per point. @throws InvalidValue before initialize
  std::vector<double> waveKinematicsPoints();
  /// Fluid velocity U [m/s] and acceleration Ud [m/s^2] at those points (3 values per point each), used by
  /// the dynamics from the next step on (hydro::HydroLoads::setNodeKinematics: each element takes the mean
  /// of its nodes; a node shared by two deck lines, inside one tangle line, takes the mean of its values).
  /// The nodes of a moving rod (a tangle line) take theirs; the values at the points, the bodies and the
  /// nodes of a held rod are not used: attachments, vessels and held rods see the current only.
  /// @throws InvalidValue before initialize, without WaveKin 1, for null or non-finite values
  void setWaveKinematics(const double* U, const double* Ud);
  /// @}

  /// @name Deck points (index p = deck id - 1)
  /// @{
  const io::MoorDynPointMap& pointMap(int p) const {
    return m_coupling.conversion.points[static_cast<std::size_t>(p)];
  }
  /// kPointCoupled, kPointFree or kPointFixed.
  int pointType(int p) const;
  Vec3 pointPosition(int p);
  Vec3 pointVelocity(int p);
  /// Coupled: CoupledRun::forces(); others: the sum of endForce() of the attached deck line ends [N].
  Vec3 pointForce(int p);
  /// @}

  /// A point's own mass, volume and drag on a body the host moves rigidly (rigidPointLoads).
  struct RigidPoint {
    double mass = 0.0;           ///< m [kg]
    double volume = 0.0;         ///< V [m^3]
    double dragArea = 0.0;       ///< CdA [m^2]
    double addedMass = 0.0;      ///< Ca [-]
    Vec3 offset = Vec3::Zero();  ///< in the body's axes from its reference point [m]
  };
  /// The loads of `point` about the body's reference point [N, N m], global axes (MoorDyn's Point::doRHS and
  /// getNetForceAndMass): weight and buoyancy (rho V - m) g, drag 1/2 rho CdA |u - v| (u - v) with u the
  /// fluid velocity [m/s] at the point and v its velocity, and the inertia -(m + rho V Ca) a of its
  /// acceleration a = a_ref + alpha x r + omega x (omega x r), r = rotation * offset. MoorDyn v2.7.1 leaves
  /// the centripetal term's moment out; tangle takes the moment of the whole force. The body's reference
  /// point moves with velocity [m/s] and acceleration [m/s^2], it turns at angularVelocity [rad/s] and
  /// angularAcceleration [rad/s^2]; density [kg/m^3], gravity [m/s^2].
  static Vec6 rigidPointLoads(const RigidPoint& point, const Mat3& rotation, const Vec3& velocity,
                              const Vec3& angularVelocity, const Vec3& acceleration,
                              const Vec3& angularAcceleration, const Vec3& fluidVelocity, double density,
                              double gravity);

  /// @name Deck rods (index r = deck id - 1; node i from 0 at the rod's end A to NumSegs)
  /// @{
  const io::MoorDynRod& deckRod(int r) const { return m_coupling.deck.rods[static_cast<std::size_t>(r)]; }
  /// kRodFixed, kRodPinned, kRodFree, kRodCoupled or kRodCoupledPinned.
  int rodType(int r) const;
  /// A pinned or free rod's node from its tangle line (`rod<id>`); a held rod's where the deck puts it; a
  /// zero-length rod's (one node) its point's [m]. @throws InvalidValue for i above NumSegs
  Vec3 rodNodePosition(int r, unsigned int i);
  Vec3 rodNodeVelocity(int r, unsigned int i);
  /// @}

 private:
  /// A node of a deck line in the tangle model.
  struct NodeRef {
    const solver::LineSnapshot* snapshot = nullptr;
    int modelLine = 0;  ///< index of the tangle line in model().lines()
    int node = 0;       ///< index along the tangle line (0 = its end A)
  };
  /// Where a tangle line's results are.
  struct TangleLine {
    int snapshot = 0;   ///< index in CoupledRun::lineResults()
    int modelLine = 0;  ///< index in model().lines()
  };

  void requireInitialized() const;
  /// The tangle line named `name` (after initialize). @throws Error when the model has no such line
  const TangleLine& tangleLine(const std::string& name);
  /// Node `node` (from its end A) of the tangle line named `line` (after initialize).
  /// `ends`: the snapshot may be CoupledRun::lineEnds() (positions, end forces and end tensions only).
  NodeRef tangleNode(const std::string& line, int node, bool ends = false);
  /// Node i of deck line l. @throws InvalidValue for i above the line's segment count
  NodeRef deckNode(int l, unsigned int i, bool ends = false);
  /// The tension vector at `n` oriented from the tangle line's end A to its end B [N]; `l` is the deck line.
  Vec3 tangleTension(const NodeRef& n, int l);
  /// Tension of deck line l's own end segment at `n`, one of its end nodes [N].
  double segmentTension(const NodeRef& n, int l);
  Vec3 velocity(const NodeRef& n);
  /// Position / velocity of a tangle line end (name, 0 A / 1 B).
  Vec3 endNodePosition(const std::pair<std::string, int>& end);
  Vec3 endNodeVelocity(const std::pair<std::string, int>& end);
  /// Position / velocity of the point a map describes (its first line end, or its junction node).
  Vec3 mappedPosition(const io::MoorDynPointMap& map);
  Vec3 mappedVelocity(const io::MoorDynPointMap& map);

  std::string m_path;
  io::DeckCoupling m_coupling;
  std::unique_ptr<analysis::CoupledRun> m_run;
  std::vector<double> m_elementTension;  ///< work space of segmentTension: element tensions [N]
  std::vector<int> m_oneElement;         ///< the element segmentTension asks for
  std::vector<int> m_coupledIndex;  ///< per deck point, its index among the run's coupled points (-1: none)
  /// A body or rod the host moves, in MoorDyn's order of the coupled DOFs (coupled bodies, coupled rods, then
  /// the coupled points). Rigid (a Coupled body or rod, 6 DOFs: reference point [m] and XYZ Euler angles
  /// [rad]): its 6 DOFs move the points on it rigidly, and the line ends at them are coupled points of the
  /// run. Pinned (3 DOFs, translations): a CoupledPinned body is a pinned free vessel of the run, a
  /// CoupledPinned rod's end A a coupled point holding the rod's line (its rotations solved by tangle).
  struct HostObject {
    int body = -1;                 ///< deck index of the body, or -1
    int rod = -1;                  ///< deck index of the rod, or -1
    bool pinned = false;           ///< 3 DOFs (translations), not 6
    std::vector<int> points;       ///< rigid: deck indices of the deck points on it (a body's)
    std::vector<int> runPoints;    ///< rigid: per offset, the run's coupled point (-1: no line end there)
    std::vector<Vec3> offsets;     ///< rigid: positions in its axes from its reference point [m]
    int runPoint = -1;             ///< pinned: the run's coupled point (-1: nothing to move)
    Vec6 position = Vec6::Zero();  ///< the host's at time0 (pinned: the first three)
    Vec6 velocity =
        Vec6::Zero();           ///< and their rates [m/s, rad/s] (the angles' taken as the angular velocity)
    /// Their second rates over the last step [m/s^2, rad/s^2]: the change of the host's velocities over
    /// its dt (MoorDyn's MoorDyn::Step); 0 at initialize.
    Vec6 acceleration = Vec6::Zero();
    std::vector<RigidPoint> pointLoads;  ///< rigid body: its deck points with mass, volume or drag
    double time0 = 0.0;         ///< [s]
    Vec6 force = Vec6::Zero();  ///< what the host got at the last step: force [N], moment [N m] (pinned: 0)
    /// Values it reads from and writes to the host's arrays.
    int hostValues() const { return pinned ? 3 : 6; }
    /// DOFs MoorDyn_NCoupledDOF counts for it (MoorDyn v2.7.1: 6 for every body, pinned or not).
    int countedValues() const { return body >= 0 ? 6 : hostValues(); }
    /// The host's 6-vector at time t [s]: reference point [m] and XYZ Euler angles [rad], linear over the
    /// host's step, the angles too (as MoorDyn's Body::updateFairlead).
    Vec6 pose(double t) const { return position + velocity * (t - time0); }
  };
  std::vector<HostObject> m_hostObjects;
  int m_deckCoupledPoints = 0;  ///< the deck's Coupled points
  std::vector<analysis::CoupledPointSpec>
      m_runPoints;  ///< the run's coupled points: the deck's, the objects'
  /// The host's DOFs (objects', then points' 3) as the run's point positions and velocities at time0 [s]; a
  /// rigid object's points move over the host's step dt [s] along the chord to where its pose puts them at
  /// its end (dt = 0, at initialize: their velocity).
  void hostToRun(const double* x, const double* xd, std::vector<double>& position,
                 std::vector<double>& velocity, double time0, double dt);
  /// The position [m] and velocity [m/s] of a point at offset `offset` of rigid host object `c` at time t
  /// [s].
  void hostObjectPoint(const HostObject& c, const Vec3& offset, double t, Vec3& position,
                       Vec3& velocity) const;
  /// The rigid host object whose points include deck point p (its offset into *offset), or null.
  const HostObject* hostObjectOf(int p, Vec3* offset) const;
  /// Every host object's force (HostObject::force) at the run's state: the coupled points' forces of the
  /// run, and for a rigid body about its reference point with its points' own loads (rigidPointLoads).
  void updateHostForces();
  /// A point on a free body that no line holds: its position [m] and velocity [m/s] from the body's vessel.
  /// False when p is not such a point (or before initialize).
  bool freeBodyPoint(int p, Vec3& position, Vec3& velocity);
  /// A free body's frame from its vessel's node (after initialize): the body's reference point [m] and axes
  /// (body to global), the node's position [m], velocity [m/s] and angular velocity [rad/s]. The node is the
  /// vessel's reference point p and Q its rotation from the axes at t = 0 (the global axes); the body's
  /// reference point is p + Q (origin0 - reference0), its axes Q R0.
  struct VesselBodyFrame {
    Vec3 origin, nodePosition, nodeVelocity, angularVelocity;
    Mat3 rotation;
    /// Velocity [m/s] of the body's point at `x` [m] (global): v + w x (x - p).
    Vec3 velocityAt(const Vec3& x) const { return nodeVelocity + angularVelocity.cross(x - nodePosition); }
  };
  VesselBodyFrame vesselBodyFrame(const io::MoorDynBodyMap& map) const;
  /// The rigid host object that is rod r (a Coupled rod), or null.
  const HostObject* rigidRod(int r) const;
  /// The 6x6 mass of the model's nodes `nodes` under the rigid motions about `reference` [m]: M_ij = phi_i^T
  /// M phi_j, phi_j the node accelerations of a unit rigid acceleration j (x, y, z, then rotations about
  /// them).
  Mat6 rigidMass(const std::vector<int>& nodes, const Vec3& reference);
  std::unordered_map<std::string, TangleLine> m_tangleLines;  ///< by name (filled after initialize)
  std::vector<std::unique_ptr<LineHandle>> m_lineHandles;
  std::vector<std::unique_ptr<PointHandle>> m_pointHandles;
  std::vector<std::unique_ptr<RodHandle>> m_rodHandles;
  std::vector<std::unique_ptr<BodyHandle>> m_bodyHandles;
  int m_verbosity;
  int m_logLevel;
  std::ofstream m_logFile;
};

}  // namespace tangle::capi
