#include "tangle/capi/MoorDynSystem.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <iostream>
#include <numbers>
#include <span>
#include <utility>

#include "MoorDynAPI.h"

namespace tangle::capi {

namespace {

/// @throws InvalidValue when `values` (n of them) is null or holds a value that is not finite.
void checkFinite(const double* values, int n, const char* name) {
  if (n == 0) return;
  if (values == nullptr) throw InvalidValue(fmt::format("{} is NULL ({} coupled DOFs expected)", name, n));
  for (int k = 0; k < n; ++k)
    if (!std::isfinite(values[k])) throw InvalidValue(fmt::format("{}[{}] is {}", name, k, values[k]));
}

/// MoorDyn's body rotation from its XYZ Euler angles [rad]: R = Rx(a) Ry(b) Rz(c) (Misc.hpp, Euler2Quat).
Mat3 eulerRotation(const Vec3& angles) {
  return (Eigen::AngleAxisd(angles.x(), Vec3::UnitX()) * Eigen::AngleAxisd(angles.y(), Vec3::UnitY()) *
          Eigen::AngleAxisd(angles.z(), Vec3::UnitZ()))
      .toRotationMatrix();
}

}  // namespace

MoorDynSystem::MoorDynSystem(const std::string& path)
    : m_path(path.empty() ? std::string("Mooring/lines.txt") : path),
      m_coupling(io::loadMoorDynCoupling(m_path)),
      m_verbosity(MOORDYN_MSG_LEVEL),
      m_logLevel(MOORDYN_MSG_LEVEL) {
  const io::MoorDynConversion& c = m_coupling.conversion;
  if (c.lines.size() != m_coupling.deck.lines.size() || c.points.size() != m_coupling.deck.points.size())
    throw Error(fmt::format("{}: the conversion maps {} of {} lines and {} of {} points (a bug in tangle)",
                            m_path, c.lines.size(), m_coupling.deck.lines.size(), c.points.size(),
                            m_coupling.deck.points.size()));
  // MoorDyn couples the bodies' DOFs ahead of the rods', and those ahead of the points' (MoorDyn2.cpp).
  m_runPoints = m_coupling.points;
  m_deckCoupledPoints = static_cast<int>(m_runPoints.size());
  m_coupledIndex.assign(c.points.size(), -1);
  {
    int k = 0;
    for (std::size_t p = 0; p < c.points.size(); ++p)
      if (c.points[p].kind == io::MoorDynPointKind::Coupled) m_coupledIndex[p] = k++;
  }
  const auto addRunPoint = [&](std::string name, std::vector<std::pair<std::string, int>> ends) {
    if (ends.empty()) return -1;
    m_runPoints.push_back({std::move(name), std::move(ends), {}});
    return static_cast<int>(m_runPoints.size()) - 1;
  };
  for (std::size_t bi = 0; bi < m_coupling.deck.bodies.size(); ++bi) {
    const io::MoorDynBody& b = m_coupling.deck.bodies[bi];
    if (b.kind != io::MoorDynBodyKind::Coupled && b.kind != io::MoorDynBodyKind::CoupledPinned) continue;
    HostObject h;
    h.body = static_cast<int>(bi);
    if (b.kind == io::MoorDynBodyKind::CoupledPinned) {
      // A pinned free vessel of the converted model (VesselSpec::pinned): the run moves its reference point.
      h.pinned = true;
      h.position.head<3>() = b.position;
      m_runPoints.push_back({fmt::format("body{}", b.id), {}, c.bodies[bi].vessel});
      h.runPoint = static_cast<int>(m_runPoints.size()) - 1;
      m_hostObjects.push_back(std::move(h));
      continue;
    }
    for (const io::MoorDynRod& r : m_coupling.deck.rods)
      if (r.body == b.id)
        throw Error(
            fmt::format("{}:{}: rod {} is on coupled body {}: tangle's MoorDyn API moves the points of "
                        "a coupled body, not its rods (attach the lines to points on the body)",
                        m_path, r.sourceLine, r.id, b.id));
    h.position << b.position, b.rotation * (std::numbers::pi / 180.0);
    for (std::size_t p = 0; p < m_coupling.deck.points.size(); ++p) {
      const io::MoorDynPoint& point = m_coupling.deck.points[p];
      if (point.kind != io::MoorDynPointKind::Body || point.body != b.id) continue;
      h.points.push_back(static_cast<int>(p));
      h.offsets.push_back(point.position);
      const int run = addRunPoint(fmt::format("body{}point{}", b.id, point.id), c.points[p].ends);
      h.runPoints.push_back(run);
      if (run >= 0) m_coupledIndex[p] = run;
      // The point's own mass, volume and drag load the body (MoorDyn's Body::doRHS sums its points').
      if (point.mass != 0.0 || point.volume != 0.0 || point.dragArea != 0.0)
        h.pointLoads.push_back({point.mass, point.volume, point.dragArea, point.addedMass, point.position});
    }
    if (b.mass != 0.0 || b.volume != 0.0 ||
        std::any_of(b.dragArea.begin(), b.dragArea.end(), [](double a) { return a != 0.0; }))
      log(MOORDYN_WRN_LEVEL,
          fmt::format("tangle (MoorDyn API): {}:{}: coupled body {}: its own mass, volume, drag and added "
                      "mass are not used (the host models them; MoorDyn v2.7.1's Body::setup sets them to "
                      "zero for a coupled body too); its points' are\n",
                      m_path, b.sourceLine, b.id));
    m_hostObjects.push_back(std::move(h));
  }
  for (std::size_t ri = 0; ri < m_coupling.deck.rods.size(); ++ri) {
    const io::MoorDynRod& r = m_coupling.deck.rods[ri];
    const io::MoorDynRodMap& map = c.rods[ri];
    if (r.kind != io::MoorDynRodKind::Coupled && r.kind != io::MoorDynRodKind::CoupledPinned) continue;
    HostObject h;
    h.rod = static_cast<int>(ri);
    h.position.head<3>() = r.endA;
    if (r.kind == io::MoorDynRodKind::CoupledPinned) {
      // The rod's line pinned at its end A (and the deck lines there): the host moves that point.
      h.pinned = true;
      h.runPoint = addRunPoint(fmt::format("rod{}a", r.id), map.endLines[0]);
    } else {
      // A Coupled rod holds its lines at its ends, which the host's 6 DOFs move as a rigid body: its
      // reference point is end A, its axes the global axes at the deck's attitude (MoorDyn's Rod: the host's
      // angles turn the deck's axis q0).
      const bool zeroLength = r.length() == 0.0;
      for (int end = 0; end < (zeroLength ? 1 : 2); ++end) {
        h.offsets.push_back(end == 0 ? Vec3::Zero() : Vec3(r.endB - r.endA));
        h.runPoints.push_back(addRunPoint(fmt::format("rod{}{}", r.id, end == 0 ? 'a' : 'b'),
                                          map.endLines[static_cast<std::size_t>(end)]));
      }
      log(MOORDYN_WRN_LEVEL,
          fmt::format("tangle (MoorDyn API): {}:{}: coupled rod {}: the forces returned are those of the "
                      "lines at its ends; its own weight, buoyancy, inertia and drag are the host's (MoorDyn "
                      "adds them), and a line clamped to it keeps its initial direction\n",
                      m_path, r.sourceLine, r.id));
    }
    m_hostObjects.push_back(std::move(h));
  }
  // What the conversion changed or approximated, and the reader's plausibility warnings.
  for (const std::string& warning : m_coupling.spec.warnings)
    log(MOORDYN_WRN_LEVEL, "tangle (MoorDyn API): " + warning + "\n");
  m_run = std::make_unique<analysis::CoupledRun>(m_coupling.spec, m_runPoints);
  for (std::size_t l = 0; l < c.lines.size(); ++l)
    m_lineHandles.push_back(std::make_unique<LineHandle>(LineHandle{this, static_cast<int>(l)}));
  for (std::size_t p = 0; p < c.points.size(); ++p)
    m_pointHandles.push_back(std::make_unique<PointHandle>(PointHandle{this, static_cast<int>(p)}));
  for (std::size_t r = 0; r < c.rods.size(); ++r)
    m_rodHandles.push_back(std::make_unique<RodHandle>(RodHandle{this, static_cast<int>(r)}));
  for (std::size_t b = 0; b < c.bodies.size(); ++b)
    m_bodyHandles.push_back(std::make_unique<BodyHandle>(BodyHandle{this, static_cast<int>(b)}));
}

MoorDynSystem::~MoorDynSystem() = default;

void MoorDynSystem::setLogFile(const std::string& path) {
  std::ofstream file(path, std::ios::out | std::ios::trunc);
  if (!file) throw OutputError(fmt::format("cannot open the log file '{}'", path));
  m_logFile = std::move(file);
}

void MoorDynSystem::log(int level, std::string_view text) {
  if (level >= m_verbosity) std::cerr << text << std::flush;
  if (m_logFile.is_open() && level >= m_logLevel) m_logFile << text << std::flush;
}

void MoorDynSystem::initialize(const double* x, const double* xd) {
  if (initialized()) throw InvalidValue("MoorDyn_Init was already called on this system");
  const int n = hostDofCount();
  checkFinite(x, n, "x");
  std::vector<double> hostVelocity(static_cast<std::size_t>(n), 0.0);
  if (xd != nullptr) {
    checkFinite(xd, n, "xd");
    std::copy(xd, xd + n, hostVelocity.begin());
  }
  std::vector<double> position, velocity;
  hostToRun(x, hostVelocity.data(), position, velocity, 0.0, 0.0);
  m_run->initialize(position, velocity);
  m_tangleLines.clear();
  updateHostForces();  // MoorDyn_GetBodyForce after MoorDyn_Init: the forces at the initial state
}

void MoorDynSystem::step(const double* x, const double* xd, double* f, double* t, double dt) {
  requireInitialized();
  const int n = hostDofCount();
  if (n > 0 && f == nullptr) throw InvalidValue(fmt::format("f is NULL ({} coupled DOFs)", n));
  if (std::isnan(dt)) throw InvalidValue("dt is NaN");
  if (dt > 0.0) {
    if (!std::isfinite(dt)) throw InvalidValue("dt is infinite");
    checkFinite(x, n, "x");
    checkFinite(xd, n, "xd");
    std::vector<double> position, velocity;
    hostToRun(x, xd, position, velocity, m_run->time(), dt);
    m_run->step(position, velocity, dt);
    updateHostForces();
  }
  // The objects' forces, then the deck's coupled points' forces.
  std::size_t ix = 0;
  for (const HostObject& h : m_hostObjects) {
    const int written = h.hostValues();
    for (int i = 0; i < written; ++i) f[ix + static_cast<std::size_t>(i)] = h.force[i];
    ix += static_cast<std::size_t>(written);
  }
  const std::vector<double>& forces = m_run->forces();
  if (m_deckCoupledPoints > 0) std::copy(forces.begin(), forces.begin() + 3 * m_deckCoupledPoints, f + ix);
  if (t != nullptr) *t = m_run->time();
}

void MoorDynSystem::updateHostForces() {
  // A rigid object's force and moment about its reference point: the sum over the line ends at its points,
  // and a body's points' own loads.
  const std::vector<double>& forces = m_run->forces();
  const auto runForce = [&](int run) {
    return Vec3(forces[3 * static_cast<std::size_t>(run)], forces[3 * static_cast<std::size_t>(run) + 1],
                forces[3 * static_cast<std::size_t>(run) + 2]);
  };
  const double time = m_run->time();
  for (HostObject& h : m_hostObjects) {
    h.force.setZero();
    if (h.pinned) {
      if (h.runPoint >= 0) h.force.head<3>() = runForce(h.runPoint);
      continue;
    }
    const Vec6 pose = h.pose(time);
    const Vec3 reference = pose.head<3>();
    for (std::size_t j = 0; j < h.runPoints.size(); ++j) {
      if (h.runPoints[j] < 0) continue;
      const Vec3 fp = runForce(h.runPoints[j]);
      h.force.head<3>() += fp;
      h.force.tail<3>() += (m_run->pointPosition(h.runPoints[j]) - reference).cross(fp);
    }
    if (h.pointLoads.empty()) continue;
    analysis::Simulation& sim = m_run->simulation();
    const model::EnvironmentSpec& environment = sim.model().environment();
    const Mat3 rotation = eulerRotation(pose.tail<3>());
    for (const RigidPoint& point : h.pointLoads) {
      const Vec3 at = reference + rotation * point.offset;
      h.force += rigidPointLoads(point, rotation, h.velocity.head<3>(), h.velocity.tail<3>(),
                                 h.acceleration.head<3>(), h.acceleration.tail<3>(),
                                 sim.hydro().fluidAt(at, time, true).velocity, environment.waterDensity,
                                 environment.gravity);
    }
  }
}

Vec6 MoorDynSystem::rigidPointLoads(const RigidPoint& point, const Mat3& rotation, const Vec3& velocity,
                                    const Vec3& angularVelocity, const Vec3& acceleration,
                                    const Vec3& angularAcceleration, const Vec3& fluidVelocity,
                                    double density, double gravity) {
  const Vec3 arm = rotation * point.offset;
  const Vec3 pointVelocity = velocity + angularVelocity.cross(arm);
  const Vec3 pointAcceleration =
      acceleration + angularAcceleration.cross(arm) + angularVelocity.cross(angularVelocity.cross(arm));
  const Vec3 relative = fluidVelocity - pointVelocity;
  const double inertia = point.mass + density * point.volume * point.addedMass;  // [kg]
  const Vec3 force = Vec3(0.0, 0.0, (density * point.volume - point.mass) * gravity) +
                     0.5 * density * point.dragArea * relative.norm() * relative -
                     inertia * pointAcceleration;
  Vec6 out;
  out << force, arm.cross(force);
  return out;
}

int MoorDynSystem::coupledDofCount() const {
  int n = 3 * m_deckCoupledPoints;
  for (const HostObject& h : m_hostObjects) n += h.countedValues();
  return n;
}

int MoorDynSystem::hostDofCount() const {
  int n = 3 * m_deckCoupledPoints;
  for (const HostObject& h : m_hostObjects) n += h.hostValues();
  return n;
}

void MoorDynSystem::hostObjectPoint(const HostObject& c, const Vec3& offset, double t, Vec3& position,
                                    Vec3& velocity) const {
  // The angle rates are taken as the angular velocity (as MoorDyn's setDependentStates).
  const Vec6 s = c.pose(t);
  const Vec3 arm = eulerRotation(s.tail<3>()) * offset;
  position = s.head<3>() + arm;
  velocity = c.velocity.head<3>() + c.velocity.tail<3>().cross(arm);
}

const MoorDynSystem::HostObject* MoorDynSystem::hostObjectOf(int p, Vec3* offset) const {
  for (const HostObject& c : m_hostObjects)
    for (std::size_t j = 0; j < c.points.size(); ++j)
      if (c.points[j] == p) {
        if (offset) *offset = c.offsets[j];
        return &c;
      }
  return nullptr;
}

const MoorDynSystem::HostObject* MoorDynSystem::rigidRod(int r) const {
  for (const HostObject& c : m_hostObjects)
    if (c.rod == r && !c.pinned) return &c;
  return nullptr;
}

void MoorDynSystem::hostToRun(const double* x, const double* xd, std::vector<double>& position,
                              std::vector<double>& velocity, double time0, double dt) {
  position.assign(3 * m_runPoints.size(), 0.0);
  velocity.assign(3 * m_runPoints.size(), 0.0);
  const auto put = [&](int run, const Vec3& p, const Vec3& v) {
    for (int i = 0; i < 3; ++i) {
      position[3 * static_cast<std::size_t>(run) + static_cast<std::size_t>(i)] = p[i];
      velocity[3 * static_cast<std::size_t>(run) + static_cast<std::size_t>(i)] = v[i];
    }
  };
  std::size_t ix = 0;
  for (HostObject& c : m_hostObjects) {
    const int read = c.hostValues();
    for (int i = 0; i < read; ++i) {
      const double v = xd[ix + static_cast<std::size_t>(i)];
      // MoorDyn's MoorDyn::Step: the acceleration is the change of the host's velocity over its step.
      c.acceleration[i] = dt > 0.0 ? (v - c.velocity[i]) / dt : 0.0;
      c.position[i] = x[ix + static_cast<std::size_t>(i)];
      c.velocity[i] = v;
    }
    ix += static_cast<std::size_t>(read);
    c.time0 = time0;
    if (c.pinned) {
      if (c.runPoint >= 0) put(c.runPoint, c.position.head<3>(), c.velocity.head<3>());
      continue;
    }
    for (std::size_t j = 0; j < c.offsets.size(); ++j) {
      if (c.runPoints[j] < 0) continue;
      Vec3 p, v;
      hostObjectPoint(c, c.offsets[j], time0, p, v);
      // Over a step, the chord to where the pose puts the point at its end: the run's points move linearly,
      // and so end each step on the rigid body (no jump into the next step, as a point velocity would
      // leave, dt^2 omega^2 |arm| / 2).
      if (dt > 0.0) {
        Vec3 p1, v1;
        hostObjectPoint(c, c.offsets[j], time0 + dt, p1, v1);
        v = (p1 - p) / dt;
      }
      put(c.runPoints[j], p, v);
    }
  }
  for (std::size_t i = 0; i < 3 * static_cast<std::size_t>(m_deckCoupledPoints); ++i) {
    position[i] = x[ix + i];
    velocity[i] = xd[ix + i];
  }
}

void MoorDynSystem::setTimeStep(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw InvalidValue(fmt::format("the time step must be > 0, not {}", dt));
  if (initialized())
    throw NotImplemented(
        "the time step can only be changed before MoorDyn_Init (the analysis is set up with it)");
  model::DynamicSpec& d = m_coupling.spec.dynamics;
  d.timeStep = dt;
  d.minTimeStep = std::min(d.minTimeStep, dt);
  d.outputInterval = std::max(d.outputInterval, dt);
  if (d.maxTimeStep > 0.0) d.maxTimeStep = std::max(d.maxTimeStep, dt);
  m_run = std::make_unique<analysis::CoupledRun>(m_coupling.spec, m_runPoints);
}

std::string MoorDynSystem::timeSchemeName() const {
  switch (m_coupling.spec.dynamics.integrator) {
    case model::IntegratorKind::GeneralizedAlpha:
      return "generalized_alpha";
    case model::IntegratorKind::Hht:
      return "hht";
    case model::IntegratorKind::Newmark:
      return "newmark";
  }
  return "unknown";
}

LineHandle* MoorDynSystem::line(unsigned int id) {
  if (id < 1 || id > m_lineHandles.size()) return nullptr;
  return m_lineHandles[id - 1].get();
}

RodHandle* MoorDynSystem::rod(unsigned int id) {
  if (id < 1 || id > m_rodHandles.size()) return nullptr;
  return m_rodHandles[id - 1].get();
}

BodyHandle* MoorDynSystem::body(unsigned int id) {
  if (id < 1 || id > m_bodyHandles.size()) return nullptr;
  return m_bodyHandles[id - 1].get();
}

int MoorDynSystem::bodyType(int b) const {
  switch (deckBody(b).kind) {
    case io::MoorDynBodyKind::Free:
      return kBodyFree;
    case io::MoorDynBodyKind::Fixed:
      return kBodyFixed;
    case io::MoorDynBodyKind::Coupled:
      return kBodyCoupled;
    case io::MoorDynBodyKind::CoupledPinned:
      return kBodyCoupledPinned;
  }
  return kBodyFixed;
}

Vec6 MoorDynSystem::bodyForce(int b) const {
  requireInitialized();
  for (const HostObject& c : m_hostObjects)
    if (c.body == b) return c.force;
  throw NotImplemented(
      "a free or fixed body's net force is not exported (a free body's vessel loads are in results.h5); a "
      "coupled body's is what MoorDyn_Step returned");
}

Vec6 MoorDynSystem::rodForce(int r) const {
  requireInitialized();
  for (const HostObject& c : m_hostObjects)
    if (c.rod == r) return c.force;
  throw NotImplemented(
      "a rod's net force is exported for coupled rods only (what MoorDyn_Step returned); a moving rod's "
      "line end forces are in results.h5");
}

Mat6 MoorDynSystem::rigidMass(const std::vector<int>& nodes, const Vec3& reference) {
  analysis::Simulation& sim = m_run->simulation();
  const model::DofMap& dofs = sim.model().dofs();
  const model::State& state = sim.state();
  std::array<VecX, 6> mode, inertia;
  for (int j = 0; j < 6; ++j) {
    mode[static_cast<std::size_t>(j)] = VecX::Zero(dofs.fullDofCount());
    VecX& phi = mode[static_cast<std::size_t>(j)];
    const Vec3 axis = Vec3::Unit(j % 3);
    for (int node : nodes) {
      const int d = dofs.firstDof(node);
      if (j < 3) {
        phi.segment<3>(d) = axis;
      } else {
        phi.segment<3>(d) = axis.cross(state.position[static_cast<std::size_t>(node)] - reference);
        if (dofs.hasRotations(node)) phi.segment<3>(d + 3) = axis;
      }
    }
    inertia[static_cast<std::size_t>(j)] = VecX::Zero(dofs.fullDofCount());
    sim.assembler().addMass(state, 0.0, nullptr, &phi, &inertia[static_cast<std::size_t>(j)]);
  }
  Mat6 m;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      m(i, j) = mode[static_cast<std::size_t>(i)].dot(inertia[static_cast<std::size_t>(j)]);
  return m;
}

Mat6 MoorDynSystem::bodyMass(int b) {
  requireInitialized();
  const io::MoorDynBodyMap& map = m_coupling.conversion.bodies[static_cast<std::size_t>(b)];
  if (map.vessel.empty())
    throw NotImplemented(
        "a fixed or coupled body's mass is not modelled by tangle (the host owns a coupled body's)");
  const model::Model& model = m_run->simulation().model();
  std::vector<int> nodes{model.vesselNode(model.vesselIndex(map.vessel))};
  const int id = deckBody(b).id;
  for (std::size_t r = 0; r < m_coupling.deck.rods.size(); ++r) {
    const io::MoorDynRod& rod = m_coupling.deck.rods[r];
    const std::string& line = m_coupling.conversion.rods[r].tangleLine;
    if (rod.body != id || rod.kind != io::MoorDynRodKind::Fixed || line.empty()) continue;
    const model::Line& l = model.lines()[static_cast<std::size_t>(model.lineIndex(line))];
    for (int i = 0; i < l.nodeCount; ++i) nodes.push_back(l.firstNode + i);
  }
  Vec6 position, velocity;
  bodyState(b, position, velocity);
  return rigidMass(nodes, position.head<3>());
}

Mat6 MoorDynSystem::rodMass(int r) {
  requireInitialized();
  const std::string& line = m_coupling.conversion.rods[static_cast<std::size_t>(r)].tangleLine;
  if (line.empty())
    throw NotImplemented(
        "a fixed, coupled or zero-length rod is not a line in tangle: its mass is not modelled (the host "
        "owns a coupled rod's)");
  const model::Model& model = m_run->simulation().model();
  const model::Line& l = model.lines()[static_cast<std::size_t>(model.lineIndex(line))];
  std::vector<int> nodes;
  for (int i = 0; i < l.nodeCount; ++i) nodes.push_back(l.firstNode + i);
  return rigidMass(nodes, m_run->simulation().state().position[static_cast<std::size_t>(l.firstNode)]);
}

void MoorDynSystem::bodyState(int b, Vec6& position, Vec6& velocity) {
  for (const HostObject& c : m_hostObjects)
    if (c.body == b && !c.pinned) {
      // The host's motion (its angles as given: MoorDyn's XYZ Euler angles).
      position = c.pose(initialized() ? m_run->time() : c.time0);
      velocity = c.velocity;
      return;
    }
  const io::MoorDynBodyMap& map = m_coupling.conversion.bodies[static_cast<std::size_t>(b)];
  Vec3 origin = map.origin;
  Mat3 rotation = map.rotation;
  velocity.setZero();
  if (!map.vessel.empty() && initialized()) {
    const VesselBodyFrame frame = vesselBodyFrame(map);
    origin = frame.origin;
    rotation = frame.rotation;
    velocity.head<3>() = frame.velocityAt(origin);
    velocity.tail<3>() = frame.angularVelocity;
  }
  // MoorDyn's XYZ Euler angles (Misc.hpp, Quat2Euler: canonical angles about x, y, z): R = Rx(a) Ry(b) Rz(c),
  // R(0, 2) = sin b, R(0, 0) = cos b cos c, R(0, 1) = -cos b sin c, R(1, 2) = -sin a cos b, R(2, 2) = cos a
  // cos b.
  position.head<3>() = origin;
  position[3] = std::atan2(-rotation(1, 2), rotation(2, 2));
  position[4] = std::asin(std::clamp(rotation(0, 2), -1.0, 1.0));
  position[5] = std::atan2(-rotation(0, 1), rotation(0, 0));
}

PointHandle* MoorDynSystem::point(unsigned int id) {
  if (id < 1 || id > m_pointHandles.size()) return nullptr;
  return m_pointHandles[id - 1].get();
}

void MoorDynSystem::requireInitialized() const {
  if (!initialized())
    throw InvalidValue("MoorDyn_Init has not been called on this system: there are no results yet");
}

const MoorDynSystem::TangleLine& MoorDynSystem::tangleLine(const std::string& name) {
  requireInitialized();
  if (const auto it = m_tangleLines.find(name); it != m_tangleLines.end()) return it->second;
  const std::vector<solver::LineSnapshot>& results = m_run->lineEnds();  // the names are in either
  const auto found = std::find_if(results.begin(), results.end(),
                                  [&name](const solver::LineSnapshot& s) { return s.name == name; });
  const int modelLine = m_run->simulation().model().lineIndex(name);
  if (found == results.end() || modelLine < 0)
    throw Error(
        fmt::format("{}: the converted model has no results for line '{}' (a bug in tangle)", m_path, name));
  return m_tangleLines[name] = TangleLine{static_cast<int>(found - results.begin()), modelLine};
}

MoorDynSystem::NodeRef MoorDynSystem::deckNode(int l, unsigned int i, bool ends) {
  const io::MoorDynLineMap& map = m_coupling.conversion.lines[static_cast<std::size_t>(l)];
  if (i > static_cast<unsigned int>(map.segments))
    throw InvalidValue(fmt::format("line {} has nodes 0 to {}, not {}", deckLine(l).id, map.segments, i));
  const int offset = static_cast<int>(i);
  const NodeRef n = tangleNode(map.tangleLine, map.firstNode + (map.reversed ? -offset : offset), ends);
  if (n.node < 0 || n.node >= static_cast<int>(n.snapshot->position.size()))
    throw Error(fmt::format(
        "{}: node {} of line {} maps to node {} of tangle line '{}', which has {} (a bug in tangle)", m_path,
        i, deckLine(l).id, n.node, map.tangleLine, n.snapshot->position.size()));
  return n;
}

Vec3 MoorDynSystem::tangleTension(const NodeRef& n, int l) {
  // At an inner node of the deck line the chord through its neighbours; at the deck line's ends its end
  // segment, with that segment's own tension (MoorDyn's Line::getNodeTen).
  const solver::LineSnapshot& s = *n.snapshot;
  const io::MoorDynLineMap& map = m_coupling.conversion.lines[static_cast<std::size_t>(l)];
  const int other = map.firstNode + (map.reversed ? -map.segments : map.segments);
  const int low = std::min(map.firstNode, other);
  const int high = std::max(map.firstNode, other);
  const auto before = static_cast<std::size_t>(n.node == low ? n.node : n.node - 1);
  const auto after = static_cast<std::size_t>(n.node == high ? n.node : n.node + 1);
  const Vec3 chord = s.position[after] - s.position[before];
  const double length = chord.norm();
  if (!(length > 0.0)) return Vec3::Zero();
  if (n.node != low && n.node != high) return s.tension[static_cast<std::size_t>(n.node)] * (chord / length);
  return segmentTension(n, l) * (chord / length);
}

double MoorDynSystem::segmentTension(const NodeRef& n, int l) {
  // The deck line's own end segment, with its own tension. At a junction of two deck lines (a free point
  // inside the tangle line) the node's tension is the mean of the two segments, which differ by the point's
  // load (a buoy's lift): the lines' forces on the point would not balance it.
  const io::MoorDynLineMap& map = m_coupling.conversion.lines[static_cast<std::size_t>(l)];
  const int other = map.firstNode + (map.reversed ? -map.segments : map.segments);
  const int segment = n.node == std::min(map.firstNode, other) ? n.node : n.node - 1;
  // That element alone (a host reading its fairlead tension at every step asks for nothing more).
  analysis::Simulation& sim = m_run->simulation();
  const model::Line& line = sim.model().lines()[static_cast<std::size_t>(n.modelLine)];
  m_oneElement.assign(1, line.firstElement + segment);
  sim.assembler().elementTension(sim.state(), m_elementTension, nullptr, &m_oneElement);
  return m_elementTension[static_cast<std::size_t>(m_oneElement.front())];
}

Vec3 MoorDynSystem::velocity(const NodeRef& n) {
  analysis::Simulation& sim = m_run->simulation();
  const model::Model& model = sim.model();
  const int global = model.lines()[static_cast<std::size_t>(n.modelLine)].firstNode + n.node;
  const Eigen::Index dof = model.dofs().firstDof(global);
  return Vec3(sim.state().velocity.segment<3>(dof));
}

double MoorDynSystem::lineAxialStiffness(int l) const {
  const std::string& type = deckLine(l).lineType;
  for (const io::MoorDynLineType& t : m_coupling.deck.lineTypes)
    if (t.name == type) return t.moorDynStiffness;  // MoorDyn's own: a curve's secant to its last point
  throw Error(fmt::format("{}: line {} has the unknown line type '{}'", m_path, deckLine(l).id, type));
}

Vec3 MoorDynSystem::nodePosition(int l, unsigned int i) {
  const NodeRef n = deckNode(l, i, true);
  return n.snapshot->position[static_cast<std::size_t>(n.node)];
}

Vec3 MoorDynSystem::nodeVelocity(int l, unsigned int i) { return velocity(deckNode(l, i)); }

Vec3 MoorDynSystem::nodeForce(int l, unsigned int i) {
  const NodeRef n = deckNode(l, i);
  if (i == 0) return endForce(l, 0);
  if (i == static_cast<unsigned int>(m_coupling.conversion.lines[static_cast<std::size_t>(l)].segments))
    return endForce(l, 1);
  analysis::Simulation& sim = m_run->simulation();
  const model::Model& model = sim.model();
  const int global = model.lines()[static_cast<std::size_t>(n.modelLine)].firstNode + n.node;
  const Eigen::Index dof = model.dofs().firstDof(global);
  return model.nodeMass()[static_cast<std::size_t>(global)] * Vec3(sim.state().acceleration.segment<3>(dof));
}

Vec3 MoorDynSystem::nodeTension(int l, unsigned int i) {
  // At the deck line's ends the line ends' results (positions) suffice: the end segment's own tension.
  const bool end = i == 0 || i == static_cast<unsigned int>(
                                      m_coupling.conversion.lines[static_cast<std::size_t>(l)].segments);
  const NodeRef n = deckNode(l, i, end);
  const Vec3 t = tangleTension(n, l);
  return m_coupling.conversion.lines[static_cast<std::size_t>(l)].reversed ? Vec3(-t) : t;
}

double MoorDynSystem::nodeCurvature(int l, unsigned int i) {
  const NodeRef n = deckNode(l, i);
  return n.snapshot->curvature[static_cast<std::size_t>(n.node)];
}

double MoorDynSystem::endTension(int l, int end) {
  const auto segments =
      static_cast<unsigned int>(m_coupling.conversion.lines[static_cast<std::size_t>(l)].segments);
  return nodeTension(l, end == 0 ? 0u : segments).norm();
}

double MoorDynSystem::maxTension(int l) {
  // MoorDyn_GetLineMaxTen: nodes 0 to N - 1 (MoorDyn2.cpp), the norm of each node's tension.
  const auto segments =
      static_cast<unsigned int>(m_coupling.conversion.lines[static_cast<std::size_t>(l)].segments);
  double largest = 0.0;
  for (unsigned int i = 0; i < segments; ++i) largest = std::max(largest, nodeTension(l, i).norm());
  return largest;
}

Vec3 MoorDynSystem::endForce(int l, int end) {
  const io::MoorDynLineMap& map = m_coupling.conversion.lines[static_cast<std::size_t>(l)];
  const unsigned int i = end == 0 ? 0u : static_cast<unsigned int>(map.segments);
  const NodeRef n = deckNode(l, i, true);  // the line ends' results suffice
  const solver::LineSnapshot& s = *n.snapshot;
  // A tangle line's end: the force on its holder (oriented A to B of the tangle line, then of the deck line).
  Vec3 tension;
  if (n.node == 0) {
    tension = s.endTensionForceA;
  } else if (n.node == static_cast<int>(s.position.size()) - 1) {
    tension = -s.endTensionForceB;
  } else {
    tension = tangleTension(n, l);  // a junction with another deck line: its end segment's tension
  }
  if (map.reversed) tension = -tension;
  return end == 0 ? tension : Vec3(-tension);
}

int MoorDynSystem::pointType(int p) const {
  switch (pointMap(p).kind) {
    case io::MoorDynPointKind::Coupled:
      return kPointCoupled;
    case io::MoorDynPointKind::Free:
      return kPointFree;
    case io::MoorDynPointKind::Fixed:
    case io::MoorDynPointKind::Body:  // MoorDyn: a point on a body is fixed to it
      return kPointFixed;
  }
  return kPointFixed;
}

Vec3 MoorDynSystem::endNodePosition(const std::pair<std::string, int>& end) {
  const solver::LineSnapshot& s = m_run->lineEnds()[static_cast<std::size_t>(tangleLine(end.first).snapshot)];
  return end.second == 0 ? s.position.front() : s.position.back();
}

MoorDynSystem::NodeRef MoorDynSystem::tangleNode(const std::string& line, int node, bool ends) {
  const TangleLine& t = tangleLine(line);
  NodeRef n;
  n.snapshot = &(ends ? m_run->lineEnds() : m_run->lineResults())[static_cast<std::size_t>(t.snapshot)];
  n.modelLine = t.modelLine;
  n.node = node;
  return n;
}

Vec3 MoorDynSystem::endNodeVelocity(const std::pair<std::string, int>& end) {
  NodeRef n = tangleNode(end.first, 0);
  if (end.second != 0) n.node = static_cast<int>(n.snapshot->position.size()) - 1;
  return velocity(n);
}

Vec3 MoorDynSystem::pointPosition(int p) {
  const io::MoorDynPointMap& map = pointMap(p);
  if (!initialized()) return map.position;
  Vec3 offset, position, velocity;
  if (const HostObject* c = hostObjectOf(p, &offset)) {  // a point on a coupled body: where the host puts it
    hostObjectPoint(*c, offset, m_run->time(), position, velocity);
    return position;
  }
  const int coupled = m_coupledIndex[static_cast<std::size_t>(p)];
  if (coupled >= 0) return m_run->pointPosition(coupled);
  if (freeBodyPoint(p, position, velocity)) return position;
  return mappedPosition(map);
}

bool MoorDynSystem::freeBodyPoint(int p, Vec3& position, Vec3& velocity) {
  const io::MoorDynPoint& point = m_coupling.deck.points[static_cast<std::size_t>(p)];
  if (!initialized() || point.kind != io::MoorDynPointKind::Body || !pointMap(p).ends.empty()) return false;
  const io::MoorDynBodyMap& body = m_coupling.conversion.bodies[static_cast<std::size_t>(point.body - 1)];
  if (body.vessel.empty()) return false;
  const VesselBodyFrame frame = vesselBodyFrame(body);
  position = frame.origin + frame.rotation * point.position;
  velocity = frame.velocityAt(position);
  return true;
}

MoorDynSystem::VesselBodyFrame MoorDynSystem::vesselBodyFrame(const io::MoorDynBodyMap& map) const {
  const model::Model& model = m_run->simulation().model();
  const model::State& state = m_run->simulation().state();
  const int node = model.vesselNode(model.vesselIndex(map.vessel));
  const Mat3& q = state.triad[static_cast<std::size_t>(node)];
  const int dof = model.dofs().firstDof(node);
  VesselBodyFrame frame;
  frame.nodePosition = state.position[static_cast<std::size_t>(node)];
  frame.nodeVelocity = state.velocity.segment<3>(dof);
  frame.angularVelocity = state.velocity.segment<3>(dof + 3);
  frame.origin = frame.nodePosition + q * (map.origin - map.reference);
  frame.rotation = q * map.rotation;
  return frame;
}

Vec3 MoorDynSystem::mappedPosition(const io::MoorDynPointMap& map) {
  if (!initialized()) return map.position;
  if (!map.ends.empty()) return endNodePosition(map.ends.front());
  if (!map.junctionLine.empty()) {
    const solver::LineSnapshot& s =
        m_run->lineEnds()[static_cast<std::size_t>(tangleLine(map.junctionLine).snapshot)];
    return s.position.at(static_cast<std::size_t>(map.junctionNode));
  }
  return map.position;  // a point no line is attached to
}

Vec3 MoorDynSystem::pointVelocity(int p) {
  const io::MoorDynPointMap& map = pointMap(p);
  if (!initialized()) return Vec3::Zero();
  Vec3 offset, position, velocity;
  if (const HostObject* c = hostObjectOf(p, &offset)) {  // MoorDyn's Body::setDependentStates: v + w x r
    hostObjectPoint(*c, offset, m_run->time(), position, velocity);
    return velocity;
  }
  const int coupled = m_coupledIndex[static_cast<std::size_t>(p)];
  if (coupled >= 0) return m_run->pointVelocity(coupled);
  if (freeBodyPoint(p, position, velocity)) return velocity;
  if (map.kind == io::MoorDynPointKind::Fixed) return Vec3::Zero();
  return mappedVelocity(map);
}

Vec3 MoorDynSystem::mappedVelocity(const io::MoorDynPointMap& map) {
  if (!initialized() || map.kind == io::MoorDynPointKind::Fixed) return Vec3::Zero();
  if (!map.ends.empty()) return endNodeVelocity(map.ends.front());
  if (!map.junctionLine.empty()) return velocity(tangleNode(map.junctionLine, map.junctionNode));
  return Vec3::Zero();
}

int MoorDynSystem::rodType(int r) const {
  switch (deckRod(r).kind) {
    case io::MoorDynRodKind::Fixed:
      return kRodFixed;
    case io::MoorDynRodKind::Pinned:
      return kRodPinned;
    case io::MoorDynRodKind::Free:
      return kRodFree;
    case io::MoorDynRodKind::Coupled:
      return kRodCoupled;
    case io::MoorDynRodKind::CoupledPinned:
      return kRodCoupledPinned;
  }
  return kRodFixed;
}

Vec3 MoorDynSystem::rodNodePosition(int r, unsigned int i) {
  const io::MoorDynRod& rod = deckRod(r);
  if (i > static_cast<unsigned int>(rod.segments))
    throw InvalidValue(fmt::format("rod {} has nodes 0 to {}, not {}", rod.id, rod.segments, i));
  const io::MoorDynRodMap& map = m_coupling.conversion.rods[static_cast<std::size_t>(r)];
  if (rod.segments == 0) return mappedPosition(map.point);
  const Vec3 along = (rod.endB - rod.endA) * (static_cast<double>(i) / rod.segments);
  if (const HostObject* c = initialized() ? rigidRod(r) : nullptr) {  // a Coupled rod, moved by the host
    Vec3 position, velocity;
    hostObjectPoint(*c, along, m_run->time(), position, velocity);
    return position;
  }
  if (map.tangleLine.empty() || !initialized()) {
    // Where the deck puts it: a rod on a body has its ends in the body's axes from its reference point.
    if (rod.body == 0) return rod.endA + along;
    const io::MoorDynBodyMap& body = m_coupling.conversion.bodies[static_cast<std::size_t>(rod.body - 1)];
    return body.origin + body.rotation * Vec3(rod.endA + along);
  }
  const solver::LineSnapshot& s =
      m_run->lineEnds()[static_cast<std::size_t>(tangleLine(map.tangleLine).snapshot)];
  return s.position.at(i);
}

Vec3 MoorDynSystem::rodNodeVelocity(int r, unsigned int i) {
  const io::MoorDynRod& rod = deckRod(r);
  if (i > static_cast<unsigned int>(rod.segments))
    throw InvalidValue(fmt::format("rod {} has nodes 0 to {}, not {}", rod.id, rod.segments, i));
  const io::MoorDynRodMap& map = m_coupling.conversion.rods[static_cast<std::size_t>(r)];
  if (rod.segments == 0) return mappedVelocity(map.point);
  if (const HostObject* c = initialized() ? rigidRod(r) : nullptr) {
    Vec3 position, velocity;
    hostObjectPoint(*c, (rod.endB - rod.endA) * (static_cast<double>(i) / rod.segments), m_run->time(),
                    position, velocity);
    return velocity;
  }
  if (map.tangleLine.empty() || !initialized()) return Vec3::Zero();
  return velocity(tangleNode(map.tangleLine, static_cast<int>(i)));
}

Vec3 MoorDynSystem::pointForce(int p) {
  requireInitialized();
  const int coupled = m_coupledIndex[static_cast<std::size_t>(p)];
  if (coupled >= 0) {
    const std::vector<double>& f = m_run->forces();
    const auto k = static_cast<std::size_t>(3 * coupled);
    return Vec3(f[k], f[k + 1], f[k + 2]);
  }
  Vec3 sum = Vec3::Zero();
  for (const auto& [deckId, end] : pointMap(p).attachedLines) sum += endForce(deckId - 1, end);
  return sum;
}

int MoorDynSystem::waveKinematicsPointCount() const {
  const auto& options = m_coupling.deck.options;
  const bool external = std::any_of(options.begin(), options.end(), [](const io::MoorDynOption& o) {
    std::string name = o.name;
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
    return name == "wavekin" && io::deckNumber(o.value) == 1.0;
  });
  if (!external) return 0;
  // MoorDyn's Waves::kinematicsForAllNodes: lines' nodes, rods' nodes, points, bodies (the ground body
  // first).
  int n = static_cast<int>(m_coupling.deck.points.size() + m_coupling.deck.bodies.size()) + 1;
  for (const io::MoorDynLine& l : m_coupling.deck.lines) n += l.segments + 1;
  for (const io::MoorDynRod& r : m_coupling.deck.rods) n += r.segments + 1;
  return n;
}

std::vector<double> MoorDynSystem::waveKinematicsPoints() {
  requireInitialized();
  std::vector<double> r;
  if (waveKinematicsPointCount() == 0) return r;
  const auto put = [&r](const Vec3& x) { r.insert(r.end(), {x.x(), x.y(), x.z()}); };
  for (int l = 0; l < lineCount(); ++l)
    for (int i = 0; i <= deckLine(l).segments; ++i) put(nodePosition(l, static_cast<unsigned int>(i)));
  for (int k = 0; k < rodCount(); ++k)
    for (int i = 0; i <= deckRod(k).segments; ++i) put(rodNodePosition(k, static_cast<unsigned int>(i)));
  for (int p = 0; p < pointCount(); ++p) put(pointPosition(p));
  put(Vec3::Zero());  // MoorDyn's ground body, at the origin
  for (int b = 0; b < bodyCount(); ++b) {
    Vec6 position, velocity;
    bodyState(b, position, velocity);
    put(position.head<3>());
  }
  return r;
}

void MoorDynSystem::setWaveKinematics(const double* U, const double* Ud) {
  requireInitialized();
  const int n = waveKinematicsPointCount();
  if (n == 0)
    throw InvalidValue(fmt::format("{}: the deck does not take its wave kinematics from the host (option WaveKin 1)",
                                   m_path));
  if (U == nullptr || Ud == nullptr) throw InvalidValue("U and Ud must not be NULL");
  for (int k = 0; k < 3 * n; ++k)
    if (!std::isfinite(U[k]) || !std::isfinite(Ud[k]))
      throw InvalidValue(fmt::format("the wave kinematics of point {} are not finite numbers", k / 3));
  const model::Model& model = m_run->simulation().model();
  const std::size_t nodes = static_cast<std::size_t>(model.nodeCount());
  std::vector<Vec3> velocity(nodes, Vec3::Zero()), acceleration(nodes, Vec3::Zero());
  std::vector<int> count(nodes, 0);
  int k = 0;
  const auto add = [&](const NodeRef& ref) {
    const auto global =
        static_cast<std::size_t>(model.lines()[static_cast<std::size_t>(ref.modelLine)].firstNode + ref.node);
    velocity[global] += Vec3(U[3 * k], U[3 * k + 1], U[3 * k + 2]);
    acceleration[global] += Vec3(Ud[3 * k], Ud[3 * k + 1], Ud[3 * k + 2]);
    ++count[global];
  };
  for (int l = 0; l < lineCount(); ++l)
    for (int i = 0; i <= deckLine(l).segments; ++i, ++k) add(deckNode(l, static_cast<unsigned int>(i)));
  for (int r = 0; r < rodCount(); ++r) {
    // A moving rod is a tangle line with the rod's nodes; a held or zero-length rod is not in the model.
    const std::string& line = m_coupling.conversion.rods[static_cast<std::size_t>(r)].tangleLine;
    for (int i = 0; i <= deckRod(r).segments; ++i, ++k)
      if (!line.empty() && deckRod(r).segments > 0) add(tangleNode(line, i));
  }
  for (std::size_t g = 0; g < nodes; ++g)
    if (count[g] > 1) {
      velocity[g] /= count[g];
      acceleration[g] /= count[g];
    }
  m_run->simulation().hydro().setNodeKinematics(std::move(velocity), std::move(acceleration));
}

}  // namespace tangle::capi
