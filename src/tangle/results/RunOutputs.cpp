#include "tangle/results/RunOutputs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <future>
#include <iostream>
#include <iterator>
#include <mutex>
#include <optional>
#include <sstream>

#include "tangle/analysis/EnergyAccount.hpp"
#include "tangle/analysis/EquilibriumAudit.hpp"
#include "tangle/analysis/FatigueDamage.hpp"
#include "tangle/analysis/RangeGraphs.hpp"
#include "tangle/analysis/ResponseStatistics.hpp"
#include "tangle/analysis/SeabedImpacts.hpp"
#include "tangle/contact/ClashReport.hpp"
#include "tangle/contact/ClearanceEnvelope.hpp"
#include "tangle/contact/StartShapeCrossings.hpp"
#include "tangle/contact/StaticContactReport.hpp"
#include "tangle/core/Error.hpp"
#include "tangle/core/JsonWriter.hpp"
#include "tangle/core/OutputFile.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/io/BackgroundWriter.hpp"
#include "tangle/io/DynamicRecorder.hpp"
#include "tangle/io/Hdf5Results.hpp"
#include "tangle/io/HtmlReport.hpp"
#include "tangle/io/ResultWriter.hpp"
#include "tangle/io/VtkWriter.hpp"
#include "tangle/results/DesignOutputs.hpp"
#include "tangle/results/RunText.hpp"
#include "tangle/vessel/VesselSystem.hpp"

namespace tangle::results {

namespace fs = std::filesystem;

namespace {

std::string readTextFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  if (in) s << in.rdbuf();
  return s.str();
}

/// Horizontal distance [m] of vessel `v`'s reference point at `state` from its position in the model.
/// The total offset: the low-frequency pose (the vessel node) plus, where the vessel has RAOs in waves, the
/// wave-frequency motion of its reference point (VesselSystem::waveFrequencyMotion, first order), as its line
/// ends get it (the mean, low- and wave-frequency offsets of DNV-OS-E301 Ch.2 Sec.2 and API RP 2SK combined
/// in the time domain). Until 2026-12-06 the wave-frequency part was left out: a prescribed unit swaying 2 m
/// in a storm reported a largest offset of 0.00 m.
double horizontalOffset(const model::Model& m, const model::State& state, std::size_t v,
                        const vessel::VesselSystem* vessels) {
  Vec3 d = state.position[static_cast<std::size_t>(m.vesselNode(static_cast<int>(v)))] -
           m.spec().vessels[v].position;
  if (vessels)
    if (const auto wave = vessels->waveFrequencyMotion(static_cast<int>(v), state.time)) {
      d.x() += (*wave)[0];
      d.y() += (*wave)[1];
    }
  return std::hypot(d.x(), d.y());
}

/// The horizontal offset [m] of each vessel at `state` (horizontalOffset) into `offset`, and the largest so
/// far into `maxOffset`.
void updateOffsets(const model::Model& m, const model::State& state, const vessel::VesselSystem* vessels,
                   std::vector<double>& offset, std::vector<double>& maxOffset) {
  offset.resize(maxOffset.size());
  for (std::size_t v = 0; v < maxOffset.size(); ++v) {
    offset[v] = horizontalOffset(m, state, v, vessels);
    maxOffset[v] = std::max(maxOffset[v], offset[v]);
  }
}

void writeDynamicSummary(const fs::path& dir, const time::DynamicResult& r, const io::DynamicRecorder& rec,
                         const std::vector<solver::LineSnapshot>& lines, double maxStopForce,
                         const model::Model& m, const std::vector<double>& maxOffset,
                         const analysis::LineFailure* failure, const vessel::HullContact* hulls) {
  core::OutputFile out(dir / "dynamics" / "summary.json");
  core::JsonWriter j(out.stream());
  j.beginObject();
  j.field("completed", r.completed);
  j.field("end_time_s", r.endTime);
  j.field("steps", r.steps);
  j.field("step_cutbacks", r.cutbacks);
  j.field("newton_iterations", static_cast<double>(r.newtonIterations));
  j.field("newton_iterations_on_parts", static_cast<double>(r.partIterations));
  j.field("converged_blocks_left_out", static_cast<double>(r.blocksLeft));
  j.field("matrix_refreshes", static_cast<double>(r.matrixRefreshes));
  j.field("block_refreshes", static_cast<double>(r.blockRefreshes));
  j.field("matrix_step_length_changes", static_cast<double>(r.matrixStepLengthChanges));
  j.field("fallback_steps", static_cast<double>(r.fallbackSteps));
  j.field("unload_rejections", r.unloadRejections);
  {
    const model::DynamicSolverSpec& c = m.spec().dynamics.solver;
    j.key("solver");
    j.beginObject();
    for (const model::DynamicSolverSpec::Choice& choice : model::DynamicSolverSpec::kChoices)
      j.field(choice.key, c.valueOf(choice));
    j.endObject();
  }
  j.field("wall_time_s", r.wallSeconds);
  j.field("real_time_factor", r.endTime / std::max(r.wallSeconds, 1e-9));
  j.field("message", r.message);
  j.field("extremes_over", "every accepted time step");
  j.field("max_tensioner_stop_force_N", maxStopForce);
  j.key("lines");
  j.beginArray();
  const std::vector<std::string> stems = io::lineFileStems(lines);
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const auto& range = rec.ranges()[l];
    j.beginObject();
    j.field("name", lines[l].name);
    j.field("file_stem", stems[l]);
    j.field("max_tension_N", *std::max_element(range.tensionMax.begin(), range.tensionMax.end()));
    j.field("min_tension_N", *std::min_element(range.tensionMin.begin(), range.tensionMin.end()));
    j.field("max_bending_moment_Nm", *std::max_element(range.momentMax.begin(), range.momentMax.end()));
    j.field("end_a_max_tension_N", range.endTensionMaxA);
    j.field("end_a_min_tension_N", range.endTensionMinA);
    j.field("end_b_max_tension_N", range.endTensionMaxB);
    j.field("end_b_min_tension_N", range.endTensionMinB);
    j.field("slack_events", range.slackEvents);
    j.field("slack_time_s", range.slackTime);
    // Only where a line type of the line gives its minimum breaking load.
    if (const BreakingLoadUse use = breakingLoadUse(m, l, range.tensionMax); use.ratio > 0.0) {
      j.field("max_tension_over_mbl", use.ratio);
      j.field("max_tension_over_mbl_at_m", use.arc);
    }
    j.endObject();
  }
  j.endArray();
  // The lines that parted (lines[].failure), in the order they did; time null: parted before the statics.
  j.key("line_failures");
  j.beginArray();
  if (failure) {
    for (const analysis::LineBreak& b : failure->breaks()) {
      j.beginObject();
      j.field("line", m.lines()[static_cast<std::size_t>(b.line)].name);
      j.field("time_s", b.time);  // null (not finite): before the statics
      j.field("trigger", b.trigger);
      j.field("value", b.value);
      j.field("threshold", b.threshold);
      j.field("parted_from_m", b.arcFrom);
      j.field("parted_to_m", b.arcTo);
      j.field("message", b.description);
      j.endObject();
    }
  }
  j.endArray();
  // The contacts with hulls (vessels[].hull; vessel::HullImpacts), when a vessel has one.
  if (hulls) {
    j.key("hull_impacts");
    j.beginArray();
    for (const vessel::HullImpact& e : hulls->impacts().events()) {
      if (!e.impact) continue;
      j.beginObject();
      j.field("body_a", e.bodyA);
      j.field("body_b", e.bodyB);
      j.field("kind", e.lineOnHull ? "line on hull" : "hull on hull");
      j.field("start_time_s", e.startTime);
      j.field("impact_velocity_m_s", e.impactVelocity);
      j.field("rebound_velocity_m_s", e.reboundVelocity);
      j.field("peak_force_N", e.peakForce);
      j.field("impulse_Ns", e.impulse);
      j.field("bodies_effective_mass_kg", e.bodiesMass);
      j.field("eq5_mass_kg", e.eq5Mass);
      j.field("impact_energy_J", e.impactEnergy);
      j.endObject();
    }
    j.endArray();
  }
  j.key("vessels");
  j.beginArray();
  for (std::size_t v = 0; v < maxOffset.size(); ++v) {
    j.beginObject();
    j.field("name", m.vessels()[v].name);
    j.field("max_offset_m", maxOffset[v]);
    j.endObject();
  }
  j.endArray();
  j.endObject();
  out.close();
}

void makePlots(const fs::path& script, const fs::path& outDir, RunLog& log) {
  if (script.empty()) return;
  if (!fs::exists("/usr/bin/python3") || !fs::exists(script)) {
    log.info(fmt::format("plots skipped: /usr/bin/python3 or {} not found\n", script.string()));
    return;
  }
  const std::string cmd = fmt::format("/usr/bin/python3 '{}' '{}' > '{}' 2>&1", script.string(),
                                      outDir.string(), (outDir / "plots.log").string());
  if (std::system(cmd.c_str()) != 0) {
    log.warning(fmt::format("warning: plotting failed, see {}\n", (outDir / "plots.log").string()));
  } else {
    log.info(fmt::format("plots written to {}\n", (outDir / "plots").string()));
  }
}

/// Whether the run writes CSV time histories and results.h5 (output.format; `auto`: both unless the CSV
/// time histories would exceed OutputSpec::kAutoCsvLimit, then HDF5 only).
struct ResultFiles {
  bool csv = true, hdf5 = true;
};
ResultFiles resultFiles(const model::Model& m, bool staticsOnly) {
  const model::OutputSpec& o = m.spec().output;
  switch (o.format) {
    case model::ResultFormat::Csv:
      return {true, false};
    case model::ResultFormat::Hdf5:
      return {false, true};
    case model::ResultFormat::Both:
      return {true, true};
    case model::ResultFormat::Auto:
      break;
  }
  const model::DynamicSpec& d = m.spec().dynamics;
  if (!d.enabled || staticsOnly) return {true, true};
  // 10 quantities per node, ~13 characters per value ("-1.234567e+05,").
  const double records = std::floor(d.duration / d.outputInterval) + 1.0;
  const double bytes =
      m.spec().output.timeHistories.valuesPerNode() * 13.0 * static_cast<double>(m.nodeCount()) * records;
  return {bytes <= model::OutputSpec::kAutoCsvLimit, true};
}

/// report/data.json and report.html of a run. A missing three.js costs the page, not the run.
void writeReport(const io::HtmlReport& report, const fs::path& outDir, RunLog& log,
                 std::chrono::steady_clock::duration collected) {
  const auto t0 = std::chrono::steady_clock::now();
  const fs::path page = outDir / "report.html";
  const std::string data = report.json();
  {
    fs::create_directories(outDir / "report");
    core::OutputFile f(outDir / "report" / "data.json");
    f.write(data);
    f.close();
  }
  const int frames = report.frameCount();
  if (frames > 0)
    log.info(fmt::format("report: {} frame(s) of the dynamics{}\n", frames,
                         report.stride() > 1 ? fmt::format(", every {} output times", report.stride()) : ""));
  try {
    io::HtmlReport::writePage(data, readTextFile(outDir / "run.log"), page);
  } catch (const InputError& e) {
    log.warning(fmt::format("warning: report.html not written: {}\n", e.what()));
    return;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0 + collected).count();
  log.info(fmt::format("report written to {} ({:.1f} MB, {:.2f} s)\n", page.string(),
                       static_cast<double>(fs::file_size(page)) / 1e6, seconds));
}

}  // namespace

RunOutputs::RunOutputs(analysis::Simulation& simulation, io::OutputFolder& folder, RunLog& log,
                       RunOutputOptions options)
    : m_sim(&simulation),
      m_folder(&folder),
      m_log(&log),
      m_options(std::move(options)),
      m_start(std::chrono::steady_clock::now()) {}

RunOutputs::~RunOutputs() = default;

template <class Work>
void RunOutputs::timed(Work&& work) {
  const auto t0 = std::chrono::steady_clock::now();
  work();
  m_reportTime += std::chrono::steady_clock::now() - t0;
}

int RunOutputs::run() {
  try {
    if (!writeStatics()) return 2;
    const bool dynamics = m_sim->model().spec().dynamics.enabled && !m_options.staticsOnly;
    const bool ok = !dynamics || runDynamics();
    finish(ok);
    return ok ? 0 : 2;
  } catch (const std::exception& e) {
    // Record the failure in the folder's log and manifest, then let the caller report it.
    try {
      m_log->logOnly(fmt::format("error: {}\n", e.what()));
      m_folder->setStatus(std::string("failed: ") + e.what());
    } catch (const std::exception&) {  // NOLINT(bugprone-empty-catch): the disk may be what failed
    }
    throw;
  }
}

bool RunOutputs::writeStatics() {
  analysis::Simulation& sim = *m_sim;
  const model::Model& m = sim.model();
  const fs::path outDir = m_folder->path();
  io::OutputFolder& folder = *m_folder;
  RunLog& log = *m_log;
  std::unique_ptr<io::Hdf5Results>& h5 = m_h5;
  std::unique_ptr<contact::ClearanceEnvelope>& envelope = m_envelope;
  std::unique_ptr<io::HtmlReport>& report = m_report;
  log.info(modelSummary(m));
  if (const vessel::HullContact* hulls = sim.hullContact()) log.info(hulls->describe());
  log.warning(warningText(m.spec()));
  if (const analysis::LineFailure* failure = sim.lineFailure())
    for (const analysis::LineBreak& b : failure->breaks()) log.info(b.description + "\n");

  const solver::StaticResult result = sim.solveStatics(m_options.progress);
  for (const contact::StartShapeLift& lift : sim.startShapeLifts()) log.info(lift.describe(m) + "\n");
  for (const std::string& w : result.warnings) log.warning("warning: " + w + "\n");
  m_static = sim.snapshot();
  const std::vector<solver::LineSnapshot>& lines = m_static;
  // The equilibrium audit (theory 7.8) of a converged solution: every force on every line and free vessel
  // by source; a body out of balance is a result that is not the physics.
  std::optional<solver::EquilibriumAudit> audit;
  if (result.converged && !m.spec().statics.skip) {
    audit = analysis::auditStatics(sim, lines);
    for (const std::string& w : audit->warnings()) log.warning("warning: " + w + "\n");
  }
  io::writeStaticSummary(outDir, m, result, lines, audit ? &*audit : nullptr);
  if (!result.converged) {
    log.error("error: " + result.message + "\n");
    log.error(fmt::format("no static results were written; the solver status is in {}\n",
                          (outDir / "summary.json").string()));
    folder.setStatus("failed: statics did not converge");
    if (!m_options.noReport) {
      // The page still gives the model, the log and the shape where the solver stopped, for the diagnosis.
      io::HtmlReport failed(m, "run", modelSummary(m));
      failed.setStatics(lines, sim.state(), nullptr, nullptr);
      failed.setStatus("failed: statics did not converge");
      writeReport(failed, outDir, log, {});
    }
    return false;
  }
  io::writeStaticLineTables(outDir, lines);
  if (m.spec().output.vtk) io::PvdSeries(outDir / "vtk" / "statics.pvd").addStep(0.0, io::toPolylines(lines));
  const ResultFiles files = resultFiles(m, m_options.staticsOnly);
  m_csv = files.csv;
  m_hdf5 = files.hdf5;
  if (files.hdf5) {
    std::ifstream modelCopy(outDir / "model.yaml", std::ios::binary);
    const std::string modelText((std::istreambuf_iterator<char>(modelCopy)),
                                std::istreambuf_iterator<char>());
    h5 = std::make_unique<io::Hdf5Results>(outDir, m, modelText);
    h5->writeStatics(lines);
    if (audit) h5->writeAudit(*audit);
  }
  log.info(result.message + "\n");
  if (audit)
    log.info(fmt::format(
        "equilibrium audit: {} lines{} and {} free vessels {}; largest out-of-balance force {:.2g} of "
        "the body's weight or load\n",
        audit->lines.size(),
        audit->points.empty() ? std::string() : fmt::format(", {} points", audit->points.size()),
        audit->vessels.size(), audit->warnings().empty() ? "in balance" : "NOT in balance (see the warnings)",
        audit->worstRelativeResidual()));
  if (sim.contact()) log.info(contact::writeStaticContact(outDir, m, *sim.contact(), sim.state()));
  // The line pairs the clearance envelope and the clash report assess (LineContact::assessedPairs).
  m_assessedPairs =
      sim.contact() ? sim.contact()->assessedPairs(sim.state()) : std::vector<std::array<int, 2>>{};
  if (sim.contact() && m_assessedPairs.size() < sim.contact()->allowedPairCount())
    log.info(
        fmt::format("clearance and clash report: the {} of the {} allowed line pairs that are within the "
                    "clearance margin ({:g} m) of each other at the static equilibrium (more than {} pairs "
                    "are assessed only where they come near; clearance.pairs lists others)\n",
                    m_assessedPairs.size(), sim.contact()->allowedPairCount(),
                    m.spec().contact.clearanceMargin, contact::LineContact::kAssessedPairLimit));
  envelope = std::make_unique<contact::ClearanceEnvelope>(m, m_assessedPairs);
  if (envelope->empty()) {
    envelope.reset();
  } else {
    envelope->recordStatic(sim.state());
  }
  // The browser report: its collection is timed, so the run log states what it cost.
  if (!m_options.noReport) {
    timed([&] {
      report = std::make_unique<io::HtmlReport>(m, "run", modelSummary(m));
      report->setStatics(lines, sim.state(), sim.contact(), envelope.get());
    });
  }
  for (const auto& s : lines) {
    std::string text = fmt::format(
        "  line '{}': end A tension {:.1f} kN, end B tension {:.1f} kN, max bending moment {:.2f} kN m",
        s.name, s.endTensionA / 1000.0, s.endTensionB / 1000.0,
        *std::max_element(s.bendingMoment.begin(), s.bendingMoment.end()) / 1000.0);
    if (s.touchdownArcLength >= 0.0)
      text += fmt::format(", touchdown at {:.1f} m from end A", s.touchdownArcLength);
    log.info(text + "\n");
  }
  const vessel::VesselSystem* vessels = sim.vessels();
  if (vessels) log.info(tensionerText(m, vessels->tensionerReadings(sim.state(), 0.0)));
  // Where the static solve put each vessel (a free vessel settles under its lines and the current).
  if (!m.vessels().empty()) {
    core::OutputFile vesselFile(outDir / "statics" / "vessels.csv");
    vesselFile.write(
        "vessel,mode,x_m,y_m,z_m,heading_deg,offset_x_m,offset_y_m,offset_z_m,heading_change_deg\n");
    for (int v = 0; v < static_cast<int>(m.vessels().size()); ++v) {
      const model::VesselSpec& spec = m.spec().vessels[static_cast<std::size_t>(v)];
      const int node = m.vesselNode(v);
      const Vec3& p = sim.state().position[node];
      const Vec3 xAxis = sim.state().triad[node].col(0);
      const double heading = radToDeg(std::atan2(xAxis.y(), xAxis.x()));
      const double change = std::remainder(heading - radToDeg(spec.heading), 360.0);
      const Vec3 offset = p - spec.position;
      vesselFile.write(fmt::format("{},{},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f}\n",
                                   spec.name, model::vesselModeName(spec.mode), p.x(), p.y(), p.z(), heading,
                                   offset.x(), offset.y(), offset.z(), change));
      if (spec.mode == model::VesselMode::Free)
        log.info(
            fmt::format("  vessel '{}': static position ({:.2f}, {:.2f}, {:.2f}) m, offset {:.2f} m "
                        "horizontally from its model position, heading {:.2f} deg ({:+.2f} deg)\n",
                        spec.name, p.x(), p.y(), p.z(), std::hypot(offset.x(), offset.y()), heading, change));
    }
    vesselFile.close();
  }
  log.warning(strainWarnings(m, lines));
  {
    std::vector<BreakingLoadUse> use;
    for (std::size_t l = 0; l < lines.size(); ++l) use.push_back(breakingLoadUse(m, l, lines[l].tension));
    log.warning(breakingLoadWarnings(m, use, "at the static equilibrium"));
  }
  return true;
}

bool RunOutputs::runDynamics() {
  const vessel::VesselSystem* vessels = m_sim->vessels();
  analysis::Simulation& sim = *m_sim;
  const model::Model& m = sim.model();
  const fs::path outDir = m_folder->path();
  io::OutputFolder& folder = *m_folder;
  RunLog& log = *m_log;
  std::unique_ptr<io::Hdf5Results>& h5 = m_h5;
  std::unique_ptr<contact::ClearanceEnvelope>& envelope = m_envelope;
  std::unique_ptr<io::HtmlReport>& report = m_report;
  const std::vector<solver::LineSnapshot>& lines = m_static;
  io::DynamicRecorder recorder(outDir, lines, m.spec().output.vtk ? m.spec().output.vtkInterval : 0.0,
                               m_csv ? m.spec().output.timeHistories
                                     : model::TimeHistorySelection{false, false, false, false, false, false, false});
  if (h5) h5->beginDynamics(lines);
  recorder.setSeabed(analysis::RangeGraphs::seabedNodes(m));
  std::vector<double> vesselMotion(6 * m.vessels().size());
  // Largest horizontal offset of each vessel over every step, from the static position on [m].
  std::vector<double> maxOffset(m.vessels().size(), 0.0), offset;
  updateOffsets(m, sim.state(), vessels, offset, maxOffset);
  std::unique_ptr<contact::ClashReport> clash;
  if (sim.contact()) clash = std::make_unique<contact::ClashReport>(m, *sim.contact(), m_assessedPairs);
  // Vessel motions: position of the reference point and rotation (roll, pitch, yaw as a rotation
  // vector relative to the initial heading) against time.
  std::unique_ptr<core::OutputFile> vesselFile;
  const std::vector<std::string> vesselStems = [&] {
    std::vector<std::string> names;
    for (const auto& v : m.vessels()) names.push_back(v.name);
    return io::uniqueFileStems(names);
  }();
  if (!m.vessels().empty()) {
    vesselFile = std::make_unique<core::OutputFile>(outDir / "dynamics" / "vessels.csv");
    // Per vessel its low-frequency pose (the vessel node), then, where its line ends get one (RAOs and
    // waves), the wave-frequency motion of its reference point (_wf_ columns, first order: the total is
    // their sum).
    std::string header = "time_s";
    for (int v = 0; v < static_cast<int>(vesselStems.size()); ++v) {
      header += fmt::format(",{0}_x_m,{0}_y_m,{0}_z_m,{0}_rx_deg,{0}_ry_deg,{0}_rz_deg", vesselStems[v]);
      if (vessels && vessels->waveFrequencyMotion(v, 0.0)) {
        header += fmt::format(",{0}_wf_x_m,{0}_wf_y_m,{0}_wf_z_m,{0}_wf_rx_deg,{0}_wf_ry_deg,{0}_wf_rz_deg",
                              vesselStems[v]);
      }
    }
    vesselFile->write(header + "\n");
  }
  // Tensioners: stroke and stop force against time (every step; read on this thread, written by the
  // writer).
  std::unique_ptr<core::OutputFile> tensionerFile;
  double maxStopForce = 0.0;
  if (vessels && !vessels->tensionerReadings(sim.state(), 0.0).empty()) {
    tensionerFile = std::make_unique<core::OutputFile>(outDir / "dynamics" / "tensioners.csv");
    std::string header = "time_s";
    const std::vector<std::string> stems = io::lineFileStems(lines);
    for (const auto& r : vessels->tensionerReadings(sim.state(), 0.0))
      header += fmt::format(",{0}_end_{1}_stroke_m,{0}_end_{1}_force_N,{0}_end_{1}_stop_force_N",
                            stems[r.line], r.end == 0 ? 'a' : 'b');
    tensionerFile->write(header + "\n");
  }
  // The range graphs and the clearance envelope of every step are also accumulated by the writer, from a
  // copy of the positions and triads (all they read): the section forces of every element and the
  // clearance search are off the solver's thread (docs/performance.md). Their work space
  // below is the writer's alone; the report's frames (this thread) measure clearances with their own
  // envelope object (ClearanceEnvelope keeps a search cache).
  std::vector<solver::LineSnapshot> stepSnapshot;
  std::unique_ptr<contact::ClearanceEnvelope> frameEnvelope;
  if (envelope) frameEnvelope = std::make_unique<contact::ClearanceEnvelope>(m, m_assessedPairs);
  // Steps are handed over in batches (one job per kStepsPerJob steps: a job per step cost more in
  // hand-over than it moved off this thread on the mooring example), always before an output time's job.
  // A batch holds its steps' positions (and triads) in one array each, filled in place: a state copied
  // per step was an allocation here and a release on the writer's thread every step (docs/performance.md).
  struct StepBatch {
    std::vector<double> time, dt;
    std::vector<Vec3> positions;  // nodeCount per step, step after step
    std::vector<Mat3> triads;     // likewise, with rotational DOFs only
    std::vector<std::vector<vessel::VesselSystem::TensionerReading>> tensioners;
    // A viscoelastic rope's tension is an internal variable of the committed state, not a function of the
    // positions: each step's (model::State::viscoelastic; empty without such ropes). Without it the ranges,
    // extremes, statistics and fatigue took the ropes' static EA (polyester-taut-mooring: a fairlead range
    // of 1.25-2.51 MN where the tension histories swing over 1.01-2.76 MN).
    std::vector<model::State::Viscoelastic> viscoelastic;
    std::size_t size() const { return time.size(); }
    void clear() {
      time.clear();
      dt.clear();
      positions.clear();
      triads.clear();
      tensioners.clear();
      viscoelastic.clear();
    }
  };
  constexpr std::size_t kStepsPerJob = 32;
  const auto nodeCount = static_cast<std::size_t>(m.dofs().nodeCount());
  // Triads are read only at nodes with rotations (beams): without any, none is copied (12 bar lines:
  // 174 kB a step; docs/performance.md).
  bool anyRotations = false;
  for (int n = 0; n < m.dofs().nodeCount(); ++n) anyRotations = anyRotations || m.dofs().hasRotations(n);
  // The writer hands every batch it has done back (emptied, its arrays keep their room): a new batch per
  // 32 steps was an allocation of fresh pages, each touched first by the solver's thread (a page fault
  // per 4 kB; docs/performance.md).
  std::mutex spareMutex;
  std::vector<std::shared_ptr<StepBatch>> spareBatches;
  const auto newBatch = [&] {
    {
      const std::lock_guard lock(spareMutex);
      if (!spareBatches.empty()) {
        std::shared_ptr<StepBatch> b = std::move(spareBatches.back());
        spareBatches.pop_back();
        return b;
      }
    }
    auto b = std::make_shared<StepBatch>();
    b->time.reserve(kStepsPerJob);
    b->dt.reserve(kStepsPerJob);
    b->positions.reserve(kStepsPerJob * nodeCount);
    if (anyRotations) b->triads.reserve(kStepsPerJob * nodeCount);
    return b;
  };
  auto pendingSteps = newBatch();
  model::State stepState;  // the writer's: one step of a batch, as computeLineResults reads it
  // The CSV rows, results.h5 and vessels.csv of each output time are formatted, compressed and written on
  // a background thread while the integration goes on (BackgroundWriter's contract: each job gets copies
  // of the state it needs). Declared after everything its jobs use, so that it finishes them before
  // those are destroyed, also when the dynamics end with an exception.
  // The peaks of the end tensions and of the tension and moment along the lines after the ramp, from every
  // step (the writer's); of each vessel's horizontal offset (this thread's).
  analysis::ResponseStatistics statistics(lines, m.spec().dynamics.rampTime);
  std::vector<analysis::PeakTracker> offsetPeaks(m.vessels().size());
  // Fatigue damage along the lines, counted by the writer from every step (the writer's alone).
  analysis::FatigueDamage fatigue(m);
  io::BackgroundWriter writer;
  const auto submitSteps = [&] {
    if (pendingSteps->size() == 0) return;
    writer.submit([&, steps = std::move(pendingSteps)] {
      for (std::size_t k = 0; k < steps->size(); ++k) {
        const auto first = static_cast<std::ptrdiff_t>(k * nodeCount);
        const auto last = first + static_cast<std::ptrdiff_t>(nodeCount);
        stepState.time = steps->time[k];
        stepState.position.assign(steps->positions.begin() + first, steps->positions.begin() + last);
        if (anyRotations) stepState.triad.assign(steps->triads.begin() + first, steps->triads.begin() + last);
        if (steps->viscoelastic.size() == steps->size())
          stepState.viscoelastic = std::move(steps->viscoelastic[k]);
        // Ranges need no support reactions (as Simulation::sectionSnapshot, from the copy).
        solver::computeLineResults(m, sim.assembler(), stepState, nullptr, stepSnapshot,
                                   solver::LineResultDetail::SectionForces);
        recorder.accumulate(stepSnapshot, steps->dt[k]);
        if (!fatigue.empty()) fatigue.accumulate(stepSnapshot, stepState);
        statistics.accumulate(stepSnapshot, stepState.time);
        if (envelope) envelope->record(stepState);  // every step: the minimum must not fall between outputs
        if (tensionerFile) {
          std::string row = fmt::format("{:.6f}", stepState.time);
          for (const auto& r : steps->tensioners[k])
            row += fmt::format(",{:.6f},{:.6e},{:.6e}", r.stroke, r.force, r.stopForce);
          tensionerFile->write(row + "\n");
        }
      }
      steps->clear();
      const std::lock_guard lock(spareMutex);
      spareBatches.push_back(steps);
    });
    pendingSteps = newBatch();
  };
  if (report) {
    const auto& d = m.spec().dynamics;
    report->planFrames(static_cast<int>(std::ceil(d.duration / std::max(d.outputInterval, 1e-12))) + 1);
  }
  // The energy account (theory 8.6), when the model asks for it: on this thread, at every step.
  std::unique_ptr<analysis::EnergyAccount> energy;
  std::unique_ptr<core::OutputFile> energyFile;
  if (m.spec().output.energy) {
    energy = std::make_unique<analysis::EnergyAccount>(sim);
    energy->start(sim.state());
    energyFile = std::make_unique<core::OutputFile>(outDir / "dynamics" / "energy.csv");
    std::string header = "time_s,kinetic_energy_J,kinetic_energy_change_J";
    for (const auto& [name, work] : energy->totals().work) header += ",\"work: " + name + " [J]\"";
    energyFile->write(header + ",residual_J,energy_flow_J\n");
  }
  const auto energyRow = [&] {
    const analysis::EnergyTotals& t = energy->totals();
    std::string row = fmt::format("{:.6f},{:.9e},{:.9e}", t.time, t.kinetic, t.kineticChange);
    for (const auto& [name, work] : t.work) row += fmt::format(",{:.9e}", work);
    energyFile->write(row + fmt::format(",{:.9e},{:.9e}\n", t.residual, t.throughput));
  };
  if (energy) energyRow();
  // Impacts of the lines on the seabed (theory 5.4): at every accepted step, on this thread.
  analysis::SeabedImpacts seabedImpacts(m, m.spec().contact.impactVelocityThreshold);
  seabedImpacts.start(sim.state());
  const time::DynamicResult dyn = sim.runDynamics(
      [&](const model::State& s, const VecX&) {
        if (energy && s.time > energy->totals().time - 1e-12 && s.time > 0.0) energyRow();
        submitSteps();  // the steps up to this output time first (the files keep their order)
        auto shared = std::make_shared<const std::vector<solver::LineSnapshot>>(sim.snapshot(true));
        const std::vector<solver::LineSnapshot>& snap = *shared;
        if (report) timed([&] { report->recordOutput(snap, s, sim.contact(), frameEnvelope.get()); });
        if (clash) clash->recordClearance(s);
        for (int v = 0; v < static_cast<int>(m.vessels().size()); ++v)
          std::ranges::copy(m.vesselMotion(s, v), vesselMotion.begin() + 6 * v);
        // Per vessel, its wave-frequency motion where it has one (the header's _wf_ columns).
        std::vector<std::optional<std::array<double, 6>>> waveMotion(m.vessels().size());
        for (int v = 0; vessels && v < static_cast<int>(waveMotion.size()); ++v)
          waveMotion[static_cast<std::size_t>(v)] = vessels->waveFrequencyMotion(v, s.time);
        writer.submit([&, shared, time = s.time, motion = vesselMotion, waveMotion = std::move(waveMotion)] {
          recorder.record(time, *shared);
          if (h5) h5->record(time, *shared, motion);
          if (vesselFile) {
            std::string row = fmt::format("{:.4f}", time);
            for (std::size_t k = 0; k < motion.size(); k += 6) {
              row += fmt::format(",{:.4f},{:.4f},{:.4f},{:.5f},{:.5f},{:.5f}", motion[k], motion[k + 1],
                                 motion[k + 2], motion[k + 3], motion[k + 4], motion[k + 5]);
              if (const auto& w = waveMotion[k / 6])
                row += fmt::format(",{:.4f},{:.4f},{:.4f},{:.5f},{:.5f},{:.5f}", (*w)[0], (*w)[1], (*w)[2],
                                   (*w)[3], (*w)[4], (*w)[5]);
            }
            vesselFile->write(row + "\n");
            vesselFile->flush();
          }
        });
      },
      m_options.progress,
      [&](const model::State& s, double dt) {
        StepBatch& b = *pendingSteps;
        b.time.push_back(s.time);
        b.dt.push_back(dt);
        b.positions.insert(b.positions.end(), s.position.begin(), s.position.end());
        updateOffsets(m, s, vessels, offset, maxOffset);
        if (s.time >= m.spec().dynamics.rampTime - 1e-9)
          for (std::size_t v = 0; v < offsetPeaks.size(); ++v) offsetPeaks[v].add(s.time, offset[v]);
        if (energy) energy->step(s, dt);
        seabedImpacts.commit(s, dt);
        if (anyRotations) b.triads.insert(b.triads.end(), s.triad.begin(), s.triad.end());
        // One per step of the batch once any step has them (the writer takes them only then).
        if (!s.viscoelastic.tension.empty() || !b.viscoelastic.empty()) {
          b.viscoelastic.resize(b.size() - 1);  // steps of this batch before the ropes' first commit: empty
          b.viscoelastic.push_back(s.viscoelastic);
        }
        if (tensionerFile) {
          // Every step: a tensioner touching its stop between two output times must show.
          b.tensioners.push_back(vessels->tensionerReadings(s, s.time));
          for (const auto& r : b.tensioners.back())
            maxStopForce = std::max(maxStopForce, std::abs(r.stopForce));
        }
        if (b.size() >= kStepsPerJob) submitSteps();
      },
      m_options.stop);
  submitSteps();
  writer.finish();  // every output time written (rethrows a write error)
  recorder.writeRanges();
  recorder.close();
  if (h5 && recorder.stepCount() > 0) h5->writeRanges(recorder);
  if (h5 && sim.contact()) h5->writeContactEvents(sim.contact()->events());
  if (report && recorder.stepCount() > 0) {
    timed([&] {
      for (std::size_t l = 0; l < recorder.ranges().size(); ++l) {
        const auto& r = recorder.ranges()[l];
        report->setRange(static_cast<int>(l), r.tensionMin, r.tensionMax, r.momentMin, r.momentMax,
                         r.curvatureMin, r.curvatureMax);
      }
      if (clash) report->setClash(*sim.contact(), *clash);
    });
  }
  if (vesselFile) vesselFile->close();
  if (tensionerFile) tensionerFile->close();
  if (clash) {
    clash->write(outDir);
    log.info(clash->terminalSummary());
  }
  seabedImpacts.finish();
  seabedImpacts.write(outDir / "dynamics");
  if (report) {
    timed([&] {
      report->addSeabedImpacts(seabedImpacts.events());
      if (const vessel::HullContact* hulls = sim.hullContact())
        report->addHullImpacts(hulls->impacts().events());
    });
  }
  if (seabedImpacts.impactCount() > 0) log.info(seabedImpacts.terminalSummary());
  if (!fatigue.empty()) {
    const std::vector<analysis::FatigueDamage::Line> damage = fatigue.finish();
    log.info(writeFatigue(outDir, m, fatigue, damage));
    if (h5) h5->writeFatigue(fatigue, damage);
    if (report) timed([&] { report->setFatigue(fatigue, damage); });
  }
  if (clash) {
    std::vector<int> contactLines;
    for (const auto& pair : m_assessedPairs)
      contactLines.insert(contactLines.end(), pair.begin(), pair.end());
    for (const contact::ContactEvent& e : sim.contact()->events()) {
      contactLines.push_back(e.lineA);
      contactLines.push_back(e.lineB);
    }
    std::sort(contactLines.begin(), contactLines.end());
    const model::ContactSpec& cs = m.spec().contact;
    const std::vector<analysis::LineClashDamage> damage = analysis::clashDamage(
        m, contactLines, sim.contact()->events(), cs.damageBinLength, cs.damageEnergyThreshold);
    log.info(writeClashDamage(outDir, m, damage, cs.damageEnergyThreshold));
    if (h5) h5->writeClashDamage(damage, cs.damageEnergyThreshold);
    if (report) timed([&] { report->setClashDamage(damage); });
  }
  if (const vessel::HullContact* hulls = sim.hullContact()) {
    hulls->impacts().write(outDir / "dynamics");
    log.info(hulls->impacts().terminalSummary());
  }
  writeDynamicSummary(outDir, dyn, recorder, lines, maxStopForce, m, maxOffset, sim.lineFailure(),
                      sim.hullContact());
  if (const analysis::LineFailure* failure = sim.lineFailure())
    for (const analysis::LineBreak& b : failure->breaks())
      if (std::isfinite(b.time)) log.info(b.description + "\n");
  {
    std::vector<BreakingLoadUse> use;
    for (std::size_t l = 0; l < lines.size(); ++l)
      use.push_back(breakingLoadUse(m, l, recorder.ranges()[l].tensionMax));
    log.warning(breakingLoadWarnings(m, use, "during the dynamics"));
  }
  {
    // The minimum clearance of each contact pair at the output times after the ramp (ClashReport's samples;
    // beyond the clearance margin: the margin).
    std::vector<std::array<int, 2>> pairs;
    std::vector<analysis::PeakTracker> clearancePeaks;
    if (clash) {
      pairs = clash->pairs();
      clearancePeaks.resize(pairs.size());
      const double margin = m.spec().contact.clearanceMargin;
      for (const contact::ClashReport::ClearanceSample& c : clash->samples())
        if (c.time >= m.spec().dynamics.rampTime - 1e-9)
          clearancePeaks[static_cast<std::size_t>(c.pair)].add(c.time, -std::min(c.clearance, margin));
    }
    log.info(writeExtremeStatistics(outDir, m, lines, statistics, offsetPeaks, pairs, clearancePeaks,
                                    m.spec().output.stormDuration));
    if (report)
      timed([&] {
        for (std::size_t l = 0; l < lines.size(); ++l) {
          const analysis::ExtremeEstimate e =
              analysis::extremeEstimate(statistics.lines()[l].endB, m.spec().output.stormDuration);
          if (e.valid) report->setPeakFit(static_cast<int>(l), e.peaks, e.rayleigh, e.weibull);
        }
      });
  }
  if (energy) {
    energyFile->close();
    const analysis::EnergyTotals& t = energy->totals();
    log.info(
        fmt::format("energy account: kinetic energy change {:.4g} J, work of the loads {:.4g} J, residual "
                    "{:.3g} % of the {:.4g} J that flowed (dynamics/energy.csv)\n",
                    t.kineticChange, t.kineticChange - t.residual,
                    t.throughput > 0.0 ? 100.0 * t.residual / t.throughput : 0.0, t.throughput));
    if (const std::string w = energy->warning(); !w.empty()) log.warning("warning: " + w + "\n");
  }
  if (maxStopForce > 0.0)
    log.warning(
        fmt::format("warning: a tensioner reached its end stop during the dynamics (largest stop force "
                    "{:.1f} kN, see dynamics/tensioners.csv)\n",
                    maxStopForce / 1000.0));
  if (!dyn.completed) {
    log.error("error: " + dyn.message + "\n");
    log.error(fmt::format("results up to t = {:.4g} s are in {}\n", dyn.endTime, outDir.string()));
    folder.setStatus(fmt::format("failed: dynamics stopped at t = {:.6g} s", dyn.endTime));
    if (report) report->setStatus(fmt::format("failed: dynamics stopped at t = {:.6g} s", dyn.endTime));
    return false;
  }
  log.info(dyn.message + "\n");
  return true;
}

void RunOutputs::finish(bool ok) {
  analysis::Simulation& sim = *m_sim;
  const model::Model& m = sim.model();
  const fs::path outDir = m_folder->path();
  io::OutputFolder& folder = *m_folder;
  RunLog& log = *m_log;
  std::unique_ptr<io::Hdf5Results>& h5 = m_h5;
  std::unique_ptr<contact::ClearanceEnvelope>& envelope = m_envelope;
  std::unique_ptr<io::HtmlReport>& report = m_report;
  if (envelope) {
    // Pairs designed to touch are assessed by the run's impacts (a run that stopped: those until then).
    if (sim.contact()) envelope->assessImpacts(sim.contact()->events());
    envelope->write(outDir);
    log.info(envelope->terminalSummary());
    if (h5) h5->writeClearance(*envelope);
  }
  // results.h5 is completed (its last chunks compressed and written, results.xdmf beside it) on a second
  // thread while this one writes the report: one after the other they took 16 and 12-17 ms of the mooring
  // example's run. The plots read results.h5, so they wait for it. HDF5 is used by one thread at a time.
  std::future<void> h5Closed;
  if (h5) h5Closed = std::async(std::launch::async, [&h5] { h5->close(); });
  if (m.spec().output.plots && !m_options.noPlots) {
    if (h5Closed.valid()) h5Closed.get();
    makePlots(m_options.plotScript, outDir, log);
  }
  if (report) {
    if (envelope) report->setEnvelope(*envelope);
    if (ok)
      report->setStatus(m_options.staticsOnly || !m.spec().dynamics.enabled ? "completed (statics)"
                                                                            : "completed");
    // The lines that parted (lines[].failure), beside the status at the top of the page.
    if (const analysis::LineFailure* failure = sim.lineFailure())
      for (const analysis::LineBreak& b : failure->breaks())
        report->setStatus(report->status() + "; " + b.description);
    writeReport(*report, outDir, log, m_reportTime);
  }
  if (h5Closed.valid()) h5Closed.get();  // rethrows a write error of results.h5
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
  if (ok)
    folder.setStatus(m_options.staticsOnly || !m.spec().dynamics.enabled ? "completed (statics)"
                                                                         : "completed");
  log.info(fmt::format("results written to {} ({:.2f} s)\n", outDir.string(), seconds));
}

}  // namespace tangle::results
