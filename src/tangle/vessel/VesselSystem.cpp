#include "tangle/vessel/VesselSystem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tangle/core/Ramp.hpp"
#include "tangle/geometry/Rotation.hpp"
#include "tangle/hydro/AiryWave.hpp"
#include "tangle/hydro/ComponentSea.hpp"
#include "tangle/hydro/JonswapSea.hpp"
#include "tangle/vessel/Tensioner.hpp"

namespace tangle::vessel {

namespace {
/// Link stiffness: 100 times the axial stiffness EA / L of the line's end element, so the link adds
/// 1 % to that element's compliance.
constexpr double kLinkFactor = 100.0;
/// A beam end hung from a vessel without a flex joint is pinned: a rotational spring of 1e-6 EI / L about
/// every axis carries no noticeable moment, and a torsion spring GJ / L (the end element's own torsional
/// stiffness) about the end's axis holds the line against spinning about itself. (With the 1e-6 EI / L
/// spring alone the twist mode was nearly singular: Newton's steps turned the whole riser by radians, and
/// statics of a steel catenary riser from a vessel took 8 000 iterations and 45 s against 186 iterations
/// with a pinned top, whose twist is locked by a constraint instead, Model::addLine.)
constexpr double kPinnedFlexFactor = 1e-6;
/// Stiffness of the "DP hold" of a free vessel in statics [N/m] and [N m/rad].
constexpr double kHoldStiffness = 1e10;
constexpr double kHoldRotationalStiffness = 1e13;

void addBlock6(solver::SystemMatrix& m, int rowFirst, int colFirst, const Mat6& b, double scale) {
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) m.add(rowFirst + i, colFirst + j, scale * b(i, j));
}
}  // namespace

VesselSystem::VesselSystem(const model::Model& model, const hydro::HydroLoads& hydro)
    : m_model(&model), m_hydro(&hydro), m_rampTime(model.spec().dynamics.rampTime) {
  const model::EnvironmentSpec& env = model.environment();
  const model::WaveSpec& w = env.waves;
  // The mean drift's amplitude squared per direction of travel (VesselLoads::addWaveDrift): a regular wave's
  // a^2 = (H / 2)^2; a spectrum's 2 m0 = Hs^2 / 8; components' a_i^2, summed per direction. (Until
  // 2026-12-06 an irregular sea had a = Hs / 2 = 2 sqrt(m0), twice the drift of the same sea made of regular
  // waves, and every component took the block's azimuth.)
  if (w.kind == model::WaveKind::Airy && w.height > 0.0)
    m_drift.push_back({0.25 * w.height * w.height, w.azimuth});
  else if (w.kind == model::WaveKind::Jonswap && w.significantHeight > 0.0)
    m_drift.push_back({w.significantHeight * w.significantHeight / 8.0, w.azimuth});
  else if (w.kind == model::WaveKind::Components)
    for (const auto& c : w.componentTable) {
      const auto same = std::find_if(m_drift.begin(), m_drift.end(),
                                     [&](const DriftDirection& d) { return d.azimuth == c[3]; });
      if (same != m_drift.end())
        same->amplitudeSquared += c[1] * c[1];
      else
        m_drift.push_back({c[1] * c[1], c[3]});
    }
  // Wave components for the RAO motion (phase sign: the waves use cos(k x - omega t + phase), the RAO
  // motion cos(omega t - k x + phase), so the component phase is the negated wave phase).
  std::vector<RaoMotion::Component> components;
  if (const hydro::WaveField* field = hydro.waves()) {
    if (const auto* airy = dynamic_cast<const hydro::AiryWave*>(field)) {
      components.push_back({0.5 * airy->height(), airy->angularFrequency(), airy->waveNumber(),
                            airy->azimuth(), -airy->phase()});
    } else if (const auto* sea = dynamic_cast<const hydro::JonswapSea*>(field)) {
      for (const hydro::WaveComponent& c : sea->components())
        components.push_back({c.amplitude, c.omega, c.waveNumber, sea->parameters().azimuth, -c.phase});
    } else if (const auto* given = dynamic_cast<const hydro::ComponentSea*>(field)) {
      for (std::size_t i = 0; i < given->components().size(); ++i) {
        const hydro::ComponentSea::Component& c = given->components()[i];
        components.push_back({c.amplitude, c.omega, given->waveNumber(i), c.azimuth, -c.phase});
      }
    }
  }
  for (int v = 0; v < static_cast<int>(model.vessels().size()); ++v) {
    const model::VesselSpec& spec = model.vessels()[v];
    VesselData d;
    d.spec = &spec;
    d.node = model.vesselNode(v);
    d.position0 = spec.position;
    d.rotation0 = model.vesselRotation(v);
    d.loads = std::make_unique<VesselLoads>(spec, env);
    if (!spec.raos.period.empty() && !components.empty())
      d.rao = std::make_unique<RaoMotion>(spec.raos, spec.heading, components);
    m_vessels.push_back(std::move(d));
  }
  const model::State s0 = model.initialState();
  for (const model::Line& line : model.lines()) {
    for (int end = 0; end < 2; ++end) {
      const model::EndSpec& e = end == 0 ? line.spec->endA : line.spec->endB;
      if (e.kind != model::EndKind::Vessel) continue;
      Connection c;
      c.vessel = model.vesselIndex(e.vessel);
      c.node = end == 0 ? line.firstNode : line.lastNode();
      c.offset = e.position;
      const model::LineElement& el =
          model.elements()[end == 0 ? line.firstElement : line.firstElement + line.elementCount - 1];
      c.linkStiffness = kLinkFactor * el.type->axialStiffness / el.restLength;
      c.tensioner = e.tensioner;
      if (model.dofs().hasRotations(c.node) && el.beam) {
        c.flexStiffness = e.flexJoint.enabled
                              ? e.flexJoint.stiffness
                              : kPinnedFlexFactor * el.beam->properties().bendingStiffness / el.restLength;
        // The twist about the end's axis is held with or without a flex joint: a flex joint is an
        // elastomeric bearing that lets the line bend and holds its torque. (With the flex joint's spring
        // alone the twist was held only by its bending stiffness: by nothing at stiffness 0, where the
        // statics of a steel catenary riser in a cross current took 17 376 Newton iterations and 13 s
        // through the quarter mesh, against 329 and 0.4 s with a pinned top.)
        const auto& props = el.beam->properties();
        const double gj = props.torsionalStiffness > 0.0 ? props.torsionalStiffness : props.bendingStiffness;
        c.twistStiffness = gj / el.restLength;
      }
      c.endTriad0 = s0.triad[c.node];
      m_connections.push_back(c);
    }
  }
}

VesselSystem::~VesselSystem() = default;

bool VesselSystem::markLoadedNodes(std::vector<char>& mark) const {
  // addForces and addMass write only at these nodes and read only their states.
  for (const VesselData& d : m_vessels) mark[static_cast<std::size_t>(d.node)] = 1;
  for (const Connection& c : m_connections) mark[static_cast<std::size_t>(c.node)] = 1;
  return true;
}

Vec3 VesselSystem::vesselPoint(const model::State& state, int vessel, const Vec3& offset) const {
  const int node = m_vessels[vessel].node;
  return state.position[node] + state.triad[node] * offset;
}

model::MotionValue VesselSystem::prescribedPose(int v, double t) const {
  const VesselData& d = m_vessels[v];
  model::MotionValue m;
  m.hasRotation = true;
  m.rotation = d.rotation0;
  if (d.spec->mode != model::VesselMode::Prescribed) return m;
  const double w = 2.0 * kPi / d.spec->motionPeriod;
  const core::RampValue r = core::ramp(t, m_rampTime);
  Vec6 value, rate, accel;
  for (int k = 0; k < 6; ++k) {
    const double a = d.spec->motionAmplitude[k];
    const double s = std::sin(w * t + d.spec->motionPhase[k]);
    const double c = std::cos(w * t + d.spec->motionPhase[k]);
    value[k] = r.value * a * s;
    rate[k] = (r.rate * s + r.value * w * c) * a;
    accel[k] = (r.accel * s + 2.0 * r.rate * w * c - r.value * w * w * s) * a;
  }
  // Translations and small rotations are given in vessel axes.
  m.displacement = d.rotation0 * value.head<3>();
  m.velocity = d.rotation0 * rate.head<3>();
  m.acceleration = d.rotation0 * accel.head<3>();
  m.rotation = d.rotation0 * geometry::expMap(value.tail<3>());
  m.angularVelocity = d.rotation0 * rate.tail<3>();
  m.angularAcceleration = d.rotation0 * accel.tail<3>();
  return m;
}

model::MotionValue VesselSystem::raoPointMotion(int v, const Mat3& rotation, const Vec3& offset,
                                                double t) const {
  model::MotionValue m;
  const VesselData& d = m_vessels[v];
  if (!d.rao) return m;
  const RaoMotion::Motion r = d.rao->at(t, d.position0, core::ramp(t, m_rampTime).value);
  const Vec3 arm = rotation * offset;
  // First order: translation plus small rotation times the lever arm.
  m.displacement = r.displacement.head<3>() + r.displacement.tail<3>().cross(arm);
  m.velocity = r.velocity.head<3>() + r.velocity.tail<3>().cross(arm);
  m.acceleration = r.acceleration.head<3>() + r.acceleration.tail<3>().cross(arm);
  return m;
}

std::optional<std::array<double, 6>> VesselSystem::waveFrequencyMotion(int v, double t) const {
  const VesselData& d = m_vessels[static_cast<std::size_t>(v)];
  if (!d.rao) return std::nullopt;
  const RaoMotion::Motion r = d.rao->at(t, d.position0, core::ramp(t, m_rampTime).value);
  constexpr double toDegrees = 180.0 / kPi;
  return std::array<double, 6>{r.displacement(0),
                               r.displacement(1),
                               r.displacement(2),
                               r.displacement(3) * toDegrees,
                               r.displacement(4) * toDegrees,
                               r.displacement(5) * toDegrees};
}

std::vector<model::PrescribedNode> VesselSystem::prescribedNodes() const {
  std::vector<model::PrescribedNode> out;
  for (int v = 0; v < static_cast<int>(m_vessels.size()); ++v) {
    const VesselData& d = m_vessels[v];
    if (d.spec->mode == model::VesselMode::Prescribed)
      out.push_back({d.node, d.position0, [this, v](double t) { return prescribedPose(v, t); }});
  }
  for (const Connection& c : m_connections) {
    const VesselData& d = m_vessels[c.vessel];
    if (d.spec->mode == model::VesselMode::Free) continue;
    const int v = c.vessel;
    const Vec3 offset = c.offset;
    const Vec3 base = d.position0 + d.rotation0 * offset;
    out.push_back({c.node, base, [this, v, offset, base](double t) {
                     const model::MotionValue pose = prescribedPose(v, t);
                     const Vec3 arm = pose.rotation * offset;
                     const model::MotionValue rao = raoPointMotion(v, pose.rotation, offset, t);
                     model::MotionValue m;
                     m.displacement =
                         m_vessels[v].position0 + pose.displacement + arm + rao.displacement - base;
                     m.velocity = pose.velocity + pose.angularVelocity.cross(arm) + rao.velocity;
                     m.acceleration = pose.acceleration + pose.angularAcceleration.cross(arm) +
                                      pose.angularVelocity.cross(pose.angularVelocity.cross(arm)) +
                                      rao.acceleration;
                     return m;
                   }});
  }
  return out;
}

void VesselSystem::addLink(const model::State& state, const Connection& c,
                           const solver::AssemblyRequest& request, VecX& force,
                           solver::SystemMatrix* matrix) const {
  const model::DofMap& dofs = m_model->dofs();
  const VesselData& d = m_vessels[c.vessel];
  const Mat3& rotation = state.triad[d.node];
  const Vec3 arm = rotation * c.offset;
  const Vec3 p =
      state.position[d.node] + arm + raoPointMotion(c.vessel, rotation, c.offset, request.time).displacement;
  const Vec3 g = state.position[c.node] - p;
  // External force on the line end and its stiffness against the relative displacement g.
  Vec3 fEnd;
  Mat3 kc;
  if (c.tensioner.enabled) {
    const Vec3 e = rotation * Vec3::UnitZ();
    const Mat3 horizontal = Mat3::Identity() - e * e.transpose();
    const double stroke = -g.dot(e);  // > 0: the end hangs below the mid-stroke point
    const TensionerForce t = tensionerForce(c.tensioner, stroke);
    fEnd = -c.linkStiffness * horizontal * g + t.force * e;
    kc = c.linkStiffness * horizontal + t.stiffness * e * e.transpose();
  } else {
    fEnd = -c.linkStiffness * g;
    kc = c.linkStiffness * Mat3::Identity();
  }
  const int de = dofs.firstDof(c.node);
  const int dv = dofs.firstDof(d.node);
  force.segment<3>(de) -= fEnd;                 // on the line end
  force.segment<3>(dv) += fEnd;                 // reaction on the vessel ...
  force.segment<3>(dv + 3) += arm.cross(fEnd);  // ... and its moment about the reference point
  if (!matrix) return;
  // dF = J^T Kc J with dg = J dq = d(x_end) - d(X) + skew(arm) d(theta), plus the turning of the lever
  // arm in the moment, d(arm) x fEnd = skew(fEnd) skew(arm) d(theta): with |fEnd| the line tension it
  // is most of the yaw stiffness of a spread mooring (without it the static Newton iteration diverges
  // in yaw). The turning of the tensioner axis is left out of the tangent.
  const Mat3 s = geometry::skew(arm);
  const double kf = request.kf;
  matrix->add3x3(de, de, kc, kf);
  matrix->add3x3(de, dv, kc, -kf);
  matrix->add3x3(de, dv + 3, Mat3(kc * s), kf);
  matrix->add3x3(dv, de, kc, -kf);
  matrix->add3x3(dv, dv, kc, kf);
  matrix->add3x3(dv, dv + 3, Mat3(-kc * s), kf);
  matrix->add3x3(dv + 3, de, Mat3(-s.transpose() * kc), -kf);
  matrix->add3x3(dv + 3, dv, Mat3(s.transpose() * kc), -kf);
  matrix->add3x3(dv + 3, dv + 3, Mat3(s.transpose() * kc * s + geometry::skew(fEnd) * s), kf);
}

void VesselSystem::addFlexJoint(const model::State& state, const Connection& c,
                                const solver::AssemblyRequest& request, VecX& force,
                                solver::SystemMatrix* matrix) const {
  if (c.flexStiffness <= 0.0 && c.twistStiffness <= 0.0) return;
  const model::DofMap& dofs = m_model->dofs();
  const VesselData& d = m_vessels[c.vessel];
  const bool free = d.spec->mode == model::VesselMode::Free;
  const Mat3 rotation = free ? state.triad[d.node] : prescribedPose(c.vessel, request.time).rotation;
  // Relative rotation of the line end with respect to the vessel since t = 0 (spatial rotation vector).
  const Mat3 endTurn = state.triad[c.node] * c.endTriad0.transpose();
  const Mat3 vesselTurn = rotation * d.rotation0.transpose();
  const Vec3 phi = geometry::logMap(endTurn * vesselTurn.transpose());
  const int de = dofs.firstDof(c.node) + 3;
  const int dv = dofs.firstDof(d.node) + 3;
  // Twist: the component of phi about the end's axis (tangent matrix k a a^T; the turn of a with the
  // end is left out of it).
  const Vec3 axis = state.triad[c.node].col(0);
  const Vec3 moment = c.flexStiffness * phi + c.twistStiffness * axis.dot(phi) * axis;
  force.segment<3>(de) += moment;
  if (free) force.segment<3>(dv) -= moment;
  if (!matrix) return;
  const Mat3 k =
      request.kf * (c.flexStiffness * Mat3::Identity() + c.twistStiffness * axis * axis.transpose());
  matrix->add3x3(de, de, k, 1.0);
  if (free) {
    matrix->add3x3(de, dv, k, -1.0);
    matrix->add3x3(dv, de, k, -1.0);
    matrix->add3x3(dv, dv, k, 1.0);
  }
}

BodyLoad VesselSystem::bodyLoad(const model::State& state, const VesselData& d,
                                const solver::AssemblyRequest& request) const {
  const int dv = m_model->dofs().firstDof(d.node);
  const Vec6 velocity = request.dynamic ? Vec6(state.velocity.segment<6>(dv)) : Vec6::Zero();
  const Vec3 current =
      m_hydro->fluidAt(Vec3(state.position[d.node].x(), state.position[d.node].y(), 0.0), request.time, false)
          .velocity;
  BodyLoad load = d.loads->loads(state.position[d.node], state.triad[d.node], velocity, d.position0,
                                 d.rotation0, current, 0.0, 0.0, 1.0);
  for (const DriftDirection& drift : m_drift)
    d.loads->addWaveDrift(load, state.triad[d.node], drift.amplitudeSquared, drift.azimuth, 1.0);
  return load;
}

void VesselSystem::raiseRoundoffFloor(const model::State& state, std::vector<double>& floor) const {
  for (const Connection& c : m_connections) {
    const VesselData& d = m_vessels[static_cast<std::size_t>(c.vessel)];
    if (d.spec->mode != model::VesselMode::Free) continue;
    const double x =
        std::max(state.position[static_cast<std::size_t>(c.node)].cwiseAbs().maxCoeff(),
                 state.position[static_cast<std::size_t>(d.node)].cwiseAbs().maxCoeff() + c.offset.norm());
    const double f = 16.0 * std::numeric_limits<double>::epsilon() * c.linkStiffness * x;
    for (const int n : {c.node, d.node})
      floor[static_cast<std::size_t>(n)] = std::max(floor[static_cast<std::size_t>(n)], f);
  }
}

Vec6 VesselSystem::holdLoad(const model::State& state, const VesselData& d) const {
  Vec6 hold;
  hold.head<3>() = -kHoldStiffness * (state.position[d.node] - d.position0);
  hold.tail<3>() =
      -kHoldRotationalStiffness * geometry::logMap(state.triad[d.node] * d.rotation0.transpose());
  return hold;
}

void VesselSystem::addForces(const model::State& state, const solver::AssemblyRequest& request, VecX& force,
                             solver::SystemMatrix* matrix) {
  const model::DofMap& dofs = m_model->dofs();
  for (const VesselData& d : m_vessels) {
    if (d.spec->mode != model::VesselMode::Free) continue;
    const int dv = dofs.firstDof(d.node);
    const BodyLoad load = bodyLoad(state, d, request);
    force.segment<6>(dv) -= load.force;
    if (matrix) {
      addBlock6(*matrix, dv, dv, load.stiffness, request.kf);
      if (request.dynamic && request.cf != 0.0) addBlock6(*matrix, dv, dv, load.damping, request.cf);
    }
    if (d.spec->heldInStatics && !request.dynamic) {
      // Dynamic positioning on station during statics: stiff springs to the initial pose.
      force.segment<6>(dv) -= holdLoad(state, d);
      if (matrix) {
        matrix->addDiagonal3(dv, request.kf * kHoldStiffness);
        matrix->addDiagonal3(dv + 3, request.kf * kHoldRotationalStiffness);
      }
    }
  }
  for (const Connection& c : m_connections) {
    const VesselData& d = m_vessels[c.vessel];
    if (d.spec->mode == model::VesselMode::Free) {
      addLink(state, c, request, force, matrix);
    } else if (c.tensioner.enabled) {
      // End on a fixed/prescribed vessel hanging from its tensioner: held horizontally (prescribed),
      // vertical force from the tensioner.
      const model::MotionValue pose = prescribedPose(c.vessel, request.time);
      const Vec3 p = d.position0 + pose.displacement + pose.rotation * c.offset +
                     raoPointMotion(c.vessel, pose.rotation, c.offset, request.time).displacement;
      const int dz = m_model->dofs().firstDof(c.node) + 2;
      const TensionerForce t = tensionerForce(c.tensioner, p.z() - state.position[c.node].z());
      force[dz] -= t.force;
      if (matrix) matrix->add(dz, dz, request.kf * t.stiffness);
    }
    addFlexJoint(state, c, request, force, matrix);
  }
}

std::vector<VesselSystem::VesselLoadReading> VesselSystem::loadReadings(
    const model::State& state, const solver::AssemblyRequest& request) const {
  std::vector<VesselLoadReading> out;
  for (std::size_t v = 0; v < m_vessels.size(); ++v) {
    const VesselData& d = m_vessels[v];
    VesselLoadReading r;
    r.name = d.spec->name;
    r.node = d.node;
    r.free = d.spec->mode == model::VesselMode::Free;
    r.pinned = r.free && d.spec->pinned;
    for (const Connection& c : m_connections)
      if (c.vessel == static_cast<int>(v)) r.endNodes.push_back(c.node);
    if (r.free) {
      // The same loads as addForces.
      r.body = bodyLoad(state, d, request).force;
      if (d.spec->heldInStatics && !request.dynamic) r.hold = holdLoad(state, d);
    }
    out.push_back(std::move(r));
  }
  return out;
}

VecX VesselSystem::endConnectionForces(const model::State& state, double time) const {
  const model::DofMap& dofs = m_model->dofs();
  VecX all = VecX::Zero(dofs.fullDofCount());
  solver::AssemblyRequest request;
  request.time = time;
  request.wantMatrix = false;
  for (const Connection& c : m_connections) {
    const VesselData& d = m_vessels[c.vessel];
    VecX one = VecX::Zero(dofs.fullDofCount());
    if (d.spec->mode == model::VesselMode::Free) {
      addLink(state, c, request, one, nullptr);
    } else if (c.tensioner.enabled) {
      const model::MotionValue pose = prescribedPose(c.vessel, time);
      const Vec3 p = d.position0 + pose.displacement + pose.rotation * c.offset +
                     raoPointMotion(c.vessel, pose.rotation, c.offset, time).displacement;
      one[dofs.firstDof(c.node) + 2] -= tensionerForce(c.tensioner, p.z() - state.position[c.node].z()).force;
    }
    all.segment<3>(dofs.firstDof(c.node)) += one.segment<3>(dofs.firstDof(c.node));
  }
  return all;
}

std::vector<VesselSystem::TensionerReading> VesselSystem::tensionerReadings(const model::State& state,
                                                                            double time) const {
  std::vector<TensionerReading> out;
  for (const Connection& c : m_connections) {
    if (!c.tensioner.enabled) continue;
    const VesselData& d = m_vessels[c.vessel];
    double stroke = 0.0;
    if (d.spec->mode == model::VesselMode::Free) {
      // Same stroke as addLink: along the vessel's z axis from the mid-stroke point.
      const Mat3& rotation = state.triad[d.node];
      const Vec3 p = state.position[d.node] + rotation * c.offset +
                     raoPointMotion(c.vessel, rotation, c.offset, time).displacement;
      stroke = -(state.position[c.node] - p).dot(rotation * Vec3::UnitZ());
    } else {
      const model::MotionValue pose = prescribedPose(c.vessel, time);
      const Vec3 p = d.position0 + pose.displacement + pose.rotation * c.offset +
                     raoPointMotion(c.vessel, pose.rotation, c.offset, time).displacement;
      stroke = p.z() - state.position[c.node].z();
    }
    TensionerReading r;
    r.line = m_model->lineOfNode(c.node);
    r.end = c.node == m_model->lines()[r.line].firstNode ? 0 : 1;
    r.stroke = stroke;
    r.halfStroke = 0.5 * c.tensioner.stroke;
    r.force = tensionerForce(c.tensioner, stroke).force;
    // The stop carries what the gas spring does not: force - (T + k_g s) with s clamped to the stroke.
    const double withinStroke = std::clamp(stroke, -r.halfStroke, r.halfStroke);
    r.stopForce = r.force - (c.tensioner.tension + c.tensioner.stiffness * withinStroke);
    out.push_back(r);
  }
  return out;
}

void VesselSystem::addMass(const model::State& state, double mf, solver::SystemMatrix* matrix,
                           const VecX* acceleration, VecX* out) {
  const model::DofMap& dofs = m_model->dofs();
  for (const VesselData& d : m_vessels) {
    if (d.spec->mode != model::VesselMode::Free) continue;
    const Mat6 m = d.loads->massMatrix(state.triad[d.node]);
    const int dv = dofs.firstDof(d.node);
    if (matrix) addBlock6(*matrix, dv, dv, m, mf);
    if (out) out->segment<6>(dv) += m * acceleration->segment<6>(dv);
  }
}

}  // namespace tangle::vessel
