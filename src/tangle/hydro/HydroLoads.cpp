#include "tangle/hydro/HydroLoads.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "tangle/core/Error.hpp"
#include "tangle/core/ForEachIndex.hpp"
#include "tangle/core/PendingSum.hpp"
#include "tangle/core/Ramp.hpp"
#include "tangle/hydro/AiryWave.hpp"
#include "tangle/hydro/ComponentSea.hpp"
#include "tangle/hydro/JonswapSea.hpp"
#include "tangle/hydro/Morison.hpp"

namespace tangle::hydro {

namespace {
Stretching stretchingOf(model::WaveStretching s) {
  switch (s) {
    case model::WaveStretching::None: return Stretching::None;
    case model::WaveStretching::Extrapolation: return Stretching::Vertical;
    case model::WaveStretching::Wheeler: break;
  }
  return Stretching::Wheeler;
}
}  // namespace

std::unique_ptr<WaveField> makeWaveField(const model::EnvironmentSpec& env) {
  const model::WaveSpec& w = env.waves;
  switch (w.kind) {
    case model::WaveKind::None:
      return nullptr;
    case model::WaveKind::Airy:
      return std::make_unique<AiryWave>(w.height, w.period, w.azimuth, env.waterDepth, env.gravity, w.phase,
                                        stretchingOf(w.stretching));
    case model::WaveKind::Jonswap: {
      JonswapSea::Parameters p;
      p.significantHeight = w.significantHeight;
      p.peakPeriod = w.peakPeriod;
      p.gamma = w.gamma;
      p.azimuth = w.azimuth;
      p.waterDepth = env.waterDepth;
      p.gravity = env.gravity;
      p.componentCount = w.components;
      p.seed = w.seed;
      p.stretching = stretchingOf(w.stretching);
      return std::make_unique<JonswapSea>(p);
    }
    case model::WaveKind::Components: {
      std::vector<ComponentSea::Component> components;
      for (const auto& [period, amplitude, phase, azimuth] : w.componentTable)
        components.push_back({2.0 * kPi / period, amplitude, phase, azimuth});
      return std::make_unique<ComponentSea>(std::move(components), env.waterDepth, env.gravity,
                                            stretchingOf(w.stretching));
    }
  }
  return nullptr;
}

CurrentProfile makeCurrentProfile(const std::vector<model::CurrentLevel>& current) {
  if (current.empty()) return CurrentProfile();
  std::vector<CurrentLevel> levels;
  for (const model::CurrentLevel& c : current) levels.push_back({c.z, c.speed, c.azimuth});
  return CurrentProfile(levels);
}

CurrentProfile makeCurrentProfile(const model::EnvironmentSpec& env) {
  if (env.currentGrid) return CurrentProfile::withGrid(env.currentGrid);
  if (env.currentHistory.empty()) return makeCurrentProfile(env.current);
  std::vector<double> times;
  std::vector<CurrentProfile> profiles;
  for (const model::CurrentSnapshot& s : env.currentHistory) {
    times.push_back(s.time);
    profiles.push_back(makeCurrentProfile(s.levels));
  }
  return CurrentProfile::withHistory(std::move(times), std::move(profiles));
}

HydroLoads::HydroLoads(const model::Model& model)
    : m_model(&model),
      m_current(makeCurrentProfile(model.environment())),
      m_waves(makeWaveField(model.environment())),
      m_rampTime(model.spec().dynamics.rampTime) {
  const std::size_t n = model.elements().size();
  m_fluid.resize(n);
  m_surface.assign(n, 0.0);
  m_addedMass.assign(n, AddedMass{});
  std::vector<const section::LineType*> types;
  m_coefficientIndex.reserve(n);
  for (const model::LineElement& el : model.elements()) {
    const auto index = static_cast<int>(std::find(types.begin(), types.end(), el.type) - types.begin());
    if (index == static_cast<int>(types.size())) {
      types.push_back(el.type);
      m_coefficients.push_back(morisonCoefficients(*el.type, model.environment().waterDensity));
    }
    m_coefficientIndex.push_back(index);
  }
  if (!model.spec().wakes.empty()) {
    m_wake = std::make_unique<WakeInterference>(model, m_current);
    if (m_wake->empty()) m_wake.reset();
  }
}

double HydroLoads::surfaceAt(double x, double y, double t, bool dynamic) const {
  if (!dynamic || !m_waves) return 0.0;
  return core::ramp(t, m_rampTime).value * m_waves->elevation(x, y, t);
}

FluidKinematics HydroLoads::fluidAt(const Vec3& p, double t, bool dynamic) const {
  FluidKinematics k;
  k.velocity = m_current.velocity(p, t);
  if (dynamic && m_waves) {
    const double r = core::ramp(t, m_rampTime).value;
    if (r > 0.0) {
      const FluidKinematics w = m_waves->kinematics(p, t);
      k.velocity += r * w.velocity;
      k.acceleration += r * w.acceleration;
    }
  }
  return k;
}

void HydroLoads::setNodeKinematics(std::vector<Vec3> velocity, std::vector<Vec3> acceleration) {
  const std::size_t n = static_cast<std::size_t>(m_model->nodeCount());
  if (velocity.size() != n || acceleration.size() != n)
    throw Error(fmt::format("wave kinematics for {} and {} nodes given to a model of {} nodes", velocity.size(),
                            acceleration.size(), n));
  m_nodeVelocity = std::move(velocity);
  m_nodeAcceleration = std::move(acceleration);
  m_cacheTime = -1e300;  // the elements' kinematics are refilled
}

void HydroLoads::clearNodeKinematics() {
  m_nodeVelocity.clear();
  m_nodeAcceleration.clear();
  m_cacheTime = -1e300;
}

bool HydroLoads::prepareWaves(const model::State& state, const solver::AssemblyRequest& request) {
  if (!m_nodeVelocity.empty()) {
    if (!(request.dynamic && request.waves)) return false;
    if (m_cacheTime != -2e300) {  // filled once per setNodeKinematics
      const auto& elements = m_model->elements();
      for (std::size_t e = 0; e < elements.size(); ++e) {
        const auto n1 = static_cast<std::size_t>(elements[e].node1), n2 = static_cast<std::size_t>(elements[e].node2);
        m_surface[e] = 0.0;
        m_fluid[e].velocity = 0.5 * (m_nodeVelocity[n1] + m_nodeVelocity[n2]);
        m_fluid[e].acceleration = 0.5 * (m_nodeAcceleration[n1] + m_nodeAcceleration[n2]);
      }
      m_cacheTime = -2e300;
    }
    return true;
  }
  const bool waves = request.dynamic && request.waves && m_waves && core::ramp(request.time, m_rampTime).value > 0.0;
  if (waves && (request.time != m_cacheTime || !m_cacheDynamic)) {
    // Wave kinematics (the costly part) once per time value; the current is cheap and is evaluated
    // at the current midpoint every call.
    const auto& elements = m_model->elements();
    const double r = core::ramp(request.time, m_rampTime).value;
    for (std::size_t e = 0; e < elements.size(); ++e) {
      const Vec3 mid = 0.5 * (state.position[elements[e].node1] + state.position[elements[e].node2]);
      double eta = 0.0;
      const FluidKinematics w = m_waves->kinematics(mid, request.time, eta);
      m_surface[e] = r * eta;
      m_fluid[e].velocity = r * w.velocity;
      m_fluid[e].acceleration = r * w.acceleration;
    }
    m_cacheTime = request.time;
    m_cacheDynamic = true;
  }
  return waves;
}

void HydroLoads::addForces(const model::State& state, const solver::AssemblyRequest& request, VecX& force,
                           solver::SystemMatrix* matrix) {
  const bool waves = prepareWaves(state, request);
  if (m_wake) m_wake->evaluate(state, m_model->environment().waterDensity, m_elementWake);
  addElementForces(state, request, waves, force, matrix, nullptr);
  addAttachmentDrag(state, request, force, matrix, nullptr);
}

void HydroLoads::addPartForces(const model::State& state, const solver::AssemblyRequest& request,
                               const solver::AssemblyPart& part, VecX& force, solver::SystemMatrix* matrix) {
  const bool waves = prepareWaves(state, request);
  addElementForces(state, request, waves, force, matrix, &part.elements);
  addAttachmentDrag(state, request, force, matrix, &part.attachments);
}

void HydroLoads::addElementForces(const model::State& state, const solver::AssemblyRequest& request,
                                  bool waves, VecX& force, solver::SystemMatrix* matrix,
                                  const std::vector<int>* list) {
  const auto& elements = m_model->elements();
  const model::DofMap& dofs = m_model->dofs();
  const double rho = m_model->environment().waterDensity;
  const Vec3 zero = Vec3::Zero();
  const bool wantDamping = matrix && request.dynamic && request.cf != 0.0;
  forEachIndex(list, elements.size(), [&](std::size_t e) {
    const model::LineElement& el = elements[e];
    const Vec3& x1 = state.position[el.node1];
    const Vec3& x2 = state.position[el.node2];
    const double wet = submergedFraction(x1.z(), x2.z(), waves ? m_surface[e] : 0.0);
    // A parted element (lines[].failure) is no longer a cylinder between its nodes: its two halves hang at
    // the new ends as point masses, without drag or added mass (docs/theory.md 8.7).
    if (wet <= 0.0 || m_model->parted().parted(e, state.time)) {
      m_addedMass[e] = AddedMass{};
      return;
    }
    const int d1 = dofs.firstDof(el.node1);
    const int d2 = dofs.firstDof(el.node2);
    const Vec3 v1 = request.dynamic ? Vec3(state.velocity.segment<3>(d1)) : zero;
    const Vec3 v2 = request.dynamic ? Vec3(state.velocity.segment<3>(d2)) : zero;
    FluidKinematics fluid;
    fluid.velocity = m_current.velocity(0.5 * (x1 + x2), request.time);
    if (m_wake) fluid.velocity += m_elementWake[e].velocityChange;
    if (!request.dynamic) fluid.velocity *= request.currentFactor;  // the statics' current continuation
    if (waves) {
      fluid.velocity += m_fluid[e].velocity;
      fluid.acceleration = m_fluid[e].acceleration;
    }
    const bool wakeTangent = m_wake && matrix && m_wake->isDownstream(static_cast<int>(e));
    const bool wantStiffness = matrix && request.dragStiffness;
    const MorisonCoefficients& coefficients = m_coefficients[static_cast<std::size_t>(m_coefficientIndex[e])];
    if (!coefficients.wet) {
      m_addedMass[e] = AddedMass{};
      return;
    }
    // Out-of-balance convention: external loads are subtracted. (The matrices' call only when a matrix is
    // assembled.)
    const MorisonNodeForces forces = morisonNodeForces(x1, x2, v1, v2, fluid, coefficients, wet);
    force.segment<3>(d1) -= forces.force1;
    force.segment<3>(d2) -= forces.force2;
    m_addedMass[e] = forces.addedMassPerNode;
    // The wake's lift comes from the full steady current (WakeInterference): in statics it is scaled, as the
    // drag, by the fraction of the current's drag being solved for, and so is its stiffness below.
    const double liftFactor = request.dynamic ? 1.0 : request.currentFactor * request.currentFactor;
    if (m_wake && !m_elementWake[e].liftPerLength.isZero(0.0)) {
      // Wake lift (Blevins) on the wetted length, half on each node.
      const Vec3 lift = 0.5 * wet * (x2 - x1).norm() * liftFactor * m_elementWake[e].liftPerLength;
      force.segment<3>(d1) -= lift;
      force.segment<3>(d2) -= lift;
    }
    if (wakeTangent) {
      // The lift's stiffness (Blevins: the pull towards the wake centre line, of the order of a riser's
      // own lateral stiffness): d(lift_i)/d(x_j) = 1/4 f L d(lift)/d(midpoint). Added for every
      // downstream element, zero where no wake acts, so the matrix entries keep their order. The drag's
      // dependence on the position through the deficit only when asked for (below): symmetrised, it took
      // Newton 111-174 iterations instead of 6-7 on the test models.
      // Symmetric part only: the linear solver is a symmetric LDL^T (LinearSolver.hpp).
      const Mat3 dLift = m_wake->liftGradient(state, static_cast<int>(e), rho);
      const Mat3 k = -0.25 * wet * (x2 - x1).norm() * liftFactor * 0.5 * (dLift + dLift.transpose());
      matrix->add3x3(d1, d1, k, request.kf);
      matrix->add3x3(d1, d2, k, request.kf);
      matrix->add3x3(d2, d1, k, request.kf);
      matrix->add3x3(d2, d2, k, request.kf);
      if (request.wakeDragStiffness && !request.dynamic) {
        // The drag through the deficit: force_i depends on the fluid velocity u at the midpoint as
        // d(force_i)/du = C_i (the drag's damping, as d/du = -d/dv), and u on the midpoint (x1 + x2) / 2 by
        // the wake's gradient times the continuation's factor: d(force_i)/d(x_j) = C_i W / 2. Subtracted.
        // Added (zero where no wake acts) for every downstream element, so the entries keep their order.
        const WakeGradient w = m_wake->velocityChangeGradient(state, static_cast<int>(e), rho);
        Mat3 k1 = Mat3::Zero(), k2 = Mat3::Zero();
        if (!w.midpoint.isZero(0.0)) {
          const MorisonElementLoad drag =
              morisonElementLoad(x1, x2, v1, v2, fluid, coefficients, wet, true, false);
          k1 = -0.5 * request.currentFactor * drag.damping1 * w.midpoint;
          k2 = -0.5 * request.currentFactor * drag.damping2 * w.midpoint;
          // The coupling to the upstream element's nodes (WakeGradient): C_i W_up, W_up = -(1 - s) W, -s W.
          if (w.upstreamNode1 >= 0) {
            const int u1 = dofs.firstDof(w.upstreamNode1), u2 = dofs.firstDof(w.upstreamNode2);
            const double f = -request.currentFactor;
            matrix->add3x3(d1, u1, f * drag.damping1 * w.upstream1, request.kf);
            matrix->add3x3(d1, u2, f * drag.damping1 * w.upstream2, request.kf);
            matrix->add3x3(d2, u1, f * drag.damping2 * w.upstream1, request.kf);
            matrix->add3x3(d2, u2, f * drag.damping2 * w.upstream2, request.kf);
          }
        }
        matrix->add3x3(d1, d1, k1, request.kf);
        matrix->add3x3(d1, d2, k1, request.kf);
        matrix->add3x3(d2, d1, k2, request.kf);
        matrix->add3x3(d2, d2, k2, request.kf);
      }
    }
    if (!wantDamping && !wantStiffness) return;
    const MorisonElementLoad load =
        morisonElementLoad(x1, x2, v1, v2, fluid, coefficients, wet, wantDamping, wantStiffness);
    if (wantStiffness) {
      // The drag turns with the element (theory 6.4): d(force_i)/d(x2) = G_i = -d(force_i)/d(x1); the
      // out-of-balance subtracts the force. Without it a limp line across a current (a lazy wave's
      // buoyant hump) has almost no lateral stiffness in the tangent and Newton crawls.
      matrix->add3x3(d1, d1, load.positionJacobian1, request.kf);
      matrix->add3x3(d1, d2, load.positionJacobian1, -request.kf);
      matrix->add3x3(d2, d1, load.positionJacobian2, request.kf);
      matrix->add3x3(d2, d2, load.positionJacobian2, -request.kf);
    }
    if (wantDamping) {
      matrix->add3x3(d1, d1, load.damping1, request.cf);
      matrix->add3x3(d2, d2, load.damping2, request.cf);
    }
  });
}

void HydroLoads::addAttachmentDrag(const model::State& state, const solver::AssemblyRequest& request,
                                   VecX& force, solver::SystemMatrix* matrix,
                                   const std::vector<int>* list) const {
  // Drag of point bodies (clumps, buoys, the LMRP as an attachment): F = 1/2 rho (Cd A) |u - v| (u - v)
  // with the fluid velocity at the node; damping -dF/dv = 1/2 rho CdA (|w| I + w w^T / |w|), w = u - v.
  const model::DofMap& dofs = m_model->dofs();
  const double rho = m_model->environment().waterDensity;
  forEachIndex(list, m_model->attachments().size(), [&](std::size_t i) {
    const model::NodeAttachment& a = m_model->attachments()[i];
    if (a.spec.dragArea <= 0.0) return;
    const Vec3& x = state.position[a.node];
    const bool withWaves = request.dynamic && request.waves;
    if (x.z() > surfaceAt(x.x(), x.y(), request.time, withWaves)) return;
    const int d = dofs.firstDof(a.node);
    const Vec3 v = request.dynamic ? Vec3(state.velocity.segment<3>(d)) : Vec3::Zero();
    const Vec3 w = (request.dynamic ? 1.0 : request.currentFactor) * fluidAt(x, request.time, withWaves).velocity - v;
    const double speed = w.norm();
    const double k = 0.5 * rho * a.spec.dragArea;
    force.segment<3>(d) -= k * speed * w;
    if (matrix && request.dynamic && request.cf != 0.0 && speed > 0.0)
      matrix->add3x3(d, d, Mat3(k * (speed * Mat3::Identity() + w * w.transpose() / speed)), request.cf);
  });
}

void HydroLoads::addMass(const model::State&, double mf, solver::SystemMatrix* matrix,
                         const VecX* acceleration, VecX* out) {
  addElementMass(mf, matrix, acceleration, out, nullptr);
}

void HydroLoads::addPartMass(const model::State&, const solver::AssemblyPart& part, double mf,
                             solver::SystemMatrix* matrix, const VecX* acceleration, VecX* out) {
  addElementMass(mf, matrix, acceleration, out, &part.elements);
}

void HydroLoads::addElementMass(double mf, solver::SystemMatrix* matrix, const VecX* acceleration, VecX* out,
                                const std::vector<int>* list) const {
  const auto& elements = m_model->elements();
  const model::DofMap& dofs = m_model->dofs();
  if (matrix) {
    forEachIndex(list, elements.size(), [&](std::size_t e) {
      const Mat3 m = m_addedMass[e].matrix();
      matrix->add3x3(dofs.firstDof(elements[e].node1), dofs.firstDof(elements[e].node1), m, mf);
      matrix->add3x3(dofs.firstDof(elements[e].node2), dofs.firstDof(elements[e].node2), m, mf);
    });
  }
  if (!out) return;
  // The inertia force of every assembly (the matrix of few): a loop of its own, without the matrix's
  // branches (docs/performance.md).
  // (Each node's sum held in registers while its elements add to it: PendingSum.)
  PendingSum<3> f(out->data());
  const double* a = acceleration->data();
  forEachIndex(list, elements.size(), [&](std::size_t e) {
    const AddedMass& ma = m_addedMass[e];
    const Vec3& t = ma.tangent;
    const double dm = ma.axial - ma.normal;
    for (const int d : {dofs.firstDof(elements[e].node1), dofs.firstDof(elements[e].node2)}) {
      const double c = dm * (t.x() * a[d] + t.y() * a[d + 1] + t.z() * a[d + 2]);
      f.add(d, std::array<double, 3>{ma.normal * a[d] + c * t.x(), ma.normal * a[d + 1] + c * t.y(),
                                     ma.normal * a[d + 2] + c * t.z()});
    }
  });
}

}  // namespace tangle::hydro
