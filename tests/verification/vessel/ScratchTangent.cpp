#include <gtest/gtest.h>
#include <fmt/format.h>
#include <fmt/ostream.h>
#include <array>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>
#include "tangle/analysis/Simulation.hpp"
#include "tangle/geometry/Rotation.hpp"
namespace tangle {
namespace scratch {

constexpr double kPiValue = 3.141592653589793;
constexpr double kDepth = 345.0;
constexpr double kRho = 1025.0;
constexpr double kRadius = 40.0;        // fairlead radius from the reference point [m]
constexpr double kFairleadZ = -15.0;    // fairlead level in vessel axes [m]
constexpr double kAnchorSpan = 1000.0;  // horizontal fairlead-anchor distance at zero offset [m]
constexpr double kK33 = 1.5e7;          // heave stiffness [N/m]
constexpr double kK55 = 1.33e9;         // pitch stiffness [N m/rad]
constexpr double kCx = 0.8;
constexpr double kAreaX = 2500.0;       // [m^2]

/// The chain and wire of examples/catenary-mooring/model.yaml (sources there), drag switched off.
void addLineTypes(model::ModelSpec& spec) {
  section::LineType chain;
  chain.name = "chain76";
  chain.outerDiameter = 0.1368;
  chain.buoyancyDiameter = 0.1368;
  chain.contactDiameter = 0.1368;
  chain.massPerLength = 114.9;
  chain.axialStiffness = 4.93e8;
  chain.dragNormal = 0.0;
  chain.dragAxial = 0.0;
  chain.addedMassNormal = 1.0;
  chain.addedMassAxial = 0.5;
  section::LineType wire;
  wire.name = "wire96";
  wire.outerDiameter = 0.096;
  wire.buoyancyDiameter = 0.0831;
  wire.contactDiameter = 0.096;
  wire.massPerLength = 42.6;
  wire.axialStiffness = 7.9e8;
  wire.dragNormal = 0.0;
  wire.dragAxial = 0.0;
  wire.addedMassNormal = 1.0;
  spec.lineTypes[chain.name] = chain;
  spec.lineTypes[wire.name] = wire;
}

model::EnvironmentSpec environment(double currentSpeed) {
  model::EnvironmentSpec env;
  env.waterDepth = kDepth;
  env.waterDensity = kRho;
  env.seabed.normalStiffness = 1.0e5;
  env.seabed.frictionCoefficient = 0.0;
  if (currentSpeed > 0.0) env.current = {{0.0, currentSpeed, 0.0}, {-kDepth, currentSpeed, 0.0}};
  return env;
}

/// Fairlead of leg i in vessel axes (legs towards +x, +y, -x, -y).
Vec3 fairleadOffset(int i) {
  const double a = 0.5 * kPiValue * i;
  return Vec3(kRadius * std::cos(a), kRadius * std::sin(a), kFairleadZ);
}
Vec3 anchorPosition(int i) {
  const double a = 0.5 * kPiValue * i;
  // Resting on the seabed: one contact radius above it.
  return Vec3((kRadius + kAnchorSpan) * std::cos(a), (kRadius + kAnchorSpan) * std::sin(a), -kDepth + 0.5 * 0.1368);
}

model::LineSpec leg(int i, const model::EndSpec& fairlead) {
  model::LineSpec l;
  l.name = "leg" + std::to_string(i + 1);
  l.endA.kind = model::EndKind::Anchored;
  l.endA.position = anchorPosition(i);
  l.endB = fairlead;
  l.sections = {{"chain76", 250.0, 20}, {"wire96", 780.0, 65}, {"chain76", 100.0, 15}};
  l.contact = false;
  return l;
}

struct CoupledResult {
  Vec3 position;
  Mat3 rotation;
  std::array<Vec3, 4> fairleads;  // global fairlead positions of the found pose [m]
};

CoupledResult solveCoupled(double currentSpeed) {
  model::ModelSpec spec;
  spec.sourceFile = "moored vessel, coupled (test)";
  spec.environment = environment(currentSpeed);
  addLineTypes(spec);
  model::VesselSpec v;
  v.name = "semisub";
  v.mode = model::VesselMode::Free;
  v.mass = 4.5e7;
  v.inertia = Vec3(4.05e10, 4.05e10, 5.5e10);
  v.addedMass = {2.2e7, 2.2e7, 4.5e7, 2.0e10, 2.0e10, 2.5e10};
  v.hydrostaticStiffness = {0.0, 0.0, kK33, 1.33e9, kK55, 0.0};
  v.currentAreas = Vec3(kAreaX, kAreaX, 80.0);
  v.currentCoefficients.heading = {0.0, 0.5 * kPiValue, kPiValue, 1.5 * kPiValue};
  v.currentCoefficients.values = {Vec3(kCx, 0, 0), Vec3(0, kCx, 0), Vec3(-kCx, 0, 0), Vec3(0, -kCx, 0)};
  spec.vessels.push_back(v);
  for (int i = 0; i < 4; ++i) {
    model::EndSpec e;
    e.kind = model::EndKind::Vessel;
    e.vessel = "semisub";
    e.position = fairleadOffset(i);
    spec.lines.push_back(leg(i, e));
  }
  analysis::Simulation sim(std::move(spec));
  const solver::StaticResult r = sim.solveStatics();
  EXPECT_TRUE(r.converged) << r.message;
  CoupledResult out;
  const int node = sim.model().vesselNode(0);
  out.position = sim.state().position[node];
  out.rotation = sim.state().triad[node];
  for (int i = 0; i < 4; ++i) out.fairleads[i] = sim.vessels()->vesselPoint(sim.state(), 0, fairleadOffset(i));
  return out;
}

/// Forces the four lines exert on fairleads pinned at the given global positions (no vessel in the model).
std::array<Vec3, 4> mooringForces(const std::array<Vec3, 4>& fairleads) {
  model::ModelSpec spec;
  spec.sourceFile = "moored vessel, lines only (test)";
  spec.environment = environment(0.0);  // the lines have no drag anyway
  addLineTypes(spec);
  for (int i = 0; i < 4; ++i) {
    model::EndSpec e;
    e.kind = model::EndKind::Pinned;
    e.position = fairleads[i];
    spec.lines.push_back(leg(i, e));
  }
  analysis::Simulation sim(std::move(spec));
  const solver::StaticResult r = sim.solveStatics();
  EXPECT_TRUE(r.converged) << r.message;
  const std::vector<solver::LineSnapshot> lines = sim.snapshot();
  std::array<Vec3, 4> f;
  for (int i = 0; i < 4; ++i) f[i] = lines[i].endForceB;
  return f;
}


model::ModelSpec coupledSpec(double u, double x0 = 0.0) {
  model::ModelSpec spec;
  spec.sourceFile = "scratch";
  spec.environment = environment(u);
  addLineTypes(spec);
  model::VesselSpec v;
  v.name = "semisub";
  v.mode = model::VesselMode::Free;
  v.position = Vec3(x0, 0, 0);
  v.mass = 4.5e7;
  v.inertia = Vec3(4.05e10, 4.05e10, 5.5e10);
  v.addedMass = {2.2e7, 2.2e7, 4.5e7, 2.0e10, 2.0e10, 2.5e10};
  v.hydrostaticStiffness = {0.0, 0.0, kK33, 1.33e9, kK55, 0.0};
  v.currentAreas = Vec3(kAreaX, kAreaX, 80.0);
  v.currentCoefficients.heading = {0.0, 0.5 * kPiValue, kPiValue, 1.5 * kPiValue};
  v.currentCoefficients.values = {Vec3(kCx, 0, 0), Vec3(0, kCx, 0), Vec3(-kCx, 0, 0), Vec3(0, -kCx, 0)};
  spec.vessels.push_back(v);
  for (int i = 0; i < 4; ++i) {
    model::EndSpec e;
    e.kind = model::EndKind::Vessel;
    e.vessel = "semisub";
    e.position = fairleadOffset(i);
    spec.lines.push_back(leg(i, e));
  }
  return spec;
}

TEST(ScratchVessel, TangentFD) {
  analysis::Simulation sim(coupledSpec(0.0));
  EXPECT_TRUE(sim.solveStatics().converged);
  model::State s = sim.state();
  const int node = sim.model().vesselNode(0);
  const auto& dofs = sim.model().dofs();
  solver::SystemMatrix m(dofs);
  solver::AssemblyRequest req; req.wantMatrix = true; req.kf = 1.0; req.dynamic = false;
  VecX f0; sim.assembler().assemble(s, req, f0, &m);
  SparseMatrix k; m.build(k);
  MatX kd = MatX(k);
  const int dv = dofs.firstDof(node);
  // columns: vessel dofs and the end node of leg1
  std::vector<std::pair<int,int>> cols;  // (node, local dof)
  for (int c = 0; c < 6; ++c) cols.push_back({node, c});
  const int end1 = sim.model().lines()[0].lastNode();
  
  for (auto [n, c] : cols) {
    const double h = c < 3 ? 1e-4 : 1e-6;
    auto pert = [&](double sgn) { model::State p = s; if (c < 3) p.position[n][c] += sgn*h; else { Vec3 t = Vec3::Zero(); t[c-3] = sgn*h; p.triad[n] = geometry::expMap(t) * p.triad[n]; }
      solver::AssemblyRequest r2; r2.wantMatrix = false; VecX f; sim.assembler().assemble(p, r2, f, nullptr); return f; };
    VecX fd = (pert(1) - pert(-1)) / (2*h);
    const int col = dofs.equation(dofs.firstDof(n) + c);
    // compare rows at vessel dofs and end node dofs
    std::vector<int> rows; for (int i = 0; i < 6; ++i) rows.push_back(dv + i); for (int i=0;i<3;++i) rows.push_back(dofs.firstDof(end1)+i);
    std::printf("col node %d dof %d\n", n, c);
    for (int r : rows) { if (r < dv || c < 3) continue; const int eq = dofs.equation(r); std::printf("   row %d: K %.6e  FD %.6e\n", r, kd(eq, col), fd[r]); }
  }
}
}  // namespace scratch
}  // namespace tangle
namespace tangle { namespace scratch {
TEST(ScratchVessel, StaticsSpeeds) {
  for (double u : {0.1}) {
    analysis::Simulation sim(coupledSpec(u));
    const solver::StaticResult r = sim.solveStatics();
    const int node = sim.model().vesselNode(0);
    const Vec3 x = sim.state().position[node]; std::printf("U %.2f: %s; pos %g %g %g\n", u, r.message.c_str(), x.x(), x.y(), x.z());
  }
}
}}
namespace tangle { namespace scratch {
TEST(ScratchVessel, Continuation) {
  model::State prev;
  bool have = false; double xprev = 0.0;
  for (double u : {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.75, 0.9, 1.0}) {
    analysis::Simulation sim(coupledSpec(u, xprev));
    const auto t0 = std::chrono::steady_clock::now();
    const solver::StaticResult r = sim.solveStatics();
    const double w = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const int node = sim.model().vesselNode(0);
    const Vec3 x = sim.state().position[node];
    std::printf("U %.2f: %s; pos %g %g %g; %.2f s\n", u, r.message.c_str(), x.x(), x.y(), x.z(), w);
    if (r.converged) { prev = sim.state(); have = true; xprev = x.x(); }
  }
}
}}
namespace tangle { namespace scratch {
TEST(ScratchVessel, FullFD) {
  analysis::Simulation sim(coupledSpec(0.1));
  EXPECT_TRUE(sim.solveStatics().converged);
  model::State s = sim.state();
  const auto& dofs = sim.model().dofs();
  solver::SystemMatrix m(dofs);
  solver::AssemblyRequest req; req.wantMatrix = true; req.kf = 1.0; req.dynamic = false;
  VecX f0; sim.assembler().assemble(s, req, f0, &m);
  SparseMatrix k; m.build(k);
  MatX kd = MatX(k);
  const int neq = dofs.equationCount();
  MatX fdm = MatX::Zero(neq, neq);
  const auto& eqDofs = dofs.equationDofs();
  for (int j = 0; j < neq; ++j) {
    const int dof = eqDofs[j];
    int n = 0; while (n + 1 < dofs.nodeCount() && dofs.firstDof(n + 1) <= dof) ++n;
    const int c = dof - dofs.firstDof(n);
    const double h = c < 3 ? 1e-5 : 1e-7;
    auto pert = [&](double sgn) { model::State p = s; if (c < 3) p.position[n][c] += sgn*h; else { Vec3 t = Vec3::Zero(); t[c-3] = sgn*h; p.triad[n] = geometry::expMap(t) * p.triad[n]; }
      solver::AssemblyRequest r2; r2.wantMatrix = false; VecX f; sim.assembler().assemble(p, r2, f, nullptr); return f; };
    const VecX fd = (pert(1) - pert(-1)) / (2*h);
    for (int i = 0; i < neq; ++i) fdm(i, j) = fd[eqDofs[i]];
  }
  // largest discrepancies, relative to sqrt(diag_i diag_j)
  struct E { double rel; int i, j; };
  std::vector<E> es;
  for (int i = 0; i < neq; ++i) for (int j = 0; j < neq; ++j) {
    const double d = std::abs(kd(i,j) - fdm(i,j));
    const double sc = std::sqrt(std::abs(kd(i,i) * kd(j,j))) + 1e-30;
    if (d > 1e-3) es.push_back({d / sc, i, j});
  }
  std::sort(es.begin(), es.end(), [](const E& a, const E& b){ return a.rel > b.rel; });
  auto describe = [&](int eq) { const int dof = eqDofs[eq]; int n = 0; while (n + 1 < dofs.nodeCount() && dofs.firstDof(n + 1) <= dof) ++n; return sim.model().describeNode(n) + " dof " + std::to_string(dof - dofs.firstDof(n)); };
  for (std::size_t q = 0; q < std::min<std::size_t>(es.size(), 25); ++q) {
    const E& e = es[q];
    std::printf("rel %.3e  K %.6e FD %.6e  [%s] x [%s]\n", e.rel, kd(e.i,e.j), fdm(e.i,e.j), describe(e.i).c_str(), describe(e.j).c_str());
  }
  // asymmetry of FD
  double asym = 0; int ai=0, aj=0;
  for (int i = 0; i < neq; ++i) for (int j = 0; j < i; ++j) { const double d = std::abs(fdm(i,j)-fdm(j,i)) / (std::sqrt(std::abs(kd(i,i)*kd(j,j)))+1e-30); if (d > asym) { asym = d; ai = i; aj = j; } }
  std::printf("max FD asymmetry rel %.3e at [%s] x [%s]: %.6e vs %.6e\n", asym, describe(ai).c_str(), describe(aj).c_str(), fdm(ai,aj), fdm(aj,ai));
}
}}
#include "tangle/solver/LinearSolver.hpp"
namespace tangle { namespace scratch {
void ownNewton(double u, double regFactor, bool relative) {
  analysis::Simulation sim(coupledSpec(0.1));
  EXPECT_TRUE(sim.solveStatics().converged);  // start from U = 0.1 equilibrium
  analysis::Simulation sim2(coupledSpec(u));
  model::State s = sim.state();
  const auto& dofs = sim2.model().dofs();
  const int neq = dofs.equationCount();
  const auto& eqDofs = dofs.equationDofs();
  solver::LinearSolver ls;
  std::printf("U %.2f reg %.1e relative %d\n", u, regFactor, relative);
  for (int it = 0; it < 40; ++it) {
    solver::SystemMatrix m(dofs);
    solver::AssemblyRequest req; req.wantMatrix = true; req.kf = 1.0; req.dynamic = false;
    VecX f; sim2.assembler().assemble(s, req, f, &m);
    SparseMatrix k; m.build(k);
    VecX r(neq); for (int i = 0; i < neq; ++i) r[i] = f[eqDofs[i]];
    const VecX diag = k.diagonal().cwiseAbs();
    const double dmax = diag.maxCoeff();
    for (int i = 0; i < neq; ++i) k.coeffRef(i, i) += relative ? regFactor * diag[i] : regFactor * dmax;
    ASSERT_TRUE(ls.factorize(k));
    const VecX dq = -ls.solve(r);
    VecX full = VecX::Zero(dofs.fullDofCount());
    for (int i = 0; i < neq; ++i) full[eqDofs[i]] = dq[i];
    s.applyIncrement(dofs, full);
    std::printf("  it %2d |r| %.3e |dq| %.3e\n", it, r.cwiseAbs().maxCoeff(), dq.cwiseAbs().maxCoeff());
    if (r.cwiseAbs().maxCoeff() < 1e-3) break;
  }
}
TEST(ScratchVessel, OwnNewton) {
  ownNewton(0.2, 1e-12, false);
  ownNewton(0.2, 1e-12, true);
}
}}
