#include "tangle/time/GeneralizedAlpha.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>

#include "tangle/core/Error.hpp"
#include "tangle/geometry/Rotation.hpp"
#include "tangle/solver/ResidualNorm.hpp"

namespace tangle::time {

using solver::LinearSolver;
using solver::sameStep;


AlphaParameters AlphaParameters::from(model::IntegratorKind kind, double rho) {
  rho = std::clamp(rho, 0.0, 1.0);
  AlphaParameters p;
  switch (kind) {
    case model::IntegratorKind::GeneralizedAlpha:
      // Chung & Hulbert (1993), eq. (25) and (17)-(18), in the convention
      // (1 - am) M a_{n+1} + am M a_n + (1 - af) F_{n+1} + af F_n = 0.
      p.alphaM = (2.0 * rho - 1.0) / (rho + 1.0);
      p.alphaF = rho / (rho + 1.0);
      break;
    case model::IntegratorKind::Hht:
      // Hilber, Hughes & Taylor (1977): alpha_HHT = -af in [-1/3, 0].
      p.alphaM = 0.0;
      p.alphaF = std::clamp((1.0 - rho) / (1.0 + rho), 0.0, 1.0 / 3.0);
      break;
    case model::IntegratorKind::Newmark:
      p.alphaM = 0.0;
      p.alphaF = 0.0;
      break;
  }
  // Second-order accuracy and unconditional stability (Chung & Hulbert 1993 eq. 17 and 20).
  p.gamma = 0.5 - p.alphaM + p.alphaF;
  p.beta = 0.25 * (1.0 - p.alphaM + p.alphaF) * (1.0 - p.alphaM + p.alphaF);
  return p;
}

GeneralizedAlpha::GeneralizedAlpha(solver::Assembler& assembler, const model::DynamicSpec& settings,
                                   std::vector<model::PrescribedNode> prescribed)
    : m_assembler(&assembler),
      m_settings(settings),
      m_prescribed(std::move(prescribed)),
      m_params(AlphaParameters::from(settings.integrator, settings.spectralRadius)),
      m_newton(assembler, std::getenv("TANGLE_DEBUG_DYNAMICS") != nullptr),
      m_seabedPredictor(assembler),
      m_debug(std::getenv("TANGLE_DEBUG_DYNAMICS") != nullptr),
      m_choice(settings.solver) {
  const model::DofMap& dofs = assembler.model().dofs();
  for (int dof = 0; dof < dofs.fullDofCount(); ++dof)
    if (dofs.equation(dof) < 0) m_constrainedDofs.push_back(dof);
  m_prescribedDof.assign(dofs.fullDofCount(), false);
  for (const model::PrescribedNode& p : m_prescribed) {
    const int d = dofs.firstDof(p.node);
    for (int k = 0; k < 3; ++k)
      if (dofs.equation(d + k) < 0) m_prescribedDof[d + k] = true;
    // A prescribed rotation (vessel node): the rotational DOFs follow it too.
    if (dofs.hasRotations(p.node) && p.motion(0.0).hasRotation)
      for (int k = 3; k < 6; ++k) m_prescribedDof[d + k] = true;
  }
}

void GeneralizedAlpha::applyPrescribed(model::State& state, double t) const {
  const model::DofMap& dofs = m_assembler->model().dofs();
  for (const model::PrescribedNode& p : m_prescribed) {
    model::MotionValue m = p.motion(t);
    if (m_frozen) {  // held still at their positions of the frozen time
      m.velocity.setZero();
      m.acceleration.setZero();
      m.angularVelocity.setZero();
      m.angularAcceleration.setZero();
    }
    const int d = dofs.firstDof(p.node);
    for (int k = 0; k < 3; ++k) {
      if (dofs.equation(d + k) >= 0) continue;  // a released direction (roller) moves freely
      state.position[p.node][k] = p.basePosition[k] + m.displacement[k];
      state.velocity[d + k] = m.velocity[k];
      state.acceleration[d + k] = m.acceleration[k];
    }
    if (m.hasRotation && dofs.hasRotations(p.node)) {
      state.triad[p.node] = m.rotation;
      state.velocity.segment<3>(d + 3) = m.angularVelocity;
      state.acceleration.segment<3>(d + 3) = m.angularAcceleration;
    }
  }
}

void GeneralizedAlpha::evaluateStartForce(model::State& state) {
  m_previousSteps = 0;
  applyPrescribed(state, environmentTime(state.time));
  solver::AssemblyRequest request;
  request.time = environmentTime(state.time);
  request.dynamic = true;
  request.waves = !m_frozen;
  request.relaxation = m_frozen;
  request.wantMatrix = false;
  m_assembler->assemble(state, request, m_forceOld, nullptr);
}

void GeneralizedAlpha::restore(model::State& previous) { evaluateStartForce(previous); }

void GeneralizedAlpha::initialize(model::State& state) {
  evaluateStartForce(state);
  // Consistent initial acceleration of the free DOFs, M a0 = -(F0 + M_prescribed a_prescribed): zero
  // at a static equilibrium, but not when e.g. a DP unit held in statics is released at t = 0.
  const model::DofMap& dofs = m_assembler->model().dofs();
  const int neq = dofs.equationCount();
  if (neq == 0) return;
  VecX known = state.acceleration;
  for (int i = 0; i < neq; ++i) known[dofs.equationDofs()[i]] = 0.0;
  VecX inertia = VecX::Zero(dofs.fullDofCount());
  solver::SystemMatrix& matrix = m_newton.matrix();  // work space: the kept factorisation is dropped below
  matrix.clear();
  m_assembler->addMass(state, 1.0, &matrix, &known, &inertia);
  VecX rhs(neq);
  for (int i = 0; i < neq; ++i)
    rhs[i] = -(m_forceOld[dofs.equationDofs()[i]] + inertia[dofs.equationDofs()[i]]);
  if (rhs.cwiseAbs().maxCoeff() <= m_settings.tolerance * m_assembler->forceScale()) return;  // at rest
  SparseMatrix mass;
  matrix.build(mass);
  LinearSolver solver;
  if (!solver.factorize(mass)) return;
  const VecX a0 = solver.solve(rhs);
  for (int i = 0; i < neq; ++i) state.acceleration[dofs.equationDofs()[i]] = a0[i];
  m_newton.invalidate();
}

void GeneralizedAlpha::moveNodes(model::State& state, const model::State& start, const VecX& dq,
                                 double dt) const {
  const model::DofMap& dofs = m_assembler->model().dofs();
  const AlphaParameters& p = m_params;
  const VecX& v0 = start.velocity;
  const VecX& a0 = start.acceleration;
  for (const int n : m_newton.movedNodes()) {
    const int d = dofs.firstDof(n);
    // Free directions only: prescribed ones keep what applyPrescribed set, fixed ones their start.
    for (int k = 0; k < 3; ++k)
      if (dofs.equation(d + k) >= 0) state.position[n][k] = start.position[n][k] + dq[d + k];
    // A node with some rotations free turns by their increments (its fixed ones are zero in dq): a torsion
    // lock fixes one rotation of a held beam end (Model::addLine), about x for a line along x, and until
    // 2026-12-06 the test of that first rotation alone left such an end's triad behind on parts.
    if (dofs.hasRotations(n) && !m_prescribedDof[d + 3] &&
        (dofs.equation(d + 3) >= 0 || dofs.equation(d + 4) >= 0 || dofs.equation(d + 5) >= 0)) {
      const Vec3 dtheta = dq.segment<3>(d + 3);
      state.triad[n] =
          dtheta.squaredNorm() > 0.0 ? Mat3(geometry::expMap(dtheta) * start.triad[n]) : start.triad[n];
    }
    // The Newmark relations of step(), entry by entry.
    for (int dof = d; dof < d + dofs.dofCount(n); ++dof) {
      if (dofs.equation(dof) < 0) continue;
      state.acceleration[dof] =
          (dq[dof] - dt * v0[dof] - dt * dt * (0.5 - p.beta) * a0[dof]) / (p.beta * dt * dt);
      state.velocity[dof] = v0[dof] + dt * ((1.0 - p.gamma) * a0[dof] + p.gamma * state.acceleration[dof]);
    }
  }
}

StepOutcome GeneralizedAlpha::step(model::State& state, double dt) {
  // The chosen path first; a step it does not converge is tried again, from the same start, with a whole
  // refresh of the matrix (no parts, no blocks or stretches refreshed on their own) and then with full
  // Newton, before the caller cuts it: a speed path may change the cost of a run, never whether it completes
  // (issue 44: a hose lowered onto a pipeline stopped at t = 0.43 s on block refreshes that kept converging
  // linearly, and ran its 40 s with whole refreshes).
  StepOutcome outcome = attempt(state, dt, m_choice);
  if (outcome.converged) return outcome;
  model::DynamicSolverSpec wholeRefresh = m_choice;
  wholeRefresh.partIterations = false;
  wholeRefresh.blockRefresh = false;
  model::DynamicSolverSpec fullNewton = wholeRefresh;
  fullNewton.modifiedNewton = false;
  int level = 0;
  for (const model::DynamicSolverSpec& fallback : {wholeRefresh, fullNewton}) {
    ++level;
    const model::DynamicSolverSpec& tried = m_newton.mode();
    const bool plainer = fallback.modifiedNewton != tried.modifiedNewton ||
                         fallback.partIterations != tried.partIterations ||
                         fallback.blockRefresh != tried.blockRefresh;
    if (!plainer) continue;  // already tried: the chosen path was this plain
    m_newton.invalidate();  // a fresh matrix at the step's first iterate
    if (m_debug) std::cerr << fmt::format("    step of {:.3e} s retried: fallback {}\n", dt, level);
    StepOutcome retry = attempt(state, dt, fallback);
    retry.iterations += outcome.iterations;
    retry.partIterations += outcome.partIterations;
    retry.blocksLeft += outcome.blocksLeft;
    retry.refreshes += outcome.refreshes;
    retry.blockRefreshes += outcome.blockRefreshes;
    retry.stepLengthChanges += outcome.stepLengthChanges;
    retry.fallback = level;
    outcome = retry;
    if (outcome.converged) break;
  }
  // The fallback's matrix is of the chosen kind for the next step as well (a whole matrix is a valid kept
  // matrix); a full Newton's last factorisation is of the last iterate, which the next step may keep.
  return outcome;
}

StepOutcome GeneralizedAlpha::attempt(model::State& state, double dt, const model::DynamicSolverSpec& mode) {
  const model::Model& model = m_assembler->model();
  const model::DofMap& dofs = model.dofs();
  const int nfull = dofs.fullDofCount();
  const int neq = dofs.equationCount();
  const auto& eqDofs = dofs.equationDofs();
  const AlphaParameters& p = m_params;
  const double t1 = state.time + dt;
  const double rayleighAlpha = m_settings.rayleighAlpha;

  // Work space kept from step to step (no allocation per step once sized).
  m_start.assignFrom(state, dofs);
  const model::State& start = m_start;
  const VecX& v0 = start.velocity;
  const VecX& a0 = start.acceleration;

  // Increment over the step per full DOF; predictor: constant acceleration when the step is the one the
  // acceleration was found with, else constant velocity. (Extrapolated over a longer step, the large
  // accelerations of an impact resolved with tiny steps land far beyond the next state; at an unchanged step
  // the constant-acceleration guess removes the O(dt^2 a) error of the free nodes next to a prescribed end,
  // the largest predictor residual of a moored line: 7.5 % fewer residual assemblies on the mooring example.)
  VecX& dq = m_dq;
  dq = dt * v0;
  if (sameStep(dt, m_lastStep)) {
    dq += 0.5 * dt * dt * a0;
    // Where the step resolves the motion, the acceleration extrapolated linearly from the last two step
    // starts, a_{n+1} = 2 a_n - a_{n-1}: by the Newmark relation dq = dt v_n + dt^2 ((1/2 - beta) a_n +
    // beta a_{n+1}) that adds beta dt^2 (a_n - a_{n-1}), and the predictor's error on a smooth motion falls
    // from O(dt^3) to O(dt^4) (theory manual 8.2). A coupled host's chain at 0.01 s: 2.83 -> 2.23 residual
    // evaluations per step, most steps converged on their first correction (docs/performance.md). Where it
    // would not pay, the constant acceleration stays:
    // - a step that does not resolve the seabed spring (SeabedPredictor::resolves, omega dt >= 1): a grounded
    //   node ringing on it changes its acceleration's sign from step to step (12 lines at dt 0.05 s: 4.29 ->
    //   4.45 per step with it);
    // - per translation, where the extrapolation would have missed a_n by more than the constant one did
    //   (|a_n - 2 a_{n-1} + a_{n-2}| >= |a_n - a_{n-1}|), i.e. the acceleration does not change smoothly
    //   there, and in part where it would have missed by more than half as much (examples/units-collide,
    //   against the constant acceleration: 25 % more evaluations without the test);
    // - beam nodes (rotations): a steel riser's touchdown took 10 % more (examples/scr-fatigue), as with
    //   SeabedPredictor's correction (which moves soft beams' nodes alone);
    // - nodes near a line contact, or tied to a vessel or a free point (Assembler::loadedNodes): an impact is
    //   no smooth motion, and a predictor carried past it can start Newton on another branch of the contact
    //   problem (RandomSweepTest: a sweep that gained 19 % of its launch energy, another that stopped).
    if (m_previousSteps >= 2 && mode.seabedPredictor && sameStep(dt, m_stepBefore) &&
        m_seabedPredictor.resolves(start, dt)) {
      // The DOFs extrapolated, as weights 1 (one flat loop over the DOFs: node by node, the loop was 4 % of a
      // coupled host's run): free cable nodes' translations, less the loaded nodes now.
      if (m_cableTranslation.size() != nfull) {
        m_cableTranslation.setZero(nfull);
        for (int node = 0; node < dofs.nodeCount(); ++node)
          if (!dofs.hasRotations(node)) m_cableTranslation.segment<3>(dofs.firstDof(node)).setOnes();
      }
      const double* eligible = m_cableTranslation.data();
      if (m_assembler->anyLoadedNode()) {
        m_extrapolated = m_cableTranslation;
        const std::vector<char>& loaded = m_assembler->loadedNodes();
        for (int node = 0; node < dofs.nodeCount(); ++node)
          if (loaded[static_cast<std::size_t>(node)])
            m_extrapolated.segment(dofs.firstDof(node), dofs.dofCount(node)).setZero();
        eligible = m_extrapolated.data();
      }
      const double* an = a0.data();
      const double* a1 = m_previousAcceleration.data();
      const double* a2 = m_olderAcceleration.data();
      double* increment = dq.data();
      const double c = p.beta * dt * dt;
      for (int dof = 0; dof < nfull; ++dof) {
        const double change = an[dof] - a1[dof];                 // a_n - a_{n-1}
        const double linearMiss = change - (a1[dof] - a2[dof]);  // a_n - (2 a_{n-1} - a_{n-2})
        // Weight 1 where the linear miss is at most half the constant one's, 0 where it is not smaller,
        // linear between: continuous in the accelerations, so that two runs whose states differ by round-off
        // predict what differs by round-off (a yes-or-no choice flipped between a C host and `tangle run` on
        // the same motion, and their converged tensions differed by the tolerance). As
        // change w = sign(change) max(0, min(|change|, 2 room)): no division, no branch.
        const double room = std::abs(change) - std::abs(linearMiss);
        increment[dof] +=
            c * eligible[dof] * std::copysign(std::max(0.0, std::min(std::abs(change), 2.0 * room)), change);
      }
    }
  }
  // Prescribed DOFs follow their motion exactly. applyPrescribed sets in `target` every entry read below
  // (the held directions' positions and the prescribed triads), so the rest of it is never refreshed: a
  // copy of the whole state per step is avoided (docs/performance.md).
  model::State& target = m_target;
  if (target.position.size() != start.position.size() || target.triad.size() != start.triad.size())
    target = start;
  applyPrescribed(target, environmentTime(t1));
  for (const model::PrescribedNode& pn : m_prescribed) {
    const int d = dofs.firstDof(pn.node);
    for (int k = 0; k < 3; ++k)
      if (m_prescribedDof[d + k]) dq[d + k] = target.position[pn.node][k] - start.position[pn.node][k];
    if (dofs.hasRotations(pn.node) && m_prescribedDof[d + 3])
      dq.segment<3>(d + 3) = geometry::logMap(target.triad[pn.node] * start.triad[pn.node].transpose());
  }
  // Other constrained DOFs stay where they are.
  for (const int dof : m_constrainedDofs)
    if (!m_prescribedDof[dof]) dq[dof] = 0.0;
  // Convergence: every free DOF's out-of-balance force below tol times its line's weight (moments over the
  // node's moment scale), or below the round-off floor of the elements at its node (Section 8.2 of the
  // theory manual). Per node: one global scale, the largest line's weight, would make a light line's test
  // meaningless next to a heavy one; the former scale, the largest element weight, made the test stricter
  // as the mesh was refined (1e-8 of the tension on a 200-bar mooring line, 4.8 residual assemblies per
  // step where 3.5 give the same tension ranges to 1.5e-4). Set here: the seabed predictor reads it.
  // (Where no node's floor can reach its tolerance, a floor of zero gives the same allowances: the floors
  // were a pass over the elements at every step, 1.7 % of a coupled host's run.)
  if (!m_assembler->roundoffFloorNegligible(start, m_settings.tolerance)) {
    m_assembler->nodeRoundoffFloor(start, m_nodeFloor);
    m_floorZero = false;
  } else if (!m_floorZero) {
    m_nodeFloor.assign(static_cast<std::size_t>(model.nodeCount()), 0.0);
    m_floorZero = true;
  }
  m_newton.setAllowed(m_settings.tolerance, m_nodeFloor);
  // Nodes on, or predicted onto, the seabed: the change of their seabed reaction within the step balanced
  // against their inertia (SeabedPredictor). Only with the constant-acceleration predictor, whose premise
  // (the rest of the force unchanged over the step) the correction shares.
  if (mode.seabedPredictor && sameStep(dt, m_lastStep)) {
    const PredictorCoefficients coefficients{p.beta, p.gamma, 1.0 - p.alphaM, 1.0 - p.alphaF};
    m_seabedPredictor.correct(start, coefficients, dt, m_newton.allowedForce(), dq);
  }
  // A contact barrier filters the predictor too: extrapolated over a step much longer than an impact, it
  // can carry a line through another (a 20 m/s bar 1 m past a wire in one 0.05 s step: TunnellingTest),
  // where no corrected iterate finds the way back. The free DOFs' increment is shortened; Newton then
  // starts on the right side of every contact.
  if (m_assembler->limitsDynamicIncrements()) {
    const double alpha = m_assembler->limitDynamicIncrement(start, dq);
    if (alpha < 1.0)
      for (int i = 0; i < neq; ++i) dq[eqDofs[i]] *= alpha;
    if (m_debug && alpha < 1.0) std::cerr << fmt::format("    contact filter: predictor x {:.3e}\n", alpha);
  }

  const double mf =
      (1.0 - p.alphaM) / (p.beta * dt * dt) + rayleighAlpha * (1.0 - p.alphaF) * p.gamma / (p.beta * dt);
  solver::AssemblyRequest request;
  request.time = environmentTime(t1);
  request.dynamic = true;
  request.waves = !m_frozen;
  request.relaxation = m_frozen;
  request.kf = 1.0 - p.alphaF;
  request.cf = (1.0 - p.alphaF) * p.gamma / (p.beta * dt);

  StepOutcome outcome;
  VecX& combo = m_combo;
  VecX& inertia = m_inertia;
  VecX& r = m_residual;
  combo.resize(nfull);
  inertia.resize(nfull);
  r.resize(neq);
  m_assembler->beginStep();
  // Iterations on a part: with a kept matrix (modified Newton) and forces local to elements and nodes.
  // Not in dynamic relaxation (a statics method): there line contact's active set, which grows with every
  // whole assembly of a step, took a different path with parts, and the lazy-wave SCR in contact of the
  // statics trials (converged in 147 s with whole assemblies) no longer converged.
  const bool partsAllowed =
      mode.modifiedNewton && mode.partIterations && !m_frozen && m_assembler->supportsParts();
  bool onPart = false;  // this iterate differs from the last evaluated one only at the nodes moved
  // Modified Newton: the factorised iteration matrix is kept while the residual falls fast (by 4x or
  // more per iteration) and refreshed when convergence slows, when the step size changed, or when keeping
  // it has come to cost more iterations than a refresh (solver::NewtonIteration).
  m_newton.startAttempt(start, dt, mode, mf);
  const solver::AssemblyPart& part = m_newton.part();
  bool haveResidual = false;
  for (int it = 0; it < m_settings.maxIterations; ++it) {
    outcome.iterations = it + 1;
    if (onPart) {
      ++outcome.partIterations;
      moveNodes(state, start, dq, dt);
    } else {
      // Every iterate is exp(dtheta) of the step's start triad (orthonormal): one re-orthonormalisation of
      // the converged state is enough (it was 2-3 per step: docs/performance.md).
      state.setIncremented(start, dofs, dq);
      state.time = t1;
      // Newmark relations for the free DOFs (and any unprescribed constrained DOF: zero motion).
      state.acceleration = (dq - dt * v0 - dt * dt * (0.5 - p.beta) * a0) / (p.beta * dt * dt);
      state.velocity = v0 + dt * ((1.0 - p.gamma) * a0 + p.gamma * state.acceleration);
      for (const int dof : m_constrainedDofs) {
        state.velocity[dof] = 0.0;
        state.acceleration[dof] = 0.0;
      }
      applyPrescribed(state, environmentTime(t1));
    }

    const bool refresh = m_newton.wantsMatrix();
    request.wantMatrix = refresh;
    try {
      // On a part the other entries of m_force are those of the last iterate, which they equal.
      if (onPart)
        m_assembler->assemblePart(state, request, part, m_force);
      else
        m_assembler->assemble(state, request, m_force, &m_newton.matrix());
    } catch (const Error& e) {
      // An element cannot be evaluated at this iterate (e.g. folded back on itself): the step is too
      // long; report a failed step so the controller cuts it.
      if (m_debug) std::cerr << "    assembly failed: " << e.what() << "\n";
      outcome.failure = fmt::format("an element cannot be evaluated ({})", e.what());
      break;
    }
    // Every mass term is M times one combination of accelerations and velocities; on a part only the
    // moved nodes' velocities and accelerations changed, so only their entries are computed again.
    // (The coefficients and arrays in locals: a store into combo or r may alias the parameters' doubles,
    // which were loaded again at every entry; the same arithmetic.)
    const double newAcceleration = 1.0 - p.alphaM, oldAcceleration = p.alphaM;
    const double newForce = 1.0 - p.alphaF, oldForce = p.alphaF;
    const double* acceleration = state.acceleration.data();
    const double* velocity = state.velocity.data();
    double* comboData = combo.data();
    const auto setCombination = [&](int dof) {
      double c = newAcceleration * acceleration[dof] + oldAcceleration * a0[dof];
      if (rayleighAlpha > 0.0) c += rayleighAlpha * (newForce * velocity[dof] + oldForce * v0[dof]);
      comboData[dof] = c;
    };
    if (onPart) {
      for (const int node : m_newton.movedNodes())
        for (int dof = dofs.firstDof(node); dof < dofs.firstDof(node) + dofs.dofCount(node); ++dof)
          setCombination(dof);
    } else if (rayleighAlpha > 0.0) {
      for (int dof = 0; dof < nfull; ++dof) setCombination(dof);
    } else {
      const double* a0Data = a0.data();
      for (int dof = 0; dof < nfull; ++dof)
        comboData[dof] = newAcceleration * acceleration[dof] + oldAcceleration * a0Data[dof];
    }
    if (onPart) {
      m_assembler->addPartMass(state, part, combo, inertia);
      for (const int node : part.nodes) {
        const int d = dofs.firstDof(node);
        for (int dof = d; dof < d + dofs.dofCount(node); ++dof) {
          const int i = dofs.equation(dof);
          if (i >= 0) r[i] = inertia[dof] + (1.0 - p.alphaF) * m_force[dof] + p.alphaF * m_forceOld[dof];
        }
      }
    } else {
      inertia.setZero();
      m_assembler->addMass(state, mf, refresh ? &m_newton.matrix() : nullptr, &combo, &inertia);
      const double* inertiaData = inertia.data();
      const double* force = m_force.data();
      const double* forceOld = m_forceOld.data();
      const int* equationDof = eqDofs.data();
      double* residual = r.data();
      for (int i = 0; i < neq; ++i) {
        const int dof = equationDof[i];
        residual[i] = inertiaData[dof] + newForce * force[dof] + oldForce * forceOld[dof];
      }
    }
    haveResidual = true;
    // Largest out-of-balance relative to what each DOF is allowed (NaN if r holds a NaN). The norm in
    // N (outcome.residual) is for the report: computed once, after the iterations.
    const double ratio = m_newton.residualRatio(r, onPart);
    if (m_debug) {
      outcome.residual =
          solver::residualNorm(model, r, solver::ResidualIndexing::Equations, &outcome.worstNode);
      std::cerr << fmt::format(
          "    t {:.6f} dt {:.3e} it {:2d} |r| {:.4e} ({:.3e} of the tolerance) worst node {}{}\n", t1, dt,
          it, outcome.residual, ratio, outcome.worstNode,
          onPart ? fmt::format(" (part of {} nodes)", part.nodes.size()) : std::string());
    }
    if (!std::isfinite(ratio)) {
      // Name where: the first equation whose out-of-balance is not finite, and what it is.
      for (int i = 0; i < neq; ++i) {
        if (std::isfinite(r[i])) continue;
        outcome.failure = fmt::format(
            "the out-of-balance force is not finite ({}) at {}: an element or a load there gave {}", r[i],
            model.describeNode(dofs.nodeOf(eqDofs[i])), r[i]);
        outcome.worstNode = dofs.nodeOf(eqDofs[i]);
        break;
      }
      break;
    }
    if (ratio <= 1.0) {
      // Converged for this active set; if a contact had to be released, iterate on.
      if (!m_assembler->updateActiveSet()) {
        outcome.converged = true;
        break;
      }
      onPart = false;
      continue;
    }
    if (!m_newton.afterResidual(state, request, mf, r, ratio, refresh)) {
      onPart = false;  // the refresh assembles the whole matrix at this iterate
      --it;
      continue;
    }
    if (refresh && !m_newton.factorize(dt, mf)) {
      outcome.failure = "the iteration matrix is singular";
      break;
    }
    m_newton.solveCorrection(r);
    VecX& delta = m_newton.correction();
    if (m_debug) {
      Eigen::Index imax = 0;
      r.cwiseAbs().maxCoeff(&imax);
      std::cerr << fmt::format("      max |r| at eq {} (full dof {}), |delta| {:.3e}\n", imax, eqDofs[imax],
                               delta.cwiseAbs().maxCoeff());
    }
    // A contact barrier (the distributed formulation) filters the correction so no iterate jumps past it.
    if (m_assembler->limitsDynamicIncrements()) {
      VecX& full = m_fullCorrection;
      full.setZero(nfull);
      for (int i = 0; i < neq; ++i) full[eqDofs[i]] = delta[i];
      const double alpha = m_assembler->limitDynamicIncrement(state, full);
      if (alpha < 1.0) delta *= alpha;
      if (m_debug && alpha < 1.0)
        std::cerr << fmt::format("      contact filter: correction x {:.3e}\n", alpha);
    }
    onPart = m_newton.applyCorrection(dq, partsAllowed);
  }
  // The norm in N and its node are for the message of a failed step (a converged step's largest
  // out-of-balance is below the tolerance by definition; the norm per step is not free: docs/performance.md).
  if (haveResidual && (!outcome.converged || m_debug) && outcome.failure.empty())
    outcome.residual =
        solver::residualNorm(model, r, solver::ResidualIndexing::Equations, &outcome.worstNode);
  const solver::MatrixWork& work = m_newton.work();
  outcome.refreshes = work.refreshes;
  outcome.blockRefreshes = work.blockRefreshes;
  outcome.stepLengthChanges = work.stepLengthChanges;
  outcome.blocksLeft = work.blocksLeft;
  if (!outcome.converged) {
    state = start;
    return outcome;
  }
  state.orthonormaliseTriads(dofs);
  m_forceOld = m_force;
  m_olderAcceleration.swap(m_previousAcceleration);
  m_previousAcceleration = start.acceleration;
  m_previousSteps = std::min(m_previousSteps + 1, 2);  // two are all the predictor reads
  m_stepBefore = m_lastStep;
  m_lastStep = dt;
  m_newton.planRefresh(outcome.iterations, outcome.partIterations, m_frozen);
  return outcome;
}

}  // namespace tangle::time
