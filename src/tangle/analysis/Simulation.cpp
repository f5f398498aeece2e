#include "tangle/analysis/Simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <optional>

#include "tangle/analysis/EquilibriumAudit.hpp"
#include "tangle/core/Error.hpp"
#include "tangle/core/Interrupt.hpp"
#include "tangle/geometry/Rotation.hpp"
#include "tangle/time/DynamicRelaxation.hpp"

namespace tangle::analysis {

Simulation::Simulation(model::ModelSpec spec)
    : m_model(std::make_unique<model::Model>(std::move(spec))),
      m_assembler(std::make_unique<solver::Assembler>(*m_model)),
      m_hydro(std::make_unique<hydro::HydroLoads>(*m_model)),
      m_state(m_model->initialState()) {
  m_assembler->addContributor(m_hydro.get());
  if (!m_model->ties().empty()) {
    m_junctions = std::make_unique<solver::JunctionTies>(*m_model);
    m_assembler->addContributor(m_junctions.get());
  }
  if (!m_model->vessels().empty()) {
    m_vessels = std::make_unique<vessel::VesselSystem>(*m_model, *m_hydro);
    m_assembler->addContributor(m_vessels.get());
  }
  if (vessel::HullContact::wanted(*m_model)) {
    m_hullContact = std::make_unique<vessel::HullContact>(*m_model, m_state);
    m_assembler->addContributor(m_hullContact.get());
  }
  if (m_model->spec().contact.enabled) {
    m_contact = std::make_unique<contact::LineContact>(*m_model, m_model->spec().contact,
                                                       m_model->spec().dynamics.timeStep);
    m_assembler->addContributor(m_contact.get());
  }
  // After the contact, so that a clash's event is up to date when the failures read it (commitStep order).
  if (LineFailure::wanted(*m_model)) {
    m_failure = std::make_unique<LineFailure>(*m_model, *m_assembler, m_contact.get());
    m_assembler->addContributor(m_failure.get());
  }
  if (m_contact) {
    checkStartShapes();
    m_startPositions = m_state.position;  // solveStatics lays crossed start shapes if still these
  }
}

void Simulation::checkStartShapes() const {
  // A start shape given by the user (lines[].start_shape) must not pass through another line: the static
  // solve would push the lines apart from the wrong side, or hold them crossed. A catenary start shape
  // is the program's, and statics separates it (theory 7.4).
  const auto& lines = m_model->lines();
  const auto smallestRadius = [&](const model::Line& line) {
    double r = std::numeric_limits<double>::infinity();
    for (const model::SectionSpec& sec : line.spec->sections)
      r = std::min(r, 0.5 * m_model->spec().lineTypes.at(sec.lineType).contactDiameter);
    return r;
  };
  // The pairs with a start shape on either side (a line with one against every line it may touch): not
  // every allowed pair, which grows as the square of the lines.
  std::vector<std::array<int, 2>> shapedPairs;
  for (int s = 0; s < static_cast<int>(lines.size()); ++s) {
    if (lines[static_cast<std::size_t>(s)].spec->startShape.empty()) continue;
    for (int o = 0; o < static_cast<int>(lines.size()); ++o)
      if (o != s && m_contact->pairAllowed(s, o)) shapedPairs.push_back({std::min(s, o), std::max(s, o)});
  }
  std::sort(shapedPairs.begin(), shapedPairs.end());
  shapedPairs.erase(std::unique(shapedPairs.begin(), shapedPairs.end()), shapedPairs.end());
  for (const auto& [a, b] : shapedPairs) {
    const std::array<double, 3> c = m_contact->clearance(m_state, a, b);
    const double allowed = 0.5 * (smallestRadius(lines[a]) + smallestRadius(lines[b]));
    if (!(c[0] < -allowed)) continue;
    const model::Line& shaped = lines[a].spec->startShape.empty() ? lines[b] : lines[a];
    throw InputError(
        m_model->spec().sourceFile, 0, "lines[" + shaped.name + "].start_shape",
        fmt::format(
            "a start shape that keeps clear of the other lines; line '{}' passes through line '{}' at "
            "{:.2f} m along '{}' and {:.2f} m along '{}' (the surfaces overlap by {:.3g} m): move the "
            "start_shape points to the side of '{}' the line should rest on, at least the sum of the "
            "contact radii from its axis",
            lines[a].name, lines[b].name, c[1], lines[a].name, c[2], lines[b].name, -c[0],
            shaped.name == lines[a].name ? lines[b].name : lines[a].name));
  }
}

Simulation::~Simulation() = default;

solver::StaticResult Simulation::solveStatics(bool progress) {
  // Progress lines: this solve's own, unless a caller's (the finer model of a mesh continuation) is shown.
  std::optional<core::ConsoleProgress> ownProgress;
  if (progress && !m_staticsProgress) {
    ownProgress.emplace();
    m_staticsProgress = &*ownProgress;
  }
  struct Release {
    Simulation* sim;
    bool own;
    ~Release() {
      if (own) sim->m_staticsProgress = nullptr;
    }
  } release{this, ownProgress.has_value()};
  // The program's start shapes that pass through each other, laid one over the other, unless the caller
  // has replaced the start state (a test, a script): then its state is the caller's.
  if (!m_startPositions.empty()) {
    if (m_state.position == m_startPositions)
      m_startShapeLifts = contact::liftCrossedStartShapes(*m_model, *m_contact, m_state);
    m_startPositions.clear();
    m_startPositions.shrink_to_fit();
  }
  if (m_model->spec().statics.skip) {
    // statics.method: none. The seabed's friction anchors and the contributors start from this shape as they
    // would from an equilibrium.
    m_assembler->beginStatics(m_state);
    m_assembler->commitIncrement(m_state);
    solver::StaticResult skipped;
    skipped.converged = true;
    skipped.loadFraction = 1.0;
    skipped.message =
        "no static solve (statics.method: none): the dynamics starts from the start shape, at rest";
    return skipped;
  }
  solver::StaticSolver solver(*m_assembler, m_model->spec().statics);
  solver.setProgress(m_staticsProgress);
  if (m_contact) solver.setContactEngaged([this] { return m_contact->touched(); });
  const model::State start = m_state;
  if (m_contact) m_contact->clearTouched();
  solver::StaticResult result = solver.solve(m_state);
  // Fallbacks, cheapest first: in a current, the tangent with the drag's follower stiffness (theory 6.4);
  // the same model on a coarser mesh; dynamic relaxation.
  // None when the loading path has no equilibrium (a free laid line sliding as a whole): each of them
  // leaves the path and the friction's history on it.
  const bool fallbacks = !result.converged && !result.noEquilibrium;
  if (fallbacks && solver::StaticSolver::debugOutput())
    std::cerr << "  first attempt: " << result.message << "\n";
  // A path that engaged line contact and stalled: dynamic relaxation first. Contact that closes, opens and
  // slides makes the equilibrium path non-smooth, and a contact problem may have several equilibria (a
  // riser hooked over another or clear of it); the other fallbacks follow load paths again and stall at the
  // same contact events (a flexible pushed across an SCR by the current: the drag-stiffness retry and the
  // coarse mesh crawled for 36 s, then the relaxation and Newton converged in 2.5 s). The damped dynamics
  // go through them as the lines would.
  const bool contactOnPath = m_contact && m_contact->touched();
  if (fallbacks && contactOnPath && !core::interruptRequested()) {
    if (solver::StaticSolver::debugOutput()) std::cerr << "  contact on the path: dynamic relaxation first\n";
    relaxThenSolve(result);
  }
  if (fallbacks && !result.converged && !core::interruptRequested() &&
      solver::StaticSolver::hasCurrent(*m_model))
    solveWithDragStiffness(start, result);
  if (fallbacks && !result.converged && !core::interruptRequested() && m_coarseFallback)
    solveFromCoarserMesh(result);
  if (fallbacks && !result.converged && !core::interruptRequested()) relaxThenSolve(result);
  if (!result.converged && core::interruptRequested())
    result.message =
        "static analysis interrupted by the user (Ctrl-C or SIGTERM) before it converged; where it "
        "stood: " +
        result.message;
  // The final static solution is committed (LoadContributor's protocol): contacts at rest in it become
  // the starting contacts of the dynamics.
  if (result.converged) m_assembler->commitStep(m_state, 0.0);
  return result;
}

bool Simulation::solveWithDragStiffness(const model::State& start, solver::StaticResult& result) {
  model::State trial = start;
  solver::StaticSolver withDrag(*m_assembler, m_model->spec().statics);
  withDrag.setDragStiffness(true);
  if (m_staticsProgress) m_staticsProgress->stage("statics: trying again with the drag's stiffness in the tangent");
  withDrag.setProgress(m_staticsProgress, "(drag stiffness)");
  solver::StaticResult again = withDrag.solve(trial);
  if (solver::StaticSolver::debugOutput())
    std::cerr << "  with the drag stiffness in the tangent: " << again.message << "\n";
  if (!again.converged) {
    result.message += "; the retry with the drag's stiffness in the tangent did not converge either";
    result.iterations += again.iterations;  // counted in the total a later fallback reports
    return false;
  }
  again.iterations += result.iterations;
  again.message += fmt::format(", with the drag's stiffness in the tangent ({} Newton iterations in all)",
                               again.iterations);
  result = again;
  m_state = trial;
  return true;
}

bool Simulation::relaxThenSolve(solver::StaticResult& result) {
  // Not with a free vessel held in statics (a DP unit on station would drift off during the relaxation);
  // other free vessels settle with their lines (a body that must sink metres before its cans float:
  // MoorDyn's BodiesAndRods.dat, where Newton's first tangent has no heave stiffness). With line contact
  // the contact acts as in dynamics (penalty, no step passes lines through each other) but no step is
  // committed to it, so the relaxation leaves no events in the clash report.
  for (const model::VesselSpec& v : m_model->spec().vessels)
    if (v.mode == model::VesselMode::Free && v.heldInStatics) return false;
  double longest = 0.0;
  for (const model::LineSpec& line : m_model->spec().lines) {
    double length = 0.0;
    for (const model::SectionSpec& s : line.sections) length += s.length;
    longest = std::max(longest, length);
  }
  std::vector<model::PrescribedNode> prescribed = time::prescribedNodes(*m_model);
  if (m_vessels)
    for (model::PrescribedNode& n : m_vessels->prescribedNodes()) prescribed.push_back(std::move(n));
  time::DynamicRelaxation relaxation(*m_assembler, m_model->spec().dynamics, std::move(prescribed), longest);
  // Rounds of two periods of the slowest (pendulum) mode, each followed by a Newton solve from the shape
  // reached; at rest means slower than 1 mm/s.
  const double period = 2.0 * std::numbers::pi / (0.5 * relaxation.damping());
  constexpr int kRounds = 4;
  constexpr double kRestSpeed = 1e-3;
  model::State relaxed = m_state;
  int newtonIterations = result.iterations;  // every Newton iteration before, and of the rounds that failed
  int lastRound = 0;
  for (int round = 0; round < kRounds; ++round) {
    if (m_staticsProgress)
      m_staticsProgress->stage(fmt::format("statics: dynamic relaxation, round {} of up to {}", round + 1, kRounds));
    const time::RelaxationResult r = relaxation.run(relaxed, m_state.time, 2.0 * period, kRestSpeed);
    if (solver::StaticSolver::debugOutput())
      std::cerr << fmt::format("  dynamic relaxation round {}: {}\n", round + 1, r.message);
    if (core::interruptRequested()) return false;
    if (r.steps == 0) break;  // the relaxation cannot move: Newton would start where it failed
    model::State trial = relaxed;
    solver::StaticSolver solver(*m_assembler, m_model->spec().statics);
    solver.setProgress(m_staticsProgress, fmt::format("(after dynamic relaxation round {})", round + 1));
    solver::StaticResult again = solver.solve(trial);
    if (again.converged) {
      again.iterations += newtonIterations;
      again.message += fmt::format(
          ", from the shape at rest after dynamic relaxation ({} round(s), damping {:.3g} 1/s; {} Newton "
          "iterations "
          "in all)",
          round + 1, relaxation.damping(), again.iterations);
      result = again;
      m_state = trial;
      return true;
    }
    newtonIterations += again.iterations;
    lastRound = round + 1;
  }
  result.iterations = newtonIterations;
  if (lastRound > 0)
    result.message += fmt::format(
        "; dynamic relaxation was tried as well ({} round(s)) and Newton did not converge "
        "from the shape it reached either",
        lastRound);
  return false;
}

bool Simulation::solveFromCoarserMesh(solver::StaticResult& result) {
  // A fine mesh has the coarse one's equilibrium to within its discretisation error, but Newton may not
  // reach it from the start shape: soft modes (a buoyant hump swinging across a current) make every
  // load increment crawl, the more so the more nodes share the mode. The coarse mesh reaches it, and
  // from the interpolated coarse equilibrium the fine Newton has only the discretisation to correct.
  constexpr int kFactor = 4;
  model::ModelSpec coarseSpec = m_model->spec();
  bool coarser = false;
  for (model::LineSpec& line : coarseSpec.lines)
    for (model::SectionSpec& s : line.sections) {
      const int n = std::max(1, (s.elements + kFactor - 1) / kFactor);
      if (n < s.elements && s.elements >= 2 * kFactor) {
        s.elements = n;
        coarser = true;
      }
    }
  if (!coarser) return false;
  std::unique_ptr<Simulation> coarse;
  try {
    coarse = std::make_unique<Simulation>(std::move(coarseSpec));
  } catch (const Error&) {
    return false;  // e.g. an attachment that the coarse mesh cannot place
  }
  coarse->m_coarseFallback = false;
  if (m_staticsProgress)
    m_staticsProgress->stage("statics: solving the model with a quarter of the elements first");
  coarse->m_staticsProgress = m_staticsProgress;
  const solver::StaticResult coarseResult = coarse->solveStatics();
  coarse->m_staticsProgress = nullptr;
  if (solver::StaticSolver::debugOutput())
    std::cerr << "  coarse mesh (1/" << kFactor << " of the elements): " << coarseResult.message << "\n";
  if (!coarseResult.converged) {
    result.message += "; the model with a quarter of the elements did not converge either";
    result.iterations += coarseResult.iterations;
    return false;
  }
  // Interpolate the coarse equilibrium onto this mesh: a cubic Hermite curve in unstretched arc length
  // through the coarse nodes (tangents by central differences), so that the fine elements keep the coarse
  // strain instead of cutting the corners at the coarse nodes (with linear interpolation the 40 m lazy-wave
  // mesh put the 10 m one in 7e7 N of compression at the hump). Heights are kept within the two coarse
  // nodes' range below (no dip into the seabed at touchdown). Beam triads: slerp of the coarse ones,
  // turned so that their first axis follows the curve.
  const model::Model& cm = coarse->model();
  const model::State& cs = coarse->m_state;
  model::State start = m_state;
  for (std::size_t l = 0; l < m_model->lines().size(); ++l) {
    const model::Line& fine = m_model->lines()[l];
    const model::Line& rough = cm.lines()[l];
    const auto& arc = rough.arcLength;
    const int last = rough.nodeCount - 1;
    auto slope = [&](int k) {  // dx/ds at coarse node k [-]
      const int a = std::max(k - 1, 0), b = std::min(k + 1, last);
      return Vec3((cs.position[rough.firstNode + b] - cs.position[rough.firstNode + a]) /
                  (arc[static_cast<std::size_t>(b)] - arc[static_cast<std::size_t>(a)]));
    };
    int k = 0;
    for (int j = 0; j < fine.nodeCount; ++j) {
      const double s = fine.arcLength[static_cast<std::size_t>(j)];
      while (k + 1 < last && arc[static_cast<std::size_t>(k + 1)] < s) ++k;
      const double s0 = arc[static_cast<std::size_t>(k)], h = arc[static_cast<std::size_t>(k + 1)] - s0;
      const double a = std::clamp((s - s0) / h, 0.0, 1.0);
      const int n0 = rough.firstNode + k, n1 = n0 + 1;
      const Vec3 &p0 = cs.position[n0], &p1 = cs.position[n1];
      const Vec3 m0 = h * slope(k), m1 = h * slope(k + 1);
      const double a2 = a * a, a3 = a2 * a;
      Vec3 x = (2 * a3 - 3 * a2 + 1) * p0 + (a3 - 2 * a2 + a) * m0 + (-2 * a3 + 3 * a2) * p1 + (a3 - a2) * m1;
      x.z() = std::max(x.z(), std::min(p0.z(), p1.z()));
      const int n = fine.firstNode + j;
      start.position[n] = x;
      if (!m_model->dofs().hasRotations(n)) continue;  // bar nodes keep the identity triad
      const Vec3 dx =
          (6 * a2 - 6 * a) * p0 + (3 * a2 - 4 * a + 1) * m0 + (-6 * a2 + 6 * a) * p1 + (3 * a2 - 2 * a) * m1;
      const Eigen::Quaterniond q0(cs.triad[n0]), q1(cs.triad[n1]);
      Mat3 triad = q0.slerp(a, q1).normalized().toRotationMatrix();
      if (dx.norm() > 0.0) triad = geometry::rotationBetween(triad.col(0), dx.normalized()) * triad;
      start.triad[n] = triad;
    }
  }
  for (std::size_t v = 0; v < m_model->vessels().size(); ++v) {
    const int n = m_model->vesselNode(static_cast<int>(v)), c = cm.vesselNode(static_cast<int>(v));
    if (n < 0 || c < 0) continue;
    start.position[n] = cs.position[c];
    start.triad[n] = cs.triad[c];
  }
  const model::State interpolated = start;
  solver::StaticSolver solver(*m_assembler, m_model->spec().statics);
  solver.setProgress(m_staticsProgress, "(from the coarse mesh's equilibrium)");
  solver::StaticResult again = solver.solve(start);
  if (!again.converged) {
    result.message +=
        "; from the equilibrium of the model with a quarter of the elements it did not "
        "converge either";
    result.iterations += coarseResult.iterations + again.iterations;
    // The dynamic relaxation that comes next starts from there: near the equilibrium, not from where the
    // continuation stalled.
    m_state = interpolated;
    return false;
  }
  again.iterations += result.iterations + coarseResult.iterations;
  again.message += fmt::format(
      ", from the equilibrium of the same model with a quarter of the elements ({} Newton iterations in "
      "all)",
      again.iterations);
  result = again;
  m_state = start;
  return true;
}

std::vector<solver::LineSnapshot> Simulation::snapshot(bool dynamic) {
  std::vector<solver::LineSnapshot> lines;
  lineResults(supportForce(dynamic), dynamic, lines);
  return lines;
}

void Simulation::lineResults(const VecX& supportForce, bool dynamic, std::vector<solver::LineSnapshot>& out,
                             solver::LineResultDetail detail) {
  // Statics: the exact end forces of the discrete model (the dynamics keep the extrapolated ones, which
  // the range graphs compute at every step from the elements alone); they need the tensions along.
  if (!dynamic) detail = solver::LineResultDetail::All;
  solver::computeLineResults(*m_model, *m_assembler, m_state, &supportForce, out, detail);
  if (!dynamic) setStaticEndForces(*this, out);
}

VecX Simulation::supportForce(bool dynamic) {
  VecX force;
  supportForce(dynamic, force);
  return force;
}

void Simulation::supportForce(bool dynamic, VecX& force) {
  solver::AssemblyRequest request;
  request.wantMatrix = false;
  request.dynamic = dynamic;
  request.time = m_state.time;
  // The force is read at the line ends only (the support reactions). Where the loads allow parts, the
  // ends and their neighbours are assembled alone: Assembler::assemblePart gives those entries bit for bit
  // as a whole assembly does (the same terms in the same order). A whole assembly at every output time
  // is avoided (docs/performance.md). With line contact too: selectPart refuses a part holding a node the
  // contact loads (its candidates' nodes, marked after each whole assembly), and elsewhere the contact adds
  // nothing (a whole assembly here was 3 % of the CPU of 12 lines with contact on every pair, apart; every
  // output of the contact examples the same bits without it). Not where selectPart refuses (an end held by
  // a vessel).
  // The model's lines do not change: their ends and the part are made at the first call, and each call asks
  // only whether the part is usable (a coupled host's selection of the same part at every step was 1-2 % of
  // its run).
  if (m_snapshotEnds.empty()) {
    for (const model::Line& line : m_model->lines()) {
      m_snapshotEnds.push_back(line.firstNode);
      m_snapshotEnds.push_back(line.lastNode());
    }
    std::sort(m_snapshotEnds.begin(), m_snapshotEnds.end());
    m_snapshotEnds.erase(std::unique(m_snapshotEnds.begin(), m_snapshotEnds.end()), m_snapshotEnds.end());
    if (m_assembler->supportsParts()) m_assembler->selectPart(m_snapshotEnds, m_snapshotPart);
  }
  const bool ends = m_assembler->supportsParts() && !m_snapshotPart.nodes.empty() &&
                    m_assembler->partUsable(m_snapshotPart);
  if (ends) {
    force.setZero(m_model->dofs().fullDofCount());
    m_assembler->assemblePart(m_state, request, m_snapshotPart, force);
  } else {
    m_assembler->assemble(m_state, request, force, nullptr);
  }
  if (dynamic) {
    // Inertia belongs in the support reactions of a moving line.
    m_supportInertia.setZero(force.size());
    if (ends)
      m_assembler->addPartMass(m_state, m_snapshotPart, m_state.acceleration, m_supportInertia);
    else
      m_assembler->addMass(m_state, 0.0, nullptr, &m_state.acceleration, &m_supportInertia);
    force += m_supportInertia;
  }
  // Ends tied to vessels: take the link forces out, so what remains at the end node is the line's pull.
  if (m_vessels) force -= m_vessels->endConnectionForces(m_state, m_state.time);
  // Ends at free points: likewise the ties' forces.
  if (m_junctions) force -= m_junctions->tieForces(m_state);
}

const std::vector<solver::LineSnapshot>& Simulation::sectionSnapshot() const {
  solver::computeLineResults(*m_model, *m_assembler, m_state, nullptr, m_sectionSnapshot,
                             solver::LineResultDetail::SectionForces);
  return m_sectionSnapshot;
}

time::DynamicResult Simulation::runDynamics(const time::DynamicAnalysis::Observer& observer, bool progress,
                                            const time::DynamicAnalysis::StepObserver& stepObserver,
                                            const time::DynamicAnalysis::StopRequest& stop) {
  time::DynamicAnalysis dynamics(*m_assembler, m_model->spec().dynamics);
  dynamics.setProgress(progress);
  dynamics.setObserver(observer);
  if (stepObserver) dynamics.setStepObserver(stepObserver);
  if (stop) dynamics.setStopRequest(stop);
  if (m_vessels) dynamics.addPrescribed(m_vessels->prescribedNodes());
  // The run advances m_state itself, so snapshot() inside the observer sees the output state.
  // The seabed friction anchors (carried over from statics, so a model with no time-varying load stays at
  // its static state) and the contact's states are committed by the dynamics (LoadContributor's protocol).
  return dynamics.run(m_state);
}

}  // namespace tangle::analysis
