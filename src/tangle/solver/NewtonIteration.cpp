#include "tangle/solver/NewtonIteration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

namespace tangle::solver {

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
}  // namespace

bool sameStep(double a, double b) { return std::abs(a - b) <= 1e-9 * std::abs(b); }

NewtonIteration::NewtonIteration(Assembler& assembler, bool debug)
    : m_assembler(&assembler),
      m_debug(debug),
      m_matrix(assembler.model().dofs()),
      m_massAssembly(assembler.model().dofs()) {}

void NewtonIteration::setAllowed(double tolerance, const std::vector<double>& nodeFloor) {
  // Per node (its equations are consecutive, DofMap::firstEquation): two divisions for a beam node, one
  // for a bar node, instead of one per equation.
  const model::Model& model = m_assembler->model();
  const model::DofMap& dofs = model.dofs();
  const auto& eqDofs = dofs.equationDofs();
  const std::vector<double>& scale = m_assembler->nodeForceScale();
  // A node whose allowance is the one it had keeps its inverses (the allowance is set at every step and
  // is the tolerance's, not the round-off floor's, almost everywhere): no division.
  if (m_inverseAllowed.size() != static_cast<Eigen::Index>(dofs.equationCount()) ||
      m_allowedForce.size() != static_cast<std::size_t>(dofs.nodeCount())) {
    m_inverseAllowed.setZero(dofs.equationCount());
    m_allowedForce.assign(static_cast<std::size_t>(dofs.nodeCount()),
                          std::numeric_limits<double>::quiet_NaN());
  }
  for (int node = 0; node < dofs.nodeCount(); ++node) {
    const int first = dofs.firstDof(node);
    const double allowed = std::max(tolerance * scale[node], nodeFloor[node]);
    if (allowed == m_allowedForce[static_cast<std::size_t>(node)]) continue;
    m_allowedForce[static_cast<std::size_t>(node)] = allowed;
    const double inverseForce = 1.0 / allowed;
    const double inverseMoment =
        dofs.hasRotations(node) ? 1.0 / (allowed * std::max(model.momentScale(node), 1e-6)) : 0.0;
    for (int i = dofs.firstEquation(node); i < dofs.firstEquation(node + 1); ++i)
      m_inverseAllowed[i] = eqDofs[i] - first >= 3 ? inverseMoment : inverseForce;
  }
}

void NewtonIteration::startAttempt(const model::State& start, double dt, const model::DynamicSolverSpec& mode,
                                   double massFactor) {
  m_mode = mode;
  m_work = MatrixWork{};
  // Only after a converged step: a retry of a failed step (cut, or on a plainer path) gets a fresh matrix.
  const bool afterConvergedStep = m_afterConvergedStep;
  m_afterConvergedStep = false;
  if (m_factorValid && !m_refreshDue && !sameStep(dt, m_factorStep) && afterConvergedStep &&
      mode.modifiedNewton && mode.stepChangeRescale && !changeStepLength(start, dt, massFactor))
    m_factorValid = false;
  m_haveFactor = m_factorValid && sameStep(dt, m_factorStep) && !m_refreshDue;
  m_previousRatio = std::numeric_limits<double>::infinity();
  m_previousBlockRatio.clear();  // no block is slow at the first iteration
}

bool NewtonIteration::afterResidual(const model::State& state, const AssemblyRequest& request, double mf,
                                    const VecX& r, double ratio, bool matrixAssembled) {
  // Slow convergence with the old matrix (a residual that fell by less than 4x): with independent blocks
  // the slow blocks' matrix is made again at this iterate, else (or when that cannot be done) this
  // iteration is redone with a whole fresh matrix. Slow blocks are refreshed on their own with modified
  // Newton on parts only (the blocks' matrices are assembled as parts).
  const bool blockwise = m_mode.modifiedNewton && m_mode.partIterations && m_mode.blockRefresh &&
                         !request.relaxation && m_assembler->supportsParts();
  bool wholeRefresh = false;
  if (!matrixAssembled) {
    m_slowBlocks.clear();
    if (blockwise && !m_blockStart.empty() && m_previousBlockRatio.size() == m_blockRatio.size())
      findSlowBlocks();
    else if (ratio > 0.25 * m_previousRatio && blockwise && m_solver.blockCount() == 1)
      m_slowBlocks.push_back(0);  // one block: a stretch of it, or the whole matrix (refreshBlocks)
    else if (ratio > 0.25 * m_previousRatio)
      wholeRefresh = true;
    if (!m_slowBlocks.empty()) {
      if (refreshBlocks(state, request, mf, r))
        m_work.blockRefreshes += static_cast<int>(m_slowBlocks.size());
      else
        wholeRefresh = true;
      if (m_debug)
        std::cerr << "      " << m_slowBlocks.size() << " of " << m_solver.blockCount()
                  << " blocks slow: " << (wholeRefresh ? "whole refresh\n" : "refreshed alone\n");
    }
  }
  if (wholeRefresh) {
    m_haveFactor = false;
    m_previousRatio = std::numeric_limits<double>::infinity();
    m_previousBlockRatio.clear();
    return false;
  }
  m_previousRatio = ratio;
  return true;
}

bool NewtonIteration::factorize(double dt, double massFactor) {
  m_matrix.build(m_k);
  if (!factorizeKept(dt, massFactor)) return false;
  m_haveFactor = true;
  m_work.refreshed = true;
  ++m_work.refreshes;
  return true;
}

bool NewtonIteration::factorizeKept(double dt, double massFactor) {
  m_kDiagonal = m_k.diagonal();
  m_factorValid = false;
  if (!m_solver.factorize(m_k)) return false;
  m_factorValid = true;
  m_factorStep = dt;
  m_factorMassFactor = massFactor;
  return true;
}

bool NewtonIteration::changeStepLength(const model::State& state, double dt, double massFactor) {
  // K_eff = kf K + cf C + mf M: the mass term made for the new step, with M at the step's start (the kept
  // matrix's own M is of the state it was made at; M changes with the lines' directions through the added
  // mass, slowly against the steps between). The damping term cf C keeps the old step's cf (cf ~ 1/dt against
  // mf ~ 1/dt^2: at the impact steps of a contact, 1e-5 to 1e-2 s, the mass term is 10^2 to 10^4 times the
  // hydrodynamic and contact damping); it is a kept matrix, already of an earlier state, and the convergence
  // rule refreshes it when it no longer serves (afterResidual). M is assembled here only, not at every
  // refresh: kept with each refresh it cost a mooring line 1.4 % of its run, most of them never used.
  m_massAssembly.clear();
  m_assembler->addMass(state, 1.0, &m_massAssembly, nullptr, nullptr);
  m_massAssembly.build(m_mass);
  // Each entry of M added where it lies in the kept matrix, which holds it (the same mass calls were summed
  // into it), found in its column's sorted rows as SystemMatrix::build finds a call's entry.
  const int* outer = m_k.outerIndexPtr();
  const int* inner = m_k.innerIndexPtr();
  double* k = m_k.valuePtr();
  const double change = massFactor - m_factorMassFactor;
  for (Eigen::Index col = 0; col < m_mass.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(m_mass, col); it; ++it) {
      const int* end = inner + outer[col + 1];
      const int* at = std::lower_bound(inner + outer[col], end, static_cast<int>(it.row()));
      // Not in the kept matrix: a whole refresh (startAttempt drops the kept factorisation, and with it
      // these partly changed values).
      if (at == end || *at != it.row()) return false;
      k[at - inner] += change * it.value();
    }
  if (!factorizeKept(dt, massFactor)) return false;
  ++m_work.stepLengthChanges;
  if (m_debug) std::cerr << fmt::format("    kept matrix made for a step of {:.3e} s\n", dt);
  return true;
}

bool NewtonIteration::applyCorrection(VecX& dq, bool partsAllowed) {
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
    // A part pays while it is clearly smaller than the model (its assembly also re-evaluates the moved
    // nodes' neighbours and their elements), and a correction spread over most of the model is better
    // applied whole: up to half the nodes (measured on 200 and 800 bars against 30 % and 80 %: equal within
    // the machine's noise at 200 bars, 80 % costs more iterations at 800).
    // (And when no contributor left out of parts loads a node of the part: a vessel, a contact.)
    // The test runs over chunks of kChunkNodes nodes and stops once more than half the nodes moved: the
    // first correction of a step moves almost every node (a coupled host's chain: 194-199 of 201), and the
    // rest of its test was a tenth of the host's Newton bookkeeping.
    constexpr int kChunkNodes = 32;
    const std::size_t halfNodes = static_cast<std::size_t>(nodes) / 2;
    m_moved.clear();
    m_equationMoved.resize(static_cast<std::size_t>(neq));
    for (const auto& range : m_activeRanges) {
      // Bounds and arrays in locals: the flags' stores (unsigned char) may alias anything, so a bound read
      // through the range was loaded again at every equation.
      const double* delta = m_delta.data();
      const double* diagonal = m_kDiagonal.data();
      const double* inverseAllowed = m_inverseAllowed.data();
      unsigned char* flag = m_equationMoved.data();
      const int lastNode = dofs.nodeOf(eqDofs[range.second - 1]);
      for (int chunk = dofs.nodeOf(eqDofs[range.first]); chunk <= lastNode && m_moved.size() <= halfNodes;
           chunk += kChunkNodes) {
        const int endNode = std::min(chunk + kChunkNodes, lastNode + 1);
        const int begin = std::max(range.first, dofs.firstEquation(chunk));
        const int end = std::min(range.second, dofs.firstEquation(endNode));
        for (int i = begin; i < end; ++i)
          flag[i] = std::abs(delta[i] * diagonal[i]) * inverseAllowed[i] > kNegligibleCorrection ? 1 : 0;
        for (int node = chunk; node < endNode; ++node) {
          unsigned char moved = 0;
          for (int i = dofs.firstEquation(node); i < dofs.firstEquation(node + 1); ++i) moved |= flag[i];
          if (moved) m_moved.push_back(node);
        }
      }
      if (m_moved.size() > halfNodes) break;
    }
    if (!m_moved.empty() && m_moved.size() <= halfNodes && m_assembler->selectPart(m_moved, m_part)) {
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

bool NewtonIteration::sameBlocks() const {
  const int blocks = m_solver.blockCount();
  if (m_blockStart.size() != static_cast<std::size_t>(blocks) + 1) return false;
  for (int k = 0; k <= blocks; ++k)
    if (m_blockStart[static_cast<std::size_t>(k)] != m_solver.blockStart(k)) return false;
  return true;
}

double NewtonIteration::residualRatio(const VecX& r, bool onPart) {
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

void NewtonIteration::findSlowBlocks() {
  m_slowBlocks.clear();
  const std::size_t blocks = m_blockRatio.size();
  for (std::size_t k = 0; k < blocks; ++k)
    if (m_blockTouched[k] && m_blockRatio[k] > 1.0 && m_blockRatio[k] > 0.25 * m_previousBlockRatio[k])
      m_slowBlocks.push_back(static_cast<int>(k));
}

bool NewtonIteration::refreshBlocks(const model::State& state, const solver::AssemblyRequest& request,
                                    double mf, const VecX& r) {
  // A line converging slowly (its touchdown point moved since the matrix was made) among lines converging
  // fast: its own matrix is assembled and factorised again, the others' kept (12 independent lines: a
  // whole refresh for one line cost 12 lines' matrices; docs/performance.md). Its nodes make a part
  // (Assembler::selectPart: their elements, seabed, attachments and hydrodynamics; refused where a vessel or
  // a contact loads a node, except for the lines of a block coupled by a contact, below), whose matrix terms
  // replace the blocks' entries (SystemMatrix's patch).
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
    // One block of several lines on the envelope (lines coupled by a contact: a riser resting across a
    // flowline): the lines from the one where the out-of-balance starts to the block's end, when they are at
    // most half of it, and with them the contact's terms (a part that holds all its nodes); the rows of the
    // factor from there on (SkylineLdlt::factorizeEnvelopeFrom).
    bool lines = false;
    if (!stretch && oneBlock && low <= high && m_solver.canFactorizeEnvelopeRows()) {
      const model::Model& model = m_assembler->model();
      // The first node out of balance that no contact couples to another line (those are out of balance
      // with the lines they touch, and join the part with them).
      const std::vector<char>& coupled = m_assembler->loadedNodes();
      int own = lastNode + 1;
      for (int i = begin; i < end && own > lastNode; ++i) {
        const int node = dofs.nodeOf(eqDofs[i]);
        if (!coupled[static_cast<std::size_t>(node)] && std::abs(r[i]) * m_inverseAllowed[i] > 1.0)
          own = node;
      }
      const int line = own <= lastNode ? model.lineOfNode(own) : -1;
      if (line >= 0) {
        const int from = model.lines()[static_cast<std::size_t>(line)].firstNode;
        lines = from > firstNode && 2 * (lastNode - from + 1) <= lastNode - firstNode + 1;
        if (lines) {
          low = from;
          high = lastNode;
        }
      }
    }
    if (!stretch && !lines && oneBlock)
      return false;  // the whole matrix: a replayed whole assembly is faster
    if (!stretch && !lines) {
      low = firstNode;
      high = lastNode;
    }
    const int patchBegin = stretch || lines ? dofs.firstEquation(low) : begin;
    const int patchEnd = stretch || lines ? dofs.firstEquation(high + 1) : end;
    m_slowNodes.clear();
    for (int node = low; node <= high; ++node) m_slowNodes.push_back(node);
    if (!m_assembler->selectPart(m_slowNodes, m_refreshPart, lines) ||
        !m_matrix.beginPatch(patchBegin, patchEnd, begin, end))
      return false;
    m_assembler->addPartMatrix(state, matrixRequest, mf, m_refreshPart, m_matrix);
    if (!m_matrix.endPatch(m_k)) return false;
    if (!stretch && !lines) {
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

void NewtonIteration::solveCorrection(const VecX& r) {
  const int blocks = m_solver.blockCount();
  m_activeRanges.clear();
  if (blocks <= 1 || !m_mode.partIterations) {
    m_delta = -r;
    m_solver.solveInPlace(m_delta);
    m_activeRanges.emplace_back(0, static_cast<int>(r.size()));
    m_previousBlockRatio = m_blockRatio;
    return;
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
    } else {
      // Zero, not left as it was: the contact filter reads the whole correction (a resized m_delta holds
      // uninitialised values there, and one NaN made a whole step's iterate NaN).
      m_delta.segment(begin, end - begin).setZero();
    }
  }
  m_solver.solveBlocksInPlace(m_delta, m_activeBlocks);
  m_work.blocksLeft += blocks - static_cast<int>(m_activeBlocks.size());
  m_previousBlockRatio = m_blockRatio;  // of the kept matrix's blocks (a refresh's, after one)
}

void NewtonIteration::planRefresh(int iterations, int partIterations, bool relaxation) {
  m_afterConvergedStep = !relaxation;
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
  const double evaluations = iterations - 0.5 * partIterations;
  // A step that refreshed blocks on their own (refreshBlocks) starts the count again as a whole refresh does:
  // the blocks that converged slowly have a new matrix, the others converged fast with the old one.
  // (Counted on, three independent lines at dt 0.01 s, tests/verification/dynamics/BlockIterationTest.cpp,
  // refreshed the whole matrix 167 times against 86 with whole refreshes alone.)
  if (m_work.refreshed || m_work.blockRefreshes > 0 || m_stepsSinceRefresh == 0) {
    m_stepsSinceRefresh = 0;
    m_evaluationsSinceRefresh = 0.0;
    m_recentEvaluations = evaluations;
    m_refreshDue = false;
  }
  ++m_stepsSinceRefresh;
  m_evaluationsSinceRefresh += evaluations;
  m_recentEvaluations += kSmoothing * (evaluations - m_recentEvaluations);
  if (relaxation || !m_mode.modifiedNewton || !m_mode.renewalRule) return;
  const double average = (kRefreshCost + m_evaluationsSinceRefresh) / m_stepsSinceRefresh;
  m_refreshDue = m_stepsSinceRefresh >= 2 && m_recentEvaluations > average;
}

}  // namespace tangle::solver
