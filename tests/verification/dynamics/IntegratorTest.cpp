// Dynamic verification, time integrator (issue 3, item 3): order of accuracy on a nonlinear problem,
// and energy conservation of the non-dissipative members of the family.
//
// Problem: an elastic pendulum swinging in air, a 1 m line of 4 bars (1 kg/m, EA = 1000 N) pinned at
// its top, with a 2 kg point mass at its free end, released from rest straight and unstretched at
// 60 degrees from the vertical. It is strongly nonlinear (large rotations, the bars stretch up to ~5 %
// under the centrifugal load and bounce axially, the free links whip), chaotic over long times and
// conservative. Variants: the pivot driven by a prescribed motion (exercises the prescribed-DOF path),
// and the same pendulum made of 4 co-rotational beams (EI = GJ = 1 N m^2, rotary diameter 0.2 m) to
// exercise the multiplicative rotation update and the rotational inertia.
//
// Order: the generalized-alpha family (Chung & Hulbert 1993, J. Appl. Mech. 60:371, eq. 17 and 20) is
// second-order accurate for any rho_inf when started from the consistent acceleration a0 = -M^{-1}F0.
// The global error at a fixed time is measured with dt, dt/2, dt/4, dt/8 against a run with dt/128
// (beams: dt/64), and the observed order log2(e(h)/e(h/2)) must be >= 1.9 (issue bound; the asymptotic
// value is 2). An order is only observable in the asymptotic range, i.e. once the stiffest mode is well
// resolved: bars, axial, omega ~ 180 rad/s, dt = 5e-4 s (omega dt = 0.09); beams, nodal rotation,
// omega ~ 160 rad/s, dt = 1e-3 s (0.16). One step coarser for the bars, dt = 1e-3 s, the first pair gives
// 1.91 (generalized-alpha), 1.92 (Newmark) and 1.87 (HHT): pre-asymptotic O(dt^3) terms still show.
//
// Energy: with no numerical dissipation (Newmark average acceleration, or generalized-alpha with
// rho_inf = 1) the total energy kinetic 1/2 v^T M v (rotational inertia included) + strain energy (bars:
// EA/(2 L0) (l - L0)^2, beams: CorotationalBeam::strainEnergy) + potential sum m_i g z_i must stay
// constant. The trapezoidal rule conserves energy exactly for linear systems (Hughes 1987, "The finite
// element method", sec. 9.3.2) and to O(dt^2) without drift for nonlinear ones such as this (the Newton
// tolerance is set far below); the issue bound is 0.5 % of the energy over 100 periods, measured
// relative to the largest kinetic energy of the swing (the total energy itself depends on the arbitrary
// datum of z). Generalized-alpha with rho_inf = 1 (alpha_m = alpha_f = 1/2) started from a consistent
// acceleration is algebraically the trapezoidal rule (its weighted residual (r_n+1 + r_n)/2 = 0 with
// r_0 = 0 gives r_n+1 = 0): on the regular beam pendulum it reproduces Newmark to all printed digits, so
// only Newmark is run there; on the chaotic bar pendulum the two differ only through the exponential
// growth of Newton-tolerance differences, and both are run.

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "support/ModelFactory.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/solver/Assembler.hpp"
#include "tangle/time/DynamicAnalysis.hpp"
#include "tangle/time/GeneralizedAlpha.hpp"

namespace tangle {
namespace {

constexpr double kLength = 1.0;        // [m]
constexpr int kElements = 4;
constexpr double kMassPerLength = 1.0; // [kg/m]
constexpr double kEA = 1000.0;         // [N]
constexpr double kTipMass = 2.0;       // [kg]
constexpr double kHeight = 10.0;       // pivot height, in air [m]
constexpr double kRelease = 60.0 * 3.141592653589793 / 180.0;  // release angle from the vertical [rad]

struct Pendulum {
  std::unique_ptr<model::Model> model;
  std::unique_ptr<solver::Assembler> assembler;
  model::State state;
};

/// a0 = -M^{-1} F(q0, v0, t0) on the free DOFs.
VecX consistentAcceleration(solver::Assembler& assembler, const model::State& state) {
  const model::DofMap& dofs = assembler.model().dofs();
  solver::AssemblyRequest request;
  request.time = state.time;
  request.dynamic = true;
  request.wantMatrix = false;
  VecX force;
  assembler.assemble(state, request, force, nullptr);
  solver::SystemMatrix m(dofs);
  assembler.addMass(state, 1.0, &m, nullptr, nullptr);
  SparseMatrix ms;
  m.build(ms);
  Eigen::SimplicialLDLT<SparseMatrix> ldlt(ms);
  VecX rhs(dofs.equationCount());
  for (int i = 0; i < dofs.equationCount(); ++i) rhs[i] = -force[dofs.equationDofs()[i]];
  const VecX a = ldlt.solve(rhs);
  VecX full = VecX::Zero(dofs.fullDofCount());
  for (int i = 0; i < dofs.equationCount(); ++i) full[dofs.equationDofs()[i]] = a[i];
  return full;
}

/// The pendulum; `driven`: its pivot moves as 0.5 m x (1, 0, 0.5) sin(2 pi t / 1 s), ramped in over 0.5 s
/// (exercises the prescribed-motion path of the integrator); `beam`: co-rotational beams instead of bars.
Pendulum makePendulum(bool driven, bool beam) {
  model::ModelSpec spec;
  spec.sourceFile = "elastic pendulum (test)";
  spec.environment.waterDepth = 100.0;
  section::LineType type = test::cableType("link", beam ? 0.2 : 0.01, kMassPerLength, kEA);
  if (beam) {
    // Flexible but not floppy (static tip deflection under the transverse weight component ~ 0.3 m);
    // outerDiameter 0.2 m sets the lumped rotary inertia m D^2 / 16 per length (in air it does nothing else).
    type.bendingStiffness = 1.0;
    type.torsionalStiffness = 1.0;
  }
  // The link is an elastic spring in compression too (the driven pivot compresses it at times): the
  // test is about the integrator's order on a smooth problem, not about slack cables.
  type.compressionFactor = 1.0;
  spec.lineTypes[type.name] = type;
  const Vec3 pivot(0, 0, kHeight);
  const Vec3 direction(std::sin(kRelease), 0.0, -std::cos(kRelease));
  spec.lines.push_back(test::simpleLine("pendulum", "link", kLength, kElements, model::EndKind::Pinned, pivot,
                                        model::EndKind::Free, pivot + kLength * direction));
  spec.lines[0].attachments.push_back({kLength, kTipMass, 0.0, 0.0, 0.0});
  if (driven) {
    spec.lines[0].endA.motion.enabled = true;
    spec.lines[0].endA.motion.amplitude = Vec3(0.5, 0.0, 0.25);
    spec.lines[0].endA.motion.period = 1.0;
    spec.dynamics.rampTime = 0.5;
  }
  Pendulum p;
  p.model = std::make_unique<model::Model>(std::move(spec));
  p.assembler = std::make_unique<solver::Assembler>(*p.model);
  // Straight, unstretched, at rest (the initial shape of a line with a free end is straight; its triads
  // are aligned with it, so the beams start stress-free too).
  p.state = p.model->initialState();
  const model::Line& line = p.model->lines()[0];
  for (int i = 0; i < line.nodeCount; ++i) p.state.position[line.firstNode + i] = pivot + line.arcLength[i] * direction;
  p.state.velocity.setZero();
  p.state.acceleration = consistentAcceleration(*p.assembler, p.state);
  return p;
}

model::DynamicSpec integratorSettings(model::IntegratorKind kind, double rhoInf) {
  model::DynamicSpec s;
  s.integrator = kind;
  s.spectralRadius = rhoInf;
  // Residual tolerance 1e-9 x the 1 N reference force: the Newton error is then < 1e-15 m per step
  // (1e-9 N against the inertia stiffness M / (beta dt^2)), far below the smallest discretisation error
  // measured (~4e-8 m). Not tighter: at the reference step (3.9e-6 s) the round-off of the inertia term
  // M eps |dq| / (beta dt^2) is ~1e-10 N.
  s.tolerance = 1e-9;
  s.maxIterations = 30;
  return s;
}

struct OrderCase {
  const char* name;
  model::IntegratorKind kind;
  double rhoInf;
  bool driven = false;
  bool beam = false;
};

/// State at tEnd integrated with a constant step dt.
model::State integrate(const OrderCase& c, double dt, double tEnd) {
  Pendulum p = makePendulum(c.driven, c.beam);
  time::GeneralizedAlpha stepper(*p.assembler, integratorSettings(c.kind, c.rhoInf), time::prescribedNodes(*p.model));
  stepper.initialize(p.state);
  const int steps = static_cast<int>(std::lround(tEnd / dt));
  for (int k = 0; k < steps; ++k) {
    const time::StepOutcome o = stepper.step(p.state, dt);
    if (!o.converged) {
      ADD_FAILURE() << "Newton failed at step " << k << " (dt = " << dt << " s), residual " << o.residual;
      break;
    }
  }
  return p.state;
}

/// Largest position error [m] and largest triad rotation error [rad] over the nodes.
std::pair<double, double> maxError(const model::State& a, const model::State& b) {
  double dx = 0.0, dr = 0.0;
  for (std::size_t i = 0; i < a.position.size(); ++i) {
    dx = std::max(dx, (a.position[i] - b.position[i]).norm());
    dr = std::max(dr, Eigen::AngleAxisd(a.triad[i] * b.triad[i].transpose()).angle());
  }
  return {dx, dr};
}

class IntegratorOrder : public ::testing::TestWithParam<OrderCase> {};

TEST_P(IntegratorOrder, IsSecondOrderOnElasticPendulum) {
  const OrderCase c = GetParam();
  // Bars: one second, about half a swing (the line passes the bottom at full speed). Beams: half a second
  // (their steps cost ~10x more).
  const double tEnd = c.beam ? 0.5 : 1.0;
  const double dt = c.beam ? 1e-3 : 5e-4;
  const model::State reference = integrate(c, dt / (c.beam ? 64.0 : 128.0), tEnd);
  std::vector<std::pair<double, double>> error;
  for (int k = 0; k < 4; ++k) error.push_back(maxError(integrate(c, dt / (1 << k), tEnd), reference));
  for (int k = 0; k + 1 < 4; ++k) {
    const double order = std::log2(error[k].first / error[k + 1].first);
    std::printf("%s: dt = %.3e s position error %.3e m, dt/2 %.3e m, observed order %.3f\n", c.name, dt / (1 << k),
                error[k].first, error[k + 1].first, order);
    EXPECT_GE(order, 1.9) << c.name << " between dt = " << dt / (1 << k) << " s and its half";
    if (c.beam) {
      const double rotationOrder = std::log2(error[k].second / error[k + 1].second);
      std::printf("%s: dt = %.3e s rotation error %.3e rad, dt/2 %.3e rad, observed order %.3f\n", c.name,
                  dt / (1 << k), error[k].second, error[k + 1].second, rotationOrder);
      EXPECT_GE(rotationOrder, 1.9) << c.name << " (rotations) between dt = " << dt / (1 << k) << " s and its half";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Schemes, IntegratorOrder,
    ::testing::Values(OrderCase{"GeneralizedAlpha_rho08", model::IntegratorKind::GeneralizedAlpha, 0.8},
                      OrderCase{"Newmark", model::IntegratorKind::Newmark, 1.0},
                      OrderCase{"Hht_rho08", model::IntegratorKind::Hht, 0.8},
                      OrderCase{"GeneralizedAlpha_rho08_drivenPivot", model::IntegratorKind::GeneralizedAlpha, 0.8, true},
                      OrderCase{"Newmark_drivenPivot", model::IntegratorKind::Newmark, 1.0, true},
                      OrderCase{"GeneralizedAlpha_rho08_beams", model::IntegratorKind::GeneralizedAlpha, 0.8, false, true},
                      OrderCase{"Newmark_beams", model::IntegratorKind::Newmark, 1.0, false, true}),
    [](const ::testing::TestParamInfo<OrderCase>& i) { return std::string(i.param.name); });

/// A step that converged and was then refused by its caller (lines passed through each other, or the error
/// control's estimate too large: DynamicAnalysis) is undone with restore(): the run must go on as if the
/// refused step had never been taken. Generalized alpha's a_n is its own variable, which M a_n + F_n = 0
/// does not hold (the balance is at the alpha-weighted points), and with mass-proportional Rayleigh damping
/// F_n leaves out a_R M v_n: until 2026-12-06 restore() re-solved a_n from M a_n = -F_n, and every retry
/// started from another acceleration than the refused step had. Compared: the pendulum integrated for 1 s at
/// dt = 0.01 s, once plainly and once with a step of 0.02 s taken and refused before each of the steps 30-39,
/// at rho_inf = 0.8 without and with Rayleigh damping (a_R = 0.5 1/s). Tolerance 1e-9 m: the two runs differ
/// by the predictor's history (restore drops it), i.e. by Newton's error, 1e-9 N against the inertia
/// stiffness M / (beta dt^2), below 1e-12 m per step.
class RefusedStep : public ::testing::TestWithParam<double> {};

TEST_P(RefusedStep, UndoneByRestoreLeavesTheRunAsIfNeverTaken) {
  model::DynamicSpec settings = integratorSettings(model::IntegratorKind::GeneralizedAlpha, 0.8);
  settings.rayleighAlpha = GetParam();
  const double dt = 0.01;  // [s]
  const auto run = [&](bool refuse) {
    Pendulum p = makePendulum(false, false);
    time::GeneralizedAlpha stepper(*p.assembler, settings, {});
    stepper.initialize(p.state);
    for (int k = 0; k < 100; ++k) {
      if (refuse && k >= 30 && k < 40) {
        model::State before = p.state;
        EXPECT_TRUE(stepper.step(p.state, 2.0 * dt).converged);
        stepper.restore(before);
        p.state = before;
      }
      EXPECT_TRUE(stepper.step(p.state, dt).converged) << "step " << k;
    }
    return p.state;
  };
  const model::State plain = run(false), refused = run(true);
  EXPECT_LT(maxError(plain, refused).first, 1e-9);
  EXPECT_LT((plain.velocity - refused.velocity).cwiseAbs().maxCoeff(), 1e-7);
}

INSTANTIATE_TEST_SUITE_P(GeneralizedAlpha, RefusedStep, ::testing::Values(0.0, 0.5),
                         [](const ::testing::TestParamInfo<double>& i) {
                           return i.param == 0.0 ? std::string("Undamped") : std::string("Rayleigh");
                         });

/// Total energy: kinetic + strain + gravity potential [J].
struct Energy {
  double kinetic = 0.0;
  double strain = 0.0;
  double potential = 0.0;
  double total() const { return kinetic + strain + potential; }
};

Energy energyOf(solver::Assembler& assembler, const model::State& state) {
  const model::Model& m = assembler.model();
  Energy e;
  // 1/2 v^T M v with the assembled mass (lumped translational mass and, for beams, rotational inertia).
  VecX mv = VecX::Zero(state.velocity.size());
  assembler.addMass(state, 0.0, nullptr, &state.velocity, &mv);
  e.kinetic = 0.5 * state.velocity.dot(mv);
  for (const model::LineElement& el : m.elements()) {
    if (el.bar) {
      // Bar strain energy EA / (2 L0) (l - L0)^2 = N^2 L0 / (2 EA), N = EA (l - L0) / L0 the axial force.
      const double n = el.bar->axialForce(state.position[el.node1], state.position[el.node2]);
      e.strain += n * n * el.bar->restLength() / (2.0 * el.bar->axialStiffness());
    } else {
      e.strain += el.beam->strainEnergy(state.position[el.node1], state.triad[el.node1], state.position[el.node2],
                                        state.triad[el.node2]);
    }
  }
  // The lumped weights are m_i g (Assembler::addWeight, in air), so the potential is sum m_i g z_i.
  for (int n = 0; n < m.nodeCount(); ++n) e.potential += m.nodeMass()[n] * m.environment().gravity * state.position[n].z();
  return e;
}

class EnergyConservation : public ::testing::TestWithParam<OrderCase> {};

TEST_P(EnergyConservation, TotalEnergyConstantOver100Periods) {
  const OrderCase c = GetParam();
  Pendulum p = makePendulum(false, c.beam);
  time::GeneralizedAlpha stepper(*p.assembler, integratorSettings(c.kind, c.rhoInf), {});
  stepper.initialize(p.state);
  const Energy e0 = energyOf(*p.assembler, p.state);
  // Period of the swing: measured from the upward zero crossings of the tip's x coordinate.
  const int tip = p.model->lines()[0].lastNode();
  // Bars: omega dt = 0.09 for the stiffest (axial) mode. The energy error of the trapezoidal rule on this
  // chaotic, nonlinear system scales as dt^2 (measured max |E - E0| / K_max over 100 periods: 1.9 % at
  // dt = 2e-3 s, 0.3 % at 1e-3 s, 0.1 % at 5e-4 s), so dt must be small enough for the 0.5 % bound.
  // Beams: the bending stiffness keeps the swing regular; 4e-3 s (omega dt = 0.64 for the nodal
  // rotations) already conserves energy to ~1e-4.
  const double dt = c.beam ? 4e-3 : 5e-4;
  double maxKinetic = 0.0, maxDrift = 0.0;
  std::vector<double> crossings;
  double previousX = p.state.position[tip].x();
  while (crossings.size() < 101) {
    const time::StepOutcome o = stepper.step(p.state, dt);
    ASSERT_TRUE(o.converged) << c.name << " at t = " << p.state.time;
    const Energy e = energyOf(*p.assembler, p.state);
    maxKinetic = std::max(maxKinetic, e.kinetic);
    maxDrift = std::max(maxDrift, std::abs(e.total() - e0.total()));
    const double x = p.state.position[tip].x();
    if (previousX < 0.0 && x >= 0.0) crossings.push_back(p.state.time);
    previousX = x;
    ASSERT_LT(p.state.time, 1000.0) << "the pendulum stopped swinging";
  }
  const double period = (crossings.back() - crossings.front()) / 100.0;
  std::printf("%s: %zu periods of %.4f s (%.1f s), max |E - E0| = %.3e J = %.3e of the max kinetic energy %.4f J\n",
              c.name, crossings.size() - 1, period, p.state.time, maxDrift, maxDrift / maxKinetic, maxKinetic);
  EXPECT_LE(maxDrift, 0.005 * maxKinetic) << c.name;
}

INSTANTIATE_TEST_SUITE_P(
    NonDissipative, EnergyConservation,
    ::testing::Values(OrderCase{"Newmark", model::IntegratorKind::Newmark, 1.0},
                      OrderCase{"GeneralizedAlpha_rho1", model::IntegratorKind::GeneralizedAlpha, 1.0},
                      OrderCase{"Newmark_beams", model::IntegratorKind::Newmark, 1.0, false, true}),
    [](const ::testing::TestParamInfo<OrderCase>& i) { return std::string(i.param.name); });

}  // namespace
}  // namespace tangle
