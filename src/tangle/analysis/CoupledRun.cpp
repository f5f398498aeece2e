#include "tangle/analysis/CoupledRun.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <limits>

#include "tangle/core/Error.hpp"

namespace tangle::analysis {

/// The host's kinematics of the coupled points over its current step: position x0 at time t0 and a
/// constant velocity (MoorDyn2.cpp, Step: the coupled points move as x + xd (t - t0) within a step).
struct CoupledRun::HostMotion {
  std::vector<Vec3> start;     ///< [m]
  std::vector<Vec3> velocity;  ///< [m/s]
  /// The change of the host's velocity over its last step divided by it [m/s^2] (MoorDyn's estimate for its
  /// coupled bodies and rods, MoorDyn2.cpp Step): the held nodes' acceleration, so that the force on the host
  /// carries their inertia (the position stays linear over the step).
  std::vector<Vec3> acceleration;
  double t0 = 0.0;  ///< [s]
  Vec3 at(int point, double t) const {
    return start[static_cast<std::size_t>(point)] + velocity[static_cast<std::size_t>(point)] * (t - t0);
  }
};

CoupledRun::CoupledRun(model::ModelSpec spec, std::vector<CoupledPointSpec> points)
    : m_spec(std::move(spec)), m_points(std::move(points)), m_motion(std::make_shared<HostMotion>()) {
  const std::string& file = m_spec.sourceFile;
  for (std::size_t p = 0; p < m_points.size(); ++p) {
    const CoupledPointSpec& point = m_points[p];
    const int first = static_cast<int>(m_ends.size());
    m_vesselOfPoint.push_back(-1);
    if (!point.vessel.empty()) {
      const std::string key = fmt::format("coupled point {}: vessel {}", point.name, point.vessel);
      const auto it = std::find_if(m_spec.vessels.begin(), m_spec.vessels.end(),
                                   [&](const model::VesselSpec& v) { return v.name == point.vessel; });
      if (it == m_spec.vessels.end()) throw InputError(file, 0, key, "no vessel of that name");
      if (it->mode != model::VesselMode::Free || !it->pinned)
        throw InputError(file, it->sourceLine, key,
                         "a host moves a vessel's reference point only when it is free and pinned (its "
                         "rotations solved)");
      if (!point.ends.empty())
        throw InputError(file, 0, key, "a coupled vessel point holds no line ends (they are on the vessel)");
      for (int q : m_vesselOfPoint)
        if (q == static_cast<int>(it - m_spec.vessels.begin()))
          throw InputError(file, it->sourceLine, key, "this vessel is in two coupled points");
      m_vesselOfPoint.back() = static_cast<int>(it - m_spec.vessels.begin());
      m_pointOfEnd.push_back({first, first});
      continue;
    }
    if (point.ends.empty())
      throw InputError(file, 0, fmt::format("coupled point {}", point.name),
                       "a coupled point needs at least one line end");
    for (const auto& [lineName, end] : point.ends) {
      const std::string key =
          fmt::format("coupled point {}: {} end {}", point.name, lineName, end == 0 ? "a" : "b");
      int line = -1;
      for (std::size_t l = 0; l < m_spec.lines.size(); ++l)
        if (m_spec.lines[l].name == lineName) line = static_cast<int>(l);
      if (line < 0) throw InputError(file, 0, key, fmt::format("no line named '{}'", lineName));
      if (end != 0 && end != 1) throw InputError(file, 0, key, "expected end a (0) or b (1)");
      const model::EndSpec& e = end == 0 ? m_spec.lines[static_cast<std::size_t>(line)].endA
                                         : m_spec.lines[static_cast<std::size_t>(line)].endB;
      if (e.kind != model::EndKind::Anchored && e.kind != model::EndKind::Pinned &&
          e.kind != model::EndKind::Fixed)
        throw InputError(file, e.sourceLine, key,
                         "a coupled end must be held (type anchored, pinned or fixed): the host moves it");
      if (e.motion.enabled)
        throw InputError(file, e.sourceLine, key, "a coupled end must not have a motion of its own");
      for (const auto& [l2, e2] : m_ends)
        if (l2 == line && e2 == end)
          throw InputError(file, e.sourceLine, key, "this end is in two coupled points");
      m_ends.push_back({line, end});
      m_endPoint.push_back(static_cast<int>(p));
    }
    m_pointOfEnd.push_back({first, static_cast<int>(m_ends.size())});
  }
  m_forces.assign(3 * m_points.size(), 0.0);
  m_motion->start.assign(m_points.size(), Vec3::Zero());
  m_motion->velocity.assign(m_points.size(), Vec3::Zero());
  m_motion->acceleration.assign(m_points.size(), Vec3::Zero());
  const std::vector<double> x = modelPositions();
  for (std::size_t p = 0; p < m_points.size(); ++p)
    m_motion->start[p] = Vec3(x[3 * p], x[3 * p + 1], x[3 * p + 2]);
}

CoupledRun::~CoupledRun() {
  if (m_dynamics && m_simulation) {
    try {
      m_dynamics->finish(m_simulation->state());
    } catch (const std::exception& e) {
      std::cerr << "tangle: closing the coupled run: " << e.what() << "\n";
    }
  }
}

std::vector<double> CoupledRun::modelPositions() const {
  std::vector<double> out;
  for (std::size_t p = 0; p < m_points.size(); ++p) {
    Vec3 x;
    if (m_vesselOfPoint[p] >= 0) {
      x = m_spec.vessels[static_cast<std::size_t>(m_vesselOfPoint[p])].position;
    } else {
      const auto [line, end] = m_ends[static_cast<std::size_t>(m_pointOfEnd[p].first)];
      const model::LineSpec& ls = m_spec.lines[static_cast<std::size_t>(line)];
      x = end == 0 ? ls.endA.position : ls.endB.position;
    }
    out.insert(out.end(), {x.x(), x.y(), x.z()});
  }
  return out;
}

void CoupledRun::setHostMotion(std::span<const double> x, std::span<const double> xd, double t0, double dt) {
  const std::size_t n = 3 * m_points.size();
  if (x.size() != n || xd.size() != n)
    throw InputError(m_spec.sourceFile, 0, "coupled points",
                     fmt::format("expected {} positions and velocities (3 per coupled point), got {} and {}",
                                 n, x.size(), xd.size()));
  for (std::size_t p = 0; p < m_points.size(); ++p) {
    const Vec3 velocity(xd[3 * p], xd[3 * p + 1], xd[3 * p + 2]);
    m_motion->acceleration[p] = dt > 0.0 ? Vec3((velocity - m_motion->velocity[p]) / dt) : Vec3::Zero();
    m_motion->start[p] = Vec3(x[3 * p], x[3 * p + 1], x[3 * p + 2]);
    m_motion->velocity[p] = velocity;
    if (!m_motion->start[p].allFinite() || !m_motion->velocity[p].allFinite() ||
        !m_motion->acceleration[p].allFinite())
      throw InputError(m_spec.sourceFile, 0, fmt::format("coupled point {}", m_points[p].name),
                       "the host gave a position or velocity that is not a finite number");
  }
  m_motion->t0 = t0;
}

void CoupledRun::initialize(std::span<const double> x, std::span<const double> xd) {
  if (m_simulation) throw Error("CoupledRun::initialize: the run is initialised already");
  setHostMotion(x, xd, 0.0, 0.0);
  model::ModelSpec spec = m_spec;
  for (std::size_t k = 0; k < m_ends.size(); ++k) {
    const auto [line, end] = m_ends[k];
    model::EndSpec& e = end == 0 ? spec.lines[static_cast<std::size_t>(line)].endA
                                 : spec.lines[static_cast<std::size_t>(line)].endB;
    e.position = m_motion->start[static_cast<std::size_t>(m_endPoint[k])];
  }
  for (std::size_t p = 0; p < m_points.size(); ++p)
    if (m_vesselOfPoint[p] >= 0)
      spec.vessels[static_cast<std::size_t>(m_vesselOfPoint[p])].position = m_motion->start[p];
  auto simulation = std::make_unique<Simulation>(std::move(spec));
  const solver::StaticResult statics = simulation->solveStatics();
  if (!statics.converged)
    throw ConvergenceError(
        fmt::format("the static analysis at the coupled points' initial positions did not converge: {}",
                    statics.message));
  // The host decides the duration: the run has none of its own, nor output times.
  model::DynamicSpec settings = simulation->model().spec().dynamics;
  settings.duration = std::numeric_limits<double>::max();
  settings.outputInterval = std::numeric_limits<double>::max();
  auto dynamics = std::make_unique<time::DynamicAnalysis>(simulation->assembler(), settings);
  if (simulation->vessels()) dynamics->addPrescribed(simulation->vessels()->prescribedNodes());
  std::vector<model::PrescribedNode> held;
  const model::Model& model = simulation->model();
  // A held node that follows coupled point `point`: its position linear over the host's step.
  const auto follow = [&](int node, int point) {
    const Vec3 base = m_motion->start[static_cast<std::size_t>(point)];
    std::shared_ptr<const HostMotion> motion = m_motion;
    held.push_back({node, base, [motion, point, base](double t) {
                      model::MotionValue v;
                      v.displacement = motion->at(point, t) - base;
                      v.velocity = motion->velocity[static_cast<std::size_t>(point)];
                      v.acceleration = motion->acceleration[static_cast<std::size_t>(point)];
                      return v;
                    }});
  };
  for (std::size_t k = 0; k < m_ends.size(); ++k) {
    const auto [line, end] = m_ends[k];
    const model::Line& ml = model.lines()[static_cast<std::size_t>(line)];
    follow(end == 0 ? ml.firstNode : ml.lastNode(), m_endPoint[k]);
  }
  // A pinned vessel's reference point: its translations follow the host, its rotations are solved.
  for (std::size_t p = 0; p < m_points.size(); ++p)
    if (m_vesselOfPoint[p] >= 0) follow(model.vesselNode(m_vesselOfPoint[p]), static_cast<int>(p));
  dynamics->addPrescribed(std::move(held));
  m_simulation = std::move(simulation);
  m_dynamics = std::move(dynamics);
  m_dynamics->start(m_simulation->state());
  refreshResults(false);
}

void CoupledRun::step(std::span<const double> x, std::span<const double> xd, double dt) {
  if (!m_simulation) throw Error("CoupledRun::step: initialize the run first");
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw InputError(m_spec.sourceFile, 0, "dt", fmt::format("expected a time step > 0, got {}", dt));
  model::State& state = m_simulation->state();
  setHostMotion(x, xd, state.time, dt);
  if (!m_dynamics->advance(state, state.time + dt)) throw ConvergenceError(m_dynamics->result().message);
  refreshResults(true);
}

double CoupledRun::time() const { return m_simulation ? m_simulation->state().time : 0.0; }

Vec3 CoupledRun::pointPosition(int point) const { return m_motion->at(point, time()); }

Vec3 CoupledRun::pointVelocity(int point) const {
  return m_motion->velocity[static_cast<std::size_t>(point)];
}

Simulation& CoupledRun::simulation() {
  if (!m_simulation) throw Error("CoupledRun::simulation: initialize the run first");
  return *m_simulation;
}

const std::vector<solver::LineSnapshot>& CoupledRun::lineResults() {
  if (!m_linesCurrent && m_simulation) {
    m_simulation->lineResults(m_supportForce, m_dynamicResults, m_lines);
    m_linesCurrent = true;
  }
  return m_lines;
}

const std::vector<solver::LineSnapshot>& CoupledRun::lineEnds() {
  if (m_linesCurrent) return m_lines;
  if (!m_endsCurrent && m_simulation) {
    m_simulation->lineResults(m_supportForce, m_dynamicResults, m_endResults, solver::LineResultDetail::Ends);
    m_endsCurrent = true;
  }
  return m_endResults;
}

void CoupledRun::refreshResults(bool dynamic) {
  // The line results are formed when asked for (lineResults, lineEnds); the forces on the host are the
  // support reactions at the coupled ends.
  m_simulation->supportForce(dynamic, m_supportForce);
  m_dynamicResults = dynamic;
  m_linesCurrent = false;
  m_endsCurrent = false;
  const model::Model& model = m_simulation->model();
  std::fill(m_forces.begin(), m_forces.end(), 0.0);
  for (std::size_t k = 0; k < m_ends.size(); ++k) {
    const auto [line, end] = m_ends[k];
    const model::Line& ml = model.lines()[static_cast<std::size_t>(line)];
    // The force the line exerts on its support (LineSnapshot::endForceA/B, minus the support's reaction on
    // the line): on the host.
    const Eigen::Index dof = model.dofs().firstDof(end == 0 ? ml.firstNode : ml.lastNode());
    for (int i = 0; i < 3; ++i)
      m_forces[3 * static_cast<std::size_t>(m_endPoint[k]) + i] -= m_supportForce[dof + i];
  }
  if (std::all_of(m_vesselOfPoint.begin(), m_vesselOfPoint.end(), [](int v) { return v < 0; })) return;
  // A pinned vessel: the out-of-balance force at its held translations (body loads, its lines' links, its
  // inertia M a) is its support's reaction; the vessel pushes on the host with its opposite (MoorDyn's
  // Body::getFnet of a CoupledPinned body: F6net - M a, translations).
  const model::State& state = m_simulation->state();
  solver::AssemblyRequest request;
  request.wantMatrix = false;
  request.dynamic = dynamic;
  request.time = state.time;
  VecX force;
  m_simulation->assembler().assemble(state, request, force, nullptr);
  if (dynamic) {
    VecX inertia = VecX::Zero(force.size());
    m_simulation->assembler().addMass(state, 0.0, nullptr, &state.acceleration, &inertia);
    force += inertia;
  }
  for (std::size_t p = 0; p < m_points.size(); ++p) {
    if (m_vesselOfPoint[p] < 0) continue;
    const int d = model.dofs().firstDof(model.vesselNode(m_vesselOfPoint[p]));
    for (int i = 0; i < 3; ++i) m_forces[3 * p + static_cast<std::size_t>(i)] = -force[d + i];
  }
}

}  // namespace tangle::analysis
