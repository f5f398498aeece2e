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

namespace {
/// max_i |r_i| w_i in four register-held accumulators; NaN if any r_i is NaN (std::max would drop it).
/// Not inlined: inside GeneralizedAlpha::step the compiler kept an accumulator in a stack slot, and the
/// loop, waiting on a store and a load per element, was a fifth of that function (docs/performance.md).
/// Over entries [0, n) of a (out-of-balance) and b (1 / allowed).
[[gnu::noinline]] double largestScaled(const double* a, const double* b, Eigen::Index n) {
  double m0 = 0.0, m1 = 0.0, m2 = 0.0, m3 = 0.0;
  bool nan = false;
  Eigen::Index i = 0;
  for (; i + 3 < n; i += 4) {
    const double v0 = std::abs(a[i]) * b[i], v1 = std::abs(a[i + 1]) * b[i + 1];
    const double v2 = std::abs(a[i + 2]) * b[i + 2], v3 = std::abs(a[i + 3]) * b[i + 3];
    m0 = v0 > m0 ? v0 : m0;
    m1 = v1 > m1 ? v1 : m1;
    m2 = v2 > m2 ? v2 : m2;
    m3 = v3 > m3 ? v3 : m3;
    nan |= (v0 != v0) | (v1 != v1) | (v2 != v2) | (v3 != v3);
  }
  for (; i < n; ++i) {
    const double v = std::abs(a[i]) * b[i];
    m0 = v > m0 ? v : m0;
    nan |= v != v;
  }
  return nan ? std::numeric_limits<double>::quiet_NaN() : std::max(std::max(m0, m1), std::max(m2, m3));
}
/// True when two step lengths [s] are the same step: equal but for round-off. A step cut to land on an
/// output time is the difference of two times (0.1 - 0.09 = 0.010000000000000009, not 0.01): compared
/// exactly, the step to and the step after every output time threw the kept factorisation away and fell
/// back to the constant-velocity predictor (4 000 refreshes in the 20 000 steps of the mooring example).
bool sameStep(double a, double b) { return std::abs(a - b) <= 1e-9 * std::abs(b); }
}  // namespace

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
      m_matrix(assembler.model().dofs()),
      m_debug(std::getenv("TANGLE_DEBUG_DYNAMICS") != nullptr),
      m_choice(settings.solver),
      m_mode(settings.solver) {
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

void GeneralizedAlpha::initialize(model::State& state) {
  applyPrescribed(state, environmentTime(state.time));
  solver::AssemblyRequest request;
  request.time = environmentTime(state.time);
  request.dynamic = true;
  request.waves = !m_frozen;
  request.relaxation = m_frozen;
  request.wantMatrix = false;
  m_assembler->assemble(state, request, m_forceOld, nullptr);
  // Consistent initial acceleration of the free DOFs, M a0 = -(F0 + M_prescribed a_prescribed): zero
  // at a static equilibrium, but not when e.g. a DP unit held in statics is released at t = 0.
  const model::DofMap& dofs = m_assembler->model().dofs();
  const int neq = dofs.equationCount();
  if (neq == 0) return;
  VecX known = state.acceleration;
  for (int i = 0; i < neq; ++i) known[dofs.equationDofs()[i]] = 0.0;
  VecX inertia = VecX::Zero(dofs.fullDofCount());
  m_matrix.clear();
  m_assembler->addMass(state, 1.0, &m_matrix, &known, &inertia);
  VecX rhs(neq);
  for (int i = 0; i < neq; ++i)
    rhs[i] = -(m_forceOld[dofs.equationDofs()[i]] + inertia[dofs.equationDofs()[i]]);
  if (rhs.cwiseAbs().maxCoeff() <= m_settings.tolerance * m_assembler->forceScale()) return;  // at rest
  SparseMatrix mass;
  m_matrix.build(mass);
  LinearSolver solver;
  if (!solver.factorize(mass)) return;
  const VecX a0 = solver.solve(rhs);
  for (int i = 0; i < neq; ++i) state.acceleration[dofs.equationDofs()[i]] = a0[i];
  m_factorValid = false;
}

void GeneralizedAlpha::moveNodes(model::State& state, const model::State& start, const VecX& dq,
                                 double dt) const {
  const model::DofMap& dofs = m_assembler->model().dofs();
  const AlphaParameters& p = m_params;
  const VecX& v0 = start.velocity;
  const VecX& a0 = start.acceleration;
  for (const int n : m_moved) {
    const int d = dofs.firstDof(n);
    // Free directions only: prescribed ones keep what applyPrescribed set, fixed ones their start.
    for (int k = 0; k < 3; ++k)
      if (dofs.equation(d + k) >= 0) state.position[n][k] = start.position[n][k] + dq[d + k];
    if (dofs.hasRotations(n) && dofs.equation(d + 3) >= 0) {
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

bool GeneralizedAlpha::applyCorrection(VecX& dq, bool partsAllowed) {
  const model::DofMap& dofs = m_assembler->model().dofs();
  const auto& eqDofs = dofs.equationDofs();
  const int neq = dofs.equationCount();
  const int nodes = dofs.nodeCount();
  // Where parts never apply (corrections spread over most of the model, or into a vessel's or a contact's
  // nodes: the drilling riser, 259 parts in 57 046 corrections), trying costs a pass over the equations and
  // the nodes at every correction (docs/performance.md): after kFutileTries corrections in a row without a
  // part, the next kPausedTries go whole without trying.
  constexpr int kFutileTries = 64, kPausedTries = 512;
  if (m_partsPaused > 0) {
    --m_partsPaused;
    partsAllowed = false;
  }
  if (partsAllowed && m_kDiagonal.size() == neq) {
    // A correction delta_i changes the force at its DOF by about H_ii delta_i (H: the iteration matrix, whose
    // diagonal dominates: mass / (beta dt^2) plus the stiffness to the neighbours). A node where that is
    // at most kNegligibleCorrection of the allowed out-of-balance at every DOF is left where it is. After
    // the first correction of a step only the touchdown zone of a mooring line still moves by more. The
    // convergence test stays on the exact residual of the whole model (the part's assembly gives the
    // whole model's entries), so a dropped correction can cost an iteration but never passes an
    // unconverged state. Measured (theory manual 8.2): 0.5 saved most on the 200-bar mooring example but
    // cost 16 % more iterations on 800 bars, where the dropped corrections add up; 0.2 costs 1 % there.
    constexpr double kNegligibleCorrection = 0.2;
    // Node by node in ascending order (AssemblyPart's): a node's equations are consecutive (DofMap) and lie
    // in one block, so the nodes of a range of equations are those between its first and last equation's.
    // A node's test is formed without branches (whether a correction is negligible does not follow a
    // pattern) over its equations and stored once (an update of a mark per equation waited on the store of
    // the one before: docs/performance.md).
    // The equations' tests first, in one pass without branches, then their OR per node (docs/performance.md).
    m_moved.clear();
    m_equationMoved.resize(static_cast<std::size_t>(neq));
    for (const auto& range : m_activeRanges) {
      // Bounds and arrays in locals: the flags' stores (unsigned char) may alias anything, so a bound read
      // through the range was loaded again at every equation.
      const int begin = range.first, end = range.second;
      const double* delta = m_delta.data();
      const double* diagonal = m_kDiagonal.data();
      const double* inverseAllowed = m_inverseAllowed.data();
      unsigned char* flag = m_equationMoved.data();
      for (int i = begin; i < end; ++i)
        flag[i] = std::abs(delta[i] * diagonal[i]) * inverseAllowed[i] > kNegligibleCorrection ? 1 : 0;
      for (int node = dofs.nodeOf(eqDofs[begin]); node <= dofs.nodeOf(eqDofs[end - 1]); ++node) {
        unsigned char moved = 0;
        for (int i = dofs.firstEquation(node); i < dofs.firstEquation(node + 1); ++i) moved |= flag[i];
        if (moved) m_moved.push_back(node);
      }
    }
    // A part pays while it is clearly smaller than the model (its assembly also re-evaluates the moved
    // nodes' neighbours and their elements), and a correction spread over most of the model is better
    // applied whole: up to half the nodes (measured on 200 and 800 bars against 30 % and 80 %: equal within
    // the machine's noise at 200 bars, 80 % costs more iterations at 800).
    // (And when no contributor left out of parts loads a node of the part: a vessel, a contact.)
    if (!m_moved.empty() && 2 * m_moved.size() <= static_cast<std::size_t>(nodes) &&
        m_assembler->selectPart(m_moved, m_part)) {
      for (const int node : m_moved) {
        const int d = dofs.firstDof(node);
        for (int dof = d; dof < d + dofs.dofCount(node); ++dof) {
          const int i = dofs.equation(dof);
          if (i >= 0) dq[dof] += m_delta[i];
        }
      }
      if (m_debug) std::cerr << "      correction at " << m_moved.size() << " of " << nodes << " nodes\n";
      m_futileTries = 0;
      return true;
    }
    if (++m_futileTries >= kFutileTries) {
      m_futileTries = 0;
      m_partsPaused = kPausedTries;
    }
  }
  for (const auto& [begin, end] : m_activeRanges)
    for (int i = begin; i < end; ++i) dq[eqDofs[i]] += m_delta[i];
  return false;
}

bool GeneralizedAlpha::sameBlocks() const {
  const int blocks = m_solver.blockCount();
  if (m_blockStart.size() != static_cast<std::size_t>(blocks) + 1) return false;
  for (int k = 0; k <= blocks; ++k)
    if (m_blockStart[static_cast<std::size_t>(k)] != m_solver.blockStart(k)) return false;
  return true;
}

double GeneralizedAlpha::residualRatio(const VecX& r, bool onPart) {
  const int neq = static_cast<int>(r.size());
  const int blocks = m_solver.blockCount();
  if (blocks <= 1 || m_solver.blockStart(blocks) != neq) {
    m_blockStart.clear();
    m_blockRatio.clear();
    return largestScaled(r.data(), m_inverseAllowed.data(), neq);
  }
  // Per independent block of the kept matrix (any partition gives the same largest ratio): solveCorrection
  // reads them, and on a part only the blocks holding one of its nodes changed.
  if (!sameBlocks()) {
    m_blockStart.resize(static_cast<std::size_t>(blocks) + 1);
    for (int k = 0; k <= blocks; ++k) m_blockStart[static_cast<std::size_t>(k)] = m_solver.blockStart(k);
    m_blockRatio.assign(static_cast<std::size_t>(blocks), 0.0);
    onPart = false;
  }
  m_blockTouched.assign(static_cast<std::size_t>(blocks), onPart ? 0 : 1);
  if (onPart) {
    const model::DofMap& dofs = m_assembler->model().dofs();
    for (const int node : m_part.nodes) {
      const int eq = dofs.firstEquation(node);
      if (eq == dofs.firstEquation(node + 1)) continue;  // held in every DOF
      const auto k =
          std::upper_bound(m_blockStart.begin(), m_blockStart.end(), eq) - m_blockStart.begin() - 1;
      m_blockTouched[static_cast<std::size_t>(k)] = 1;
    }
  }
  double ratio = 0.0;
  bool nan = false;
  for (int k = 0; k < blocks; ++k) {
    double& blockRatio = m_blockRatio[static_cast<std::size_t>(k)];
    if (m_blockTouched[static_cast<std::size_t>(k)]) {
      const int begin = m_blockStart[static_cast<std::size_t>(k)];
      blockRatio = largestScaled(r.data() + begin, m_inverseAllowed.data() + begin,
                                 m_blockStart[static_cast<std::size_t>(k) + 1] - begin);
    }
    nan = nan || std::isnan(blockRatio);
    ratio = std::max(ratio, blockRatio);
  }
  return nan ? std::numeric_limits<double>::quiet_NaN() : ratio;
}

void GeneralizedAlpha::findSlowBlocks() {
  m_slowBlocks.clear();
  const std::size_t blocks = m_blockRatio.size();
  for (std::size_t k = 0; k < blocks; ++k)
    if (m_blockTouched[k] && m_blockRatio[k] > 1.0 && m_blockRatio[k] > 0.25 * m_previousBlockRatio[k])
      m_slowBlocks.push_back(static_cast<int>(k));
}

bool GeneralizedAlpha::refreshBlocks(const model::State& state, const solver::AssemblyRequest& request,
                                     double mf, const VecX& r) {
  // A line converging slowly (its touchdown point moved since the matrix was made) among lines converging
  // fast: its own matrix is assembled and factorised again, the others' kept (12 independent lines: a
  // whole refresh for one line cost 12 lines' matrices; docs/performance.md). Its nodes make a part
  // (Assembler::selectPart: their elements, seabed, attachments and hydrodynamics; refused where a vessel or
  // a contact loads a node), whose matrix terms replace the blocks' entries (SystemMatrix's patch).
  // When the block's out-of-balance beyond the tolerance lies in a stretch of a cable (its touchdown zone,
  // where the seabed spring switches and the kept matrix is stale), only that stretch's entries are made
  // again and only the rows of the factor that depend on them (SkylineLdlt::factorizeRows): the same for a
  // model of one block, where a whole refresh is the alternative.
  // Margin [nodes] around the stretch: the neighbours whose entries the stretch's elements share.
  constexpr int kStretchMargin = 2;
  const model::DofMap& dofs = m_assembler->model().dofs();
  const auto& eqDofs = dofs.equationDofs();
  solver::AssemblyRequest matrixRequest = request;
  matrixRequest.wantMatrix = true;
  const bool oneBlock = m_solver.blockCount() == 1;
  m_wholeSlowBlocks.clear();
  for (const int k : m_slowBlocks) {
    const int begin = m_solver.blockStart(k), end = m_solver.blockStart(k + 1);
    const int firstNode = dofs.nodeOf(eqDofs[begin]), lastNode = dofs.nodeOf(eqDofs[end - 1]);
    // The block's nodes out of balance: [low, high].
    int low = lastNode + 1, high = firstNode - 1;
    for (int i = begin; i < end; ++i)
      if (std::abs(r[i]) * m_inverseAllowed[i] > 1.0) {
        low = std::min(low, dofs.nodeOf(eqDofs[i]));
        break;
      }
    for (int i = end - 1; i >= begin; --i)
      if (std::abs(r[i]) * m_inverseAllowed[i] > 1.0) {
        high = std::max(high, dofs.nodeOf(eqDofs[i]));
        break;
      }
    bool stretch = false;
    if (low <= high) {
      low = std::max(firstNode, low - kStretchMargin);
      high = std::min(lastNode, high + kStretchMargin);
      stretch = m_solver.canFactorizeRows() && 2 * (high - low + 1) <= lastNode - firstNode + 1;
      // Cable stretches only: on a beam riser in a plane (examples/scr-fatigue) stretch refreshes let the
      // out-of-plane round-off grow a hundredfold (2e-6 m, 2.6 N m against 0.28 N m with whole refreshes)
      // for 5 % of CPU time.
      for (int node = low; node <= high && stretch; ++node) stretch = !dofs.hasRotations(node);
    }
    if (!stretch && oneBlock) return false;  // the whole matrix: a replayed whole assembly is faster
    if (!stretch) {
      low = firstNode;
      high = lastNode;
    }
    const int patchBegin = stretch ? dofs.firstEquation(low) : begin;
    const int patchEnd = stretch ? dofs.firstEquation(high + 1) : end;
    m_slowNodes.clear();
    for (int node = low; node <= high; ++node) m_slowNodes.push_back(node);
    if (!m_assembler->selectPart(m_slowNodes, m_refreshPart) ||
        !m_matrix.beginPatch(patchBegin, patchEnd, begin, end))
      return false;
    m_assembler->addPartMatrix(state, matrixRequest, mf, m_refreshPart, m_matrix);
    if (!m_matrix.endPatch(m_k)) return false;
    if (!stretch) {
      m_wholeSlowBlocks.push_back(k);
      continue;
    }
    if (!m_solver.factorizeRows(m_k, k, patchBegin, patchEnd)) {
      m_factorValid = false;
      return false;
    }
    for (int i = patchBegin; i < patchEnd; ++i) m_kDiagonal[i] = m_k.coeff(i, i);
  }
  if (m_wholeSlowBlocks.empty()) return true;
  if (!m_solver.factorizeBlocks(m_k, m_wholeSlowBlocks)) {
    m_factorValid = false;
    return false;
  }
  for (const int k : m_wholeSlowBlocks)
    for (int i = m_solver.blockStart(k); i < m_solver.blockStart(k + 1); ++i)
      m_kDiagonal[i] = m_k.coeff(i, i);
  return true;
}

int GeneralizedAlpha::solveCorrection(const VecX& r) {
  const int blocks = m_solver.blockCount();
  m_activeRanges.clear();
  if (blocks <= 1 || !m_mode.partIterations) {
    m_delta = -r;
    m_solver.solveInPlace(m_delta);
    m_activeRanges.emplace_back(0, static_cast<int>(r.size()));
    return 0;
  }
  // Independent blocks of the matrix (lines not coupled to each other): a block whose out-of-balance is
  // already within the tolerance has converged and is left as it is; only the others are solved and
  // corrected. Nothing outside a block changes its residual (the kept matrix has no coupling there; a
  // coupling the matrix does not hold, e.g. a contact made since it was factorised, is assembled in the
  // residual, and the convergence test stays on every equation). 12 independent mooring lines: the lines
  // converge at different iterations of a step, and the solve of all 7 200 equations at every one of them
  // was wasted on the converged ones (docs/performance.md).
  if (!sameBlocks()) residualRatio(r, false);  // the refreshed matrix has other blocks
  m_delta.resize(r.size());
  m_activeBlocks.clear();
  for (int k = 0; k < blocks; ++k) {
    const int begin = m_solver.blockStart(k), end = m_solver.blockStart(k + 1);
    if (!(m_blockRatio[static_cast<std::size_t>(k)] <= 1.0)) {
      m_activeBlocks.push_back(k);
      m_delta.segment(begin, end - begin) = -r.segment(begin, end - begin);
      if (!m_activeRanges.empty() && m_activeRanges.back().second == begin)
        m_activeRanges.back().second = end;
      else
        m_activeRanges.emplace_back(begin, end);
    } else if (m_debug) {
      m_delta.segment(begin, end - begin).setZero();
    }
  }
  m_solver.solveBlocksInPlace(m_delta, m_activeBlocks);
  return blocks - static_cast<int>(m_activeBlocks.size());
}

StepOutcome GeneralizedAlpha::step(model::State& state, double dt) {
  // The chosen path first; a step it does not converge is tried again, from the same start, with a whole
  // refresh of the matrix (no parts, no blocks or stretches refreshed on their own) and then with full
  // Newton, before the caller cuts it: a speed path may change the cost of a run, never whether it completes
  // (issue 44: a hose lowered onto a pipeline stopped at t = 0.43 s on block refreshes that kept converging
  // linearly, and ran its 40 s with whole refreshes).
  m_mode = m_choice;
  StepOutcome outcome = attempt(state, dt);
  if (outcome.converged) return outcome;
  model::DynamicSolverSpec wholeRefresh = m_choice;
  wholeRefresh.partIterations = false;
  wholeRefresh.blockRefresh = false;
  model::DynamicSolverSpec fullNewton = wholeRefresh;
  fullNewton.modifiedNewton = false;
  int level = 0;
  for (const model::DynamicSolverSpec& fallback : {wholeRefresh, fullNewton}) {
    ++level;
    const bool plainer = fallback.modifiedNewton != m_mode.modifiedNewton ||
                         fallback.partIterations != m_mode.partIterations ||
                         fallback.blockRefresh != m_mode.blockRefresh;
    if (!plainer) continue;  // already tried: the chosen path was this plain
    m_mode = fallback;
    m_factorValid = false;  // a fresh matrix at the step's first iterate
    if (m_debug) std::cerr << fmt::format("    step of {:.3e} s retried: fallback {}\n", dt, level);
    StepOutcome retry = attempt(state, dt);
    retry.iterations += outcome.iterations;
    retry.partIterations += outcome.partIterations;
    retry.blocksLeft += outcome.blocksLeft;
    retry.refreshes += outcome.refreshes;
    retry.blockRefreshes += outcome.blockRefreshes;
    retry.fallback = level;
    if (!retry.converged && retry.failure.empty()) retry.failure = outcome.failure;
    outcome = retry;
    if (outcome.converged) break;
  }
  m_mode = m_choice;
  // The fallback's matrix is of the chosen kind for the next step as well (a whole matrix is a valid kept
  // matrix); a full Newton's last factorisation is of the last iterate, which the next step may keep.
  return outcome;
}

StepOutcome GeneralizedAlpha::attempt(model::State& state, double dt) {
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
  if (sameStep(dt, m_lastStep)) dq += 0.5 * dt * dt * a0;
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
  // Convergence: every free DOF's out-of-balance force below tol times its line's weight (moments over the
  // node's moment scale), or below the round-off floor of the elements at its node (Section 8.2 of the
  // theory manual). Per node: one global scale, the largest line's weight, would make a light line's test
  // meaningless next to a heavy one; the former scale, the largest element weight, made the test stricter
  // as the mesh was refined (1e-8 of the tension on a 200-bar mooring line, 4.8 residual assemblies per
  // step where 3.5 give the same tension ranges to 1.5e-4).
  m_assembler->nodeRoundoffFloor(start, m_nodeFloor);
  {
    // Per node (its equations are consecutive, DofMap::firstEquation): two divisions for a beam node, one
    // for a bar node, instead of one per equation.
    const std::vector<double>& scale = m_assembler->nodeForceScale();
    m_inverseAllowed.resize(neq);
    for (int node = 0; node < dofs.nodeCount(); ++node) {
      const int first = dofs.firstDof(node);
      const double allowed = std::max(m_settings.tolerance * scale[node], m_nodeFloor[node]);
      const double inverseForce = 1.0 / allowed;
      const double inverseMoment =
          dofs.hasRotations(node) ? 1.0 / (allowed * std::max(model.momentScale(node), 1e-6)) : 0.0;
      for (int i = dofs.firstEquation(node); i < dofs.firstEquation(node + 1); ++i)
        m_inverseAllowed[i] = eqDofs[i] - first >= 3 ? inverseMoment : inverseForce;
    }
  }

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
      m_mode.modifiedNewton && m_mode.partIterations && !m_frozen && m_assembler->supportsParts();
  bool onPart = false;  // this iterate differs from the last evaluated one only at the nodes m_moved
  // Modified Newton: the factorised iteration matrix is kept while the residual falls fast (by 4x or
  // more per iteration) and refreshed when convergence slows, when the step size changed, or when keeping
  // it has come to cost more iterations than a refresh (planRefresh).
  bool haveFactor = m_reuseAcrossSteps && m_factorValid && sameStep(dt, m_factorStep) && !m_refreshDue;
  bool refreshed = false;
  double previousResidual = std::numeric_limits<double>::infinity();
  m_previousBlockRatio.clear();  // no block is slow at the first iteration
  // Slow blocks refreshed on their own: with modified Newton on parts (the blocks' matrices are assembled as
  // parts), not in dynamic relaxation (partsAllowed).
  const bool blockwise = partsAllowed && m_mode.blockRefresh;
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

    const bool refresh = !haveFactor || !m_mode.modifiedNewton;
    request.wantMatrix = refresh;
    try {
      // On a part the other entries of m_force are those of the last iterate, which they equal.
      if (onPart)
        m_assembler->assemblePart(state, request, m_part, m_force);
      else
        m_assembler->assemble(state, request, m_force, &m_matrix);
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
      for (const int node : m_moved)
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
      m_assembler->addPartMass(state, m_part, combo, inertia);
      for (const int node : m_part.nodes) {
        const int d = dofs.firstDof(node);
        for (int dof = d; dof < d + dofs.dofCount(node); ++dof) {
          const int i = dofs.equation(dof);
          if (i >= 0) r[i] = inertia[dof] + (1.0 - p.alphaF) * m_force[dof] + p.alphaF * m_forceOld[dof];
        }
      }
    } else {
      inertia.setZero();
      m_assembler->addMass(state, mf, refresh ? &m_matrix : nullptr, &combo, &inertia);
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
    const double ratio = residualRatio(r, onPart);
    if (m_debug) {
      outcome.residual =
          solver::residualNorm(model, r, solver::ResidualIndexing::Equations, &outcome.worstNode);
      std::cerr << fmt::format(
          "    t {:.6f} dt {:.3e} it {:2d} |r| {:.4e} ({:.3e} of the tolerance) worst node {}{}\n", t1, dt,
          it, outcome.residual, ratio, outcome.worstNode,
          onPart ? fmt::format(" (part of {} nodes)", m_part.nodes.size()) : std::string());
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
    // Slow convergence with the old matrix (a residual that fell by less than 4x): with independent blocks
    // the slow blocks' matrix is made again at this iterate, else (or when that cannot be done) this
    // iteration is redone with a whole fresh matrix.
    bool wholeRefresh = false;
    if (!refresh) {
      m_slowBlocks.clear();
      if (blockwise && !m_blockStart.empty() && m_previousBlockRatio.size() == m_blockRatio.size())
        findSlowBlocks();
      else if (ratio > 0.25 * previousResidual && blockwise && m_solver.blockCount() == 1)
        m_slowBlocks.push_back(0);  // one block: a stretch of it, or the whole matrix (refreshBlocks)
      else if (ratio > 0.25 * previousResidual)
        wholeRefresh = true;
      if (!m_slowBlocks.empty()) {
        if (refreshBlocks(state, request, mf, r))
          outcome.blockRefreshes += static_cast<int>(m_slowBlocks.size());
        else
          wholeRefresh = true;
        if (m_debug)
          std::cerr << "      " << m_slowBlocks.size() << " of " << m_solver.blockCount()
                    << " blocks slow: " << (wholeRefresh ? "whole refresh\n" : "refreshed alone\n");
      }
    }
    if (wholeRefresh) {
      haveFactor = false;
      previousResidual = std::numeric_limits<double>::infinity();
      m_previousBlockRatio.clear();
      onPart = false;  // the refresh assembles the whole matrix at this iterate
      --it;
      continue;
    }
    previousResidual = ratio;
    if (refresh) {
      m_matrix.build(m_k);
      m_kDiagonal = m_k.diagonal();
      m_factorValid = false;
      if (!m_solver.factorize(m_k)) {
        outcome.failure = "the iteration matrix is singular";
        break;
      }
      m_factorValid = true;
      m_factorStep = dt;
      haveFactor = true;
      refreshed = true;
      ++outcome.refreshes;
    }
    outcome.blocksLeft += solveCorrection(r);
    m_previousBlockRatio = m_blockRatio;  // of the kept matrix's blocks (solveCorrection follows a refresh's)
    const VecX& delta = m_delta;
    if (m_debug) {
      Eigen::Index imax = 0;
      r.cwiseAbs().maxCoeff(&imax);
      std::cerr << fmt::format("      max |r| at eq {} (full dof {}), |delta| {:.3e}, relres {:.3e}\n", imax,
                               eqDofs[imax], delta.cwiseAbs().maxCoeff(),
                               (m_k * delta + r).norm() / r.norm());
    }
    // A contact barrier (the distributed formulation) filters the correction so no iterate jumps past it.
    if (m_assembler->limitsDynamicIncrements()) {
      VecX full = VecX::Zero(nfull);
      for (int i = 0; i < neq; ++i) full[eqDofs[i]] = m_delta[i];
      const double alpha = m_assembler->limitDynamicIncrement(state, full);
      if (alpha < 1.0) m_delta *= alpha;
      if (m_debug && alpha < 1.0)
        std::cerr << fmt::format("      contact filter: correction x {:.3e}\n", alpha);
    }
    onPart = applyCorrection(dq, partsAllowed);
  }
  // The norm in N and its node are for the message of a failed step (a converged step's largest
  // out-of-balance is below the tolerance by definition; the norm per step is not free: docs/performance.md).
  if (haveResidual && (!outcome.converged || m_debug) && outcome.failure.empty())
    outcome.residual =
        solver::residualNorm(model, r, solver::ResidualIndexing::Equations, &outcome.worstNode);
  if (!outcome.converged) {
    state = start;
    return outcome;
  }
  state.orthonormaliseTriads(dofs);
  m_forceOld = m_force;
  m_lastStep = dt;
  planRefresh(outcome, refreshed);
  return outcome;
}

void GeneralizedAlpha::planRefresh(const StepOutcome& outcome, bool refreshed) {
  // A kept matrix ages: the elements turn and the seabed contact of touchdown nodes changes, and each
  // correction removes less of the out-of-balance (the mooring example: 2.16 residual evaluations per
  // step with a matrix made at every step's predictor, 3.6 with one kept as long as it converges 4x per
  // iteration). A refresh costs about kRefreshCost evaluations (measured on the mooring example: 2.8 with
  // the replayed matrix assembly, 4.7 before it; the times of that example and of the drilling riser
  // differ by under 2 % for any value from 2 to 5, against 7 % and 17 % without the rule). Keeping the matrix
  // for n steps that take I_1..I_n evaluations costs (kRefreshCost + sum I_k) / n per step; that average is
  // least when the evaluations of the latest steps reach it (the renewal rule of replacement theory, e.g.
  // Ross 1996, "Stochastic processes", sec. 3.6), so the matrix is refreshed at the next step from then on.
  // The latest steps' count is smoothed (exponential average over about 3 steps); a step on a part counts
  // half (its assembly is local, its solve whole). Not in dynamic relaxation (statics), where the matrix
  // keeps the old rule (line contact's active set follows the iteration path there).
  constexpr double kRefreshCost = 3.0;
  constexpr double kSmoothing = 0.3;
  const double evaluations = outcome.iterations - 0.5 * outcome.partIterations;
  // A step that refreshed blocks on their own (refreshBlocks) starts the count again as a whole refresh does:
  // the blocks that converged slowly have a new matrix, the others converged fast with the old one.
  // (Counted on, three independent lines at dt 0.01 s, tests/verification/dynamics/BlockIterationTest.cpp,
  // refreshed the whole matrix 167 times against 86 with whole refreshes alone.)
  if (refreshed || outcome.blockRefreshes > 0 || m_stepsSinceRefresh == 0) {
    m_stepsSinceRefresh = 0;
    m_evaluationsSinceRefresh = 0.0;
    m_recentEvaluations = evaluations;
    m_refreshDue = false;
  }
  ++m_stepsSinceRefresh;
  m_evaluationsSinceRefresh += evaluations;
  m_recentEvaluations += kSmoothing * (evaluations - m_recentEvaluations);
  if (m_frozen || !m_mode.modifiedNewton || !m_mode.renewalRule) return;
  const double average = (kRefreshCost + m_evaluationsSinceRefresh) / m_stepsSinceRefresh;
  m_refreshDue = m_stepsSinceRefresh >= 2 && m_recentEvaluations > average;
}

}  // namespace tangle::time
