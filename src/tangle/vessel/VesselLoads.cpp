/// @file VesselLoads.cpp
/// Hydrostatic, damping, current, wind and drift loads on a free vessel (see VesselLoads.hpp and
/// docs/theory.md (section 10)).

#include "tangle/vessel/VesselLoads.hpp"

#include <cmath>

#include <fmt/format.h>

#include "tangle/core/Error.hpp"
#include "tangle/geometry/Rotation.hpp"
#include "tangle/vessel/HeadingTable.hpp"

namespace tangle::vessel {
namespace {

using geometry::skew;

/// Load in vessel axes (F_x, F_y, M_z) of a horizontal flow and its Jacobian with respect to the flow
/// components (u_bx, u_by) in vessel axes.
struct FlowLoad {
  Vec3 load = Vec3::Zero();
  Eigen::Matrix<double, 3, 2> jacobian = Eigen::Matrix<double, 3, 2>::Zero();
};

/// quadratic = true: load_i = scale_i V^2 C_i(beta) (drag); false: load_i = scale_i C_i(beta) (direction
/// only: drift). beta = atan2(b, a), V^2 = a^2 + b^2, (a, b) = flow in vessel axes.
/// d(V^2 C)/da = 2 a C - b C', d(V^2 C)/db = 2 b C + a C' (dbeta/da = -b/V^2, dbeta/db = a/V^2).
FlowLoad flowLoad(const model::HeadingTable& table, const Vec3& scale, double a, double b, bool quadratic) {
  FlowLoad result;
  const double v2 = a * a + b * b;
  if (table.heading.empty() || v2 == 0.0) return result;
  const HeadingSample c = interpolateWithSlope(table, std::atan2(b, a));
  for (int i = 0; i < 3; ++i) {
    if (quadratic) {
      result.load(i) = scale(i) * v2 * c.value(i);
      result.jacobian(i, 0) = scale(i) * (2.0 * a * c.value(i) - b * c.slope(i));
      result.jacobian(i, 1) = scale(i) * (2.0 * b * c.value(i) + a * c.slope(i));
    } else {
      result.load(i) = scale(i) * c.value(i);
      result.jacobian(i, 0) = -scale(i) * c.slope(i) * b / v2;
      result.jacobian(i, 1) = scale(i) * c.slope(i) * a / v2;
    }
  }
  return result;
}

/// Maps (F_x, F_y, M_z) in vessel axes to the global 6-vector: force R (F_x, F_y, 0), moment R (0, 0, M_z).
Eigen::Matrix<double, 6, 3> planarToGlobal(const Mat3& r) {
  Eigen::Matrix<double, 6, 3> t = Eigen::Matrix<double, 6, 3>::Zero();
  t.block<3, 1>(0, 0) = r.col(0);
  t.block<3, 1>(0, 1) = r.col(1);
  t.block<3, 1>(3, 2) = r.col(2);
  return t;
}

/// Adds a horizontal-flow load to `out`. flow: global flow vector (its z component is ignored);
/// relative: the flow is (environment - vessel velocity), so it depends on the vessel velocity.
void addFlowLoad(BodyLoad& out, const model::HeadingTable& table, const Vec3& scale, const Vec3& flowGlobal,
                 const Mat3& r, bool quadratic, bool relative, double factor) {
  if (table.heading.empty() || factor == 0.0) return;
  const Vec3 w(flowGlobal.x(), flowGlobal.y(), 0.0);
  const Vec3 wb = r.transpose() * w;
  const FlowLoad f = flowLoad(table, scale, wb.x(), wb.y(), quadratic);
  const Eigen::Matrix<double, 6, 3> t = planarToGlobal(r);
  const Vec6 load = t * f.load;
  out.force += factor * load;
  // Rotation dependence: d(T F_b) = [-skew(F); -skew(M)] dtheta + T J d(u_b,xy), d(u_b) = R^T skew(w) dtheta.
  Eigen::Matrix<double, 6, 3> dLoadDTheta = Eigen::Matrix<double, 6, 3>::Zero();
  dLoadDTheta.topRows<3>() = -skew(load.head<3>());
  dLoadDTheta.bottomRows<3>() = -skew(load.tail<3>());
  const Mat3 rtSkewW = r.transpose() * skew(w);
  dLoadDTheta += t * f.jacobian * rtSkewW.topRows<2>();
  out.stiffness.rightCols<3>() -= factor * dLoadDTheta;
  if (relative) {
    // w = E (environment - v): d(u_b,xy)/dv = -(R^T)_{xy rows} E, E = diag(1, 1, 0).
    Eigen::Matrix<double, 2, 3> duDv = -r.transpose().topRows<2>();
    duDv.col(2).setZero();
    out.damping.leftCols<3>() -= factor * t * f.jacobian * duDv;
  }
}

void checkNonNegative(const std::string& vessel, const std::string& field, double value) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw Error(fmt::format("vessel '{}': {} = {} must be finite and >= 0", vessel, field, value));
  }
}

}  // namespace

VesselLoads::VesselLoads(const model::VesselSpec& vessel, const model::EnvironmentSpec& environment)
    : m_name(vessel.name),
      m_mass(vessel.mass),
      m_inertia(vessel.inertia),
      m_addedMass(vessel.addedMass),
      m_linearDamping(vessel.linearDamping),
      m_quadraticDamping(vessel.quadraticDamping),
      m_hydrostatic(vessel.hydrostaticStiffness),
      m_currentCoefficients(vessel.currentCoefficients),
      m_windCoefficients(vessel.windCoefficients),
      m_waveDrift(vessel.waveDrift) {
  const std::string& n = m_name;
  checkNonNegative(n, "mass", m_mass);
  for (int i = 0; i < 3; ++i) checkNonNegative(n, fmt::format("inertia[{}]", i), m_inertia(i));
  for (int i = 0; i < 6; ++i) {
    checkNonNegative(n, fmt::format("addedMass[{}]", i), m_addedMass[i]);
    checkNonNegative(n, fmt::format("linearDamping[{}]", i), m_linearDamping[i]);
    checkNonNegative(n, fmt::format("quadraticDamping[{}]", i), m_quadraticDamping[i]);
    checkNonNegative(n, fmt::format("hydrostaticStiffness[{}]", i), m_hydrostatic[i]);
  }
  for (int i = 0; i < 3; ++i) {
    checkNonNegative(n, fmt::format("currentAreas[{}]", i), vessel.currentAreas(i));
    checkNonNegative(n, fmt::format("windAreas[{}]", i), vessel.windAreas(i));
  }
  if (!std::isnan(vessel.displacedVolume)) {
    checkNonNegative(n, "displacedVolume", vessel.displacedVolume);
    m_weight = vessel.mass * environment.gravity;
    m_buoyancy = environment.waterDensity * environment.gravity * vessel.displacedVolume;
    m_centreOfBuoyancy = vessel.centreOfBuoyancy;
  }
  checkNonNegative(n, "environment.waterDensity", environment.waterDensity);
  checkNonNegative(n, "environment.airDensity", environment.airDensity);
  checkNonNegative(n, "environment.windSpeed", environment.windSpeed);
  if (!m_currentCoefficients.heading.empty()) {
    validateHeadingTable(m_currentCoefficients, fmt::format("vessel '{}' currentCoefficients", n));
  }
  if (!m_windCoefficients.heading.empty()) {
    validateHeadingTable(m_windCoefficients, fmt::format("vessel '{}' windCoefficients", n));
  }
  if (!m_waveDrift.heading.empty()) validateHeadingTable(m_waveDrift, fmt::format("vessel '{}' waveDrift", n));
  const Vec3& ac = vessel.currentAreas;
  m_currentScale = 0.5 * environment.waterDensity * Vec3(ac(0), ac(1), ac(1) * ac(2));
  const Vec3& aw = vessel.windAreas;
  m_windScale = 0.5 * environment.airDensity * Vec3(aw(0), aw(1), aw(1) * aw(2));
  m_windVelocity = environment.windSpeed * Vec3(std::cos(environment.windAzimuth), std::sin(environment.windAzimuth), 0.0);
}

BodyLoad VesselLoads::loads(const Vec3& position, const Mat3& rotation, const Vec6& velocity,
                            const Vec3& initialPosition, const Mat3& initialRotation, const Vec3& currentVelocity,
                            double waveAmplitude, double waveAzimuth, double ramp) const {
  BodyLoad out;
  const Mat3& r = rotation;

  // --- A submerged body's weight (at the reference point) and buoyancy (at its centre of buoyancy), never
  // ramped. The moment of a constant force F at r = R c turns with the body: d(r x F)/d(dtheta) =
  // r F^T - (r . F) I, so -d/d(dtheta) adds (r . F) I - r F^T.
  if (m_weight != 0.0 || m_buoyancy != 0.0) {
    const Vec3 lift(0.0, 0.0, m_buoyancy);
    const Vec3 arm = r * m_centreOfBuoyancy;
    out.force(2) += m_buoyancy - m_weight;
    out.force.tail<3>() += arm.cross(lift);
    out.stiffness.block<3, 3>(3, 3) += arm.dot(lift) * Mat3::Identity() - arm * lift.transpose();
  }

  // --- Hydrostatic restoring (Faltinsen 1990, ch. 2), about the initial equilibrium.
  out.force(2) += -m_hydrostatic[2] * (position.z() - initialPosition.z());
  out.stiffness(2, 2) += m_hydrostatic[2];
  const double k44 = m_hydrostatic[3];
  const double k55 = m_hydrostatic[4];
  if (k44 != 0.0 || k55 != 0.0) {
    // n: the initial "up" axis seen in the current vessel axes; tilt vector theta_b = g (n_y, -n_x, 0).
    const Vec3 nv = r.transpose() * (initialRotation * Vec3::UnitZ());
    const double s = std::hypot(nv.x(), nv.y());
    const double nz = nv.z();
    const double r2 = s * s + nz * nz;
    double g = 0.0;
    double h = 0.0;  // (dg/ds) / s
    if (nz > 0.0 && s < 1.0e-4 * nz) {
      // Series in t = s / n_z: g = (1 - t^2/3 + t^4/5) / n_z, h = (-2/3 + 4 t^2/5) / n_z^3.
      const double t2 = (s / nz) * (s / nz);
      g = (1.0 - t2 / 3.0 + t2 * t2 / 5.0) / nz;
      h = (-2.0 / 3.0 + 0.8 * t2) / (nz * nz * nz);
    } else {
      if (s == 0.0) throw Error(fmt::format("vessel '{}': capsized (turned upside down)", m_name));
      const double alpha = std::atan2(s, nz);
      g = alpha / s;
      h = (s * nz / r2 - alpha) / (s * s * s);
    }
    const Vec3 theta(g * nv.y(), -g * nv.x(), 0.0);
    const Vec3 momentBody(-k44 * theta.x(), -k55 * theta.y(), 0.0);
    const Vec3 moment = r * momentBody;
    out.force.tail<3>() += moment;
    // d theta_b / d n (rows x, y; z row zero).
    const Vec3 gradG(h * nv.x(), h * nv.y(), -1.0 / r2);
    Mat3 dThetaDn = Mat3::Zero();
    dThetaDn.row(0) = g * Vec3::UnitY().transpose() + nv.y() * gradG.transpose();
    dThetaDn.row(1) = -g * Vec3::UnitX().transpose() - nv.x() * gradG.transpose();
    // dn = skew(n) R^T dtheta; dM = -skew(M) dtheta + R dM_b.
    const Mat3 kDiag = Vec3(k44, k55, 0.0).asDiagonal();
    out.stiffness.block<3, 3>(3, 3) += skew(moment) + r * kDiag * dThetaDn * skew(nv) * r.transpose();
  }

  // --- Linear + quadratic damping on the body velocity, per DOF in vessel axes.
  const Vec3 vb = r.transpose() * velocity.head<3>();
  const Vec3 wb = r.transpose() * velocity.tail<3>();
  Vec3 fb;
  Vec3 mb;
  Vec3 cf;
  Vec3 cm;
  for (int i = 0; i < 3; ++i) {
    fb(i) = -m_linearDamping[i] * vb(i) - m_quadraticDamping[i] * std::abs(vb(i)) * vb(i);
    mb(i) = -m_linearDamping[i + 3] * wb(i) - m_quadraticDamping[i + 3] * std::abs(wb(i)) * wb(i);
    cf(i) = m_linearDamping[i] + 2.0 * m_quadraticDamping[i] * std::abs(vb(i));
    cm(i) = m_linearDamping[i + 3] + 2.0 * m_quadraticDamping[i + 3] * std::abs(wb(i));
  }
  out.force.head<3>() += r * fb;
  out.force.tail<3>() += r * mb;
  out.damping.block<3, 3>(0, 0) += r * cf.asDiagonal() * r.transpose();
  out.damping.block<3, 3>(3, 3) += r * cm.asDiagonal() * r.transpose();

  // --- Environmental loads (ramped).
  if (ramp != 0.0) {
    const Vec3 v = velocity.head<3>();
    addFlowLoad(out, m_currentCoefficients, m_currentScale, currentVelocity - v, r, true, true, ramp);
    addFlowLoad(out, m_windCoefficients, m_windScale, m_windVelocity - v, r, true, true, ramp);
    addWaveDrift(out, r, waveAmplitude * waveAmplitude, waveAzimuth, ramp);
  }
  return out;
}

void VesselLoads::addWaveDrift(BodyLoad& out, const Mat3& rotation, double amplitudeSquared,
                               double waveAzimuth, double ramp) const {
  if (ramp == 0.0 || amplitudeSquared == 0.0) return;
  const Vec3 waveDirection(std::cos(waveAzimuth), std::sin(waveAzimuth), 0.0);
  addFlowLoad(out, m_waveDrift, Vec3::Constant(amplitudeSquared), waveDirection, rotation, false, false,
              ramp);
}

Mat6 VesselLoads::massMatrix(const Mat3& rotation) const {
  Mat6 m = Mat6::Zero();
  const Vec3 addedTranslation(m_addedMass[0], m_addedMass[1], m_addedMass[2]);
  const Vec3 rotational = m_inertia + Vec3(m_addedMass[3], m_addedMass[4], m_addedMass[5]);
  m.block<3, 3>(0, 0) = m_mass * Mat3::Identity() + rotation * addedTranslation.asDiagonal() * rotation.transpose();
  m.block<3, 3>(3, 3) = rotation * rotational.asDiagonal() * rotation.transpose();
  return m;
}

}  // namespace tangle::vessel
