/// @file PySimulation.cpp
/// Analyses driven from Python (see PySimulation.hpp).

#include "tangle/python/PySimulation.hpp"

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <vector>

#include "tangle/analysis/EquilibriumAudit.hpp"
#include "tangle/analysis/RangeGraphs.hpp"
#include "tangle/analysis/SeabedImpacts.hpp"
#include "tangle/contact/ClearanceEnvelope.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/geometry/Rotation.hpp"
#include "tangle/io/ModelReader.hpp"
#include "tangle/io/OutputFolder.hpp"
#include "tangle/results/RunLog.hpp"
#include "tangle/results/RunOutputs.hpp"

namespace py = pybind11;

namespace tangle::python {

namespace {

using Array = py::array_t<double>;

/// A numpy array of the given shape filled from `data` (row-major).
Array array(const std::vector<double>& data, std::vector<py::ssize_t> shape) {
  Array a(shape);
  std::copy(data.begin(), data.end(), a.mutable_data());
  return a;
}

Array vec3Array(const Vec3& v) { return array({v.x(), v.y(), v.z()}, {3}); }

Array positions(const std::vector<Vec3>& p) {
  std::vector<double> flat;
  for (const Vec3& x : p) flat.insert(flat.end(), {x.x(), x.y(), x.z()});
  return array(flat, {static_cast<py::ssize_t>(p.size()), 3});
}

/// One line's results at one state (the quantities of statics/<line>.csv and summary.json).
py::dict profile(const solver::LineSnapshot& s) {
  const auto n = static_cast<py::ssize_t>(s.arcLength.size());
  py::dict d;
  d["name"] = s.name;
  d["arc_length_m"] = array(s.arcLength, {n});
  d["position_m"] = positions(s.position);
  d["effective_tension_N"] = array(s.tension, {n});
  if (!s.wallTension.empty()) {  // a line with a bore
    d["wall_tension_N"] = array(s.wallTension, {n});
    d["internal_pressure_Pa"] = array(s.internalPressure, {n});
  }
  d["bending_moment_Nm"] = array(s.bendingMoment, {n});
  d["curvature_1_per_m"] = array(s.curvature, {n});
  d["torque_Nm"] = array(s.torque, {n});
  d["end_a_tension_N"] = s.endTensionA;
  d["end_b_tension_N"] = s.endTensionB;
  d["end_a_force_N"] = vec3Array(s.endTensionForceA);
  d["end_b_force_N"] = vec3Array(s.endTensionForceB);
  d["end_a_support_reaction_N"] = vec3Array(s.endForceA);
  d["end_b_support_reaction_N"] = vec3Array(s.endForceB);
  d["touchdown_arc_length_m"] = s.touchdownArcLength >= 0.0 ? s.touchdownArcLength : std::nan("");
  d["nodes_on_seabed"] = s.seabedNodes;
  return d;
}

/// Time histories of one line, filled at the output times.
struct LineHistory {
  std::vector<double> position, tension, moment, curvature, torque, endTension, endForce;
  std::vector<double> wallTension;  // lines with a bore only
};

}  // namespace

std::pair<int, std::string> runToFolder(const std::string& yaml, const std::string& sourceName, const std::string& folder,
                                        bool overwrite, bool staticsOnly, bool report, bool plots, bool quiet) {
  analysis::Simulation sim(io::readModelString(yaml, sourceName));
  io::OutputFolder out(folder, sourceName, yaml, overwrite);
  results::RunLog log(quiet);
  log.open(out.path() / "run.log");
  log.info(fmt::format("tangle {} (Python)\n", TANGLE_VERSION));
  results::RunOutputOptions options;
  options.staticsOnly = staticsOnly;
  options.noReport = !report;
  options.noPlots = !plots;
  options.progress = !quiet;
  options.plotScript = std::filesystem::path(TANGLE_PYTHON_DIR) / "tangle_plot.py";
  std::atomic<bool> stopped{false};
  options.stop = [&stopped] {
    if (stopped) return true;
    py::gil_scoped_acquire acquire;
    if (PyErr_CheckSignals() != 0) {
      PyErr_Clear();  // the run reports the stop in its status; the caller raises
      stopped = true;
    }
    return stopped.load();
  };
  int code = 0;
  {
    py::gil_scoped_release release;
    code = results::RunOutputs(sim, out, log, options).run();
    log.close();
  }
  if (stopped) code = 130;  // as a shell reports SIGINT: the Python layer raises KeyboardInterrupt
  return {code, out.status()};
}

PySimulation::PySimulation(const std::string& yaml, const std::string& sourceName)
    : m_sim(std::make_unique<analysis::Simulation>(io::readModelString(yaml, sourceName))) {}

py::list PySimulation::lines() {
  py::list out;
  const model::Model& m = m_sim->model();
  for (int i = 0; i < static_cast<int>(m.lines().size()); ++i) {
    const model::Line& l = m.lines()[static_cast<std::size_t>(i)];
    py::dict d;
    d["name"] = l.name;
    d["nodes"] = l.nodeCount;
    d["elements"] = l.elementCount;
    d["length_m"] = l.length;
    d["mass_kg"] = m.lineMass(i);
    d["arc_length_m"] = array(l.arcLength, {static_cast<py::ssize_t>(l.arcLength.size())});
    out.append(d);
  }
  return out;
}

py::dict PySimulation::statics() {
  solver::StaticResult r;
  {
    py::gil_scoped_release release;
    r = m_sim->solveStatics();
  }
  m_staticsConverged = r.converged;
  py::dict d;
  d["converged"] = r.converged;
  d["iterations"] = r.iterations;
  d["load_fraction"] = r.loadFraction;
  d["max_out_of_balance_N"] = r.residual;
  d["message"] = r.message;
  // The equilibrium audit (theory 7.8), as the command line prints and stores it.
  py::list audit;
  if (r.converged) {
    const solver::EquilibriumAudit a = analysis::auditStatics(*m_sim, m_sim->snapshot());
    for (const std::string& w : a.warnings()) r.warnings.push_back(w);
    const auto add = [&audit](const solver::ForceBalance& b, const char* kind) {
      py::dict body;
      body["kind"] = kind;
      body["name"] = b.name;
      py::dict forces;
      for (const auto& [name, f] : b.terms) forces[py::str(name)] = vec3Array(f);
      body["forces_N"] = forces;
      body["residual_N"] = vec3Array(b.residual);
      body["reference_force_N"] = b.scale;
      body["relative_residual"] = b.relativeResidual();
      body["tolerance"] = b.tolerance;
      audit.append(body);
    };
    for (const solver::ForceBalance& b : a.lines) add(b, "line");
    for (const solver::ForceBalance& b : a.vessels) add(b, "vessel");
    for (const solver::ForceBalance& b : a.points) add(b, "point");
  }
  d["equilibrium_audit"] = audit;
  d["warnings"] = r.warnings;
  return d;
}

py::list PySimulation::profiles() {
  py::list out;
  for (const solver::LineSnapshot& s : m_sim->snapshot()) out.append(profile(s));
  return out;
}

py::dict PySimulation::dynamics(const py::object& progress) {
  if (!m_staticsConverged)
    throw std::runtime_error("run the statics first (the dynamics start from the static equilibrium)");
  const model::Model& m = m_sim->model();
  if (!m.spec().dynamics.enabled)
    throw std::runtime_error(
        "the model has no dynamics block (set dynamics.duration and dynamics.time_step)");
  const std::size_t lineCount = m.lines().size();
  std::vector<LineHistory> hist(lineCount);
  // Range graphs over every accepted step: the run's own accumulator (analysis::RangeGraphs), as the files.
  analysis::RangeGraphs ranges(m_sim->snapshot());
  ranges.setSeabed(analysis::RangeGraphs::seabedNodes(m));
  std::vector<double> times, vesselMotion;
  std::unique_ptr<contact::ClearanceEnvelope> envelope = std::make_unique<contact::ClearanceEnvelope>(
      m, m_sim->contact() ? m_sim->contact()->assessedPairs(m_sim->state()) : std::vector<std::array<int, 2>>{});
  if (envelope->empty()) {
    envelope.reset();
  } else {
    envelope->recordStatic(m_sim->state());
  }
  // Impacts on the seabed (analysis::SeabedImpacts), as dynamics/seabed_impacts.csv.
  analysis::SeabedImpacts seabedImpacts(m, m.spec().contact.impactVelocityThreshold);
  seabedImpacts.start(m_sim->state());
  const double duration = m.spec().dynamics.duration;
  std::atomic<bool> stop{false};
  py::object error = py::none();

  time::DynamicResult result;
  {
    py::gil_scoped_release release;
    const auto observer = [&](const model::State& s, const VecX&) {
      const std::vector<solver::LineSnapshot> snap = m_sim->snapshot(true);
      times.push_back(s.time);
      for (std::size_t l = 0; l < lineCount; ++l) {
        const solver::LineSnapshot& x = snap[l];
        LineHistory& h = hist[l];
        for (const Vec3& p : x.position) h.position.insert(h.position.end(), {p.x(), p.y(), p.z()});
        h.tension.insert(h.tension.end(), x.tension.begin(), x.tension.end());
        h.wallTension.insert(h.wallTension.end(), x.wallTension.begin(), x.wallTension.end());
        h.moment.insert(h.moment.end(), x.bendingMoment.begin(), x.bendingMoment.end());
        h.curvature.insert(h.curvature.end(), x.curvature.begin(), x.curvature.end());
        h.torque.insert(h.torque.end(), x.torque.begin(), x.torque.end());
        h.endTension.insert(h.endTension.end(), {x.endTensionA, x.endTensionB});
        const Vec3 &fa = x.endTensionForceA, &fb = x.endTensionForceB;
        h.endForce.insert(h.endForce.end(), {fa.x(), fa.y(), fa.z(), fb.x(), fb.y(), fb.z()});
      }
      for (int v = 0; v < static_cast<int>(m.vessels().size()); ++v) {
        const std::array<double, 6> motion = m.vesselMotion(s, v);  // as dynamics/vessels.csv
        vesselMotion.insert(vesselMotion.end(), motion.begin(), motion.end());
      }
      if (!progress.is_none() && !stop) {
        py::gil_scoped_acquire acquire;
        try {
          progress(s.time, duration);
        } catch (py::error_already_set& e) {
          error = e.value();
          stop = true;
        }
      }
    };
    const auto stepObserver = [&](const model::State& s, double dt) {
      ranges.accumulate(m_sim->sectionSnapshot(), dt);
      if (envelope) envelope->record(s);
      seabedImpacts.commit(s, dt);
    };
    // Ctrl-C: Python's handler only sets a flag; it is seen here, with the GIL, before every step.
    const auto stopRequest = [&]() {
      if (stop) return true;
      py::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() != 0) {
        error = py::error_already_set().value();  // takes the pending KeyboardInterrupt
        stop = true;
      }
      return stop.load();
    };
    result = m_sim->runDynamics(observer, false, stepObserver, stopRequest);
  }

  py::dict out;
  out["completed"] = result.completed;
  out["interrupted"] = result.interrupted;
  out["error"] = error;
  out["end_time_s"] = result.endTime;
  out["steps"] = result.steps;
  out["step_cutbacks"] = result.cutbacks;
  out["newton_iterations"] = result.newtonIterations;
  out["newton_iterations_on_parts"] = result.partIterations;
  out["matrix_refreshes"] = result.matrixRefreshes;
  out["block_refreshes"] = result.blockRefreshes;
  out["matrix_step_length_changes"] = result.matrixStepLengthChanges;
  out["fallback_steps"] = result.fallbackSteps;
  out["unload_rejections"] = result.unloadRejections;
  out["converged_blocks_left_out"] = result.blocksLeft;
  out["wall_time_s"] = result.wallSeconds;
  out["message"] = result.message;
  // The lines that parted (lines[].failure), as dynamics/summary.json's line_failures (time None: before the
  // statics).
  py::list failures;
  if (const analysis::LineFailure* failure = m_sim->lineFailure()) {
    for (const analysis::LineBreak& b : failure->breaks()) {
      py::dict f;
      f["line"] = m.lines()[static_cast<std::size_t>(b.line)].name;
      f["time_s"] = std::isfinite(b.time) ? py::object(py::float_(b.time)) : py::object(py::none());
      f["trigger"] = b.trigger;
      f["value"] = b.value;
      f["threshold"] = b.threshold;
      f["parted_from_m"] = b.arcFrom;
      f["parted_to_m"] = b.arcTo;
      f["message"] = b.description;
      failures.append(f);
    }
  }
  out["line_failures"] = failures;
  seabedImpacts.finish();
  py::list impacts;
  for (const analysis::SeabedImpact& e : seabedImpacts.events()) {
    py::dict d;
    d["line"] = m.lines()[static_cast<std::size_t>(e.line)].name;
    d["kind"] = e.impact ? "impact" : "contact";
    d["start_time_s"] = e.startTime;
    d["end_time_s"] = e.endTime;
    d["arc_length_m"] = e.arcLength;
    d["position_m"] = py::make_tuple(e.position.x(), e.position.y(), e.position.z());
    d["impact_velocity_m_s"] = e.impactVelocity;
    // None as the CSV's empty cell: not an impact, or an impact whose Eq. 5 mass was not measurable.
    d["impact_energy_J"] = e.impact && !std::isnan(e.impactEnergy) ? py::object(py::float_(e.impactEnergy))
                                                                   : py::object(py::none());
    d["eq5_mass_kg"] = std::isnan(e.eq5Mass) ? py::object(py::none()) : py::object(py::float_(e.eq5Mass));
    d["impact_phase_end_s"] = e.phaseEndTime;
    d["impact_phase_work_J"] = e.phaseWork;
    d["peak_force_N"] = e.peakForce;
    d["impulse_Ns"] = e.impulse;
    d["open_at_end"] = e.open;
    impacts.append(d);
  }
  out["seabed_impacts"] = impacts;
  // Contacts with vessels' hulls (vessel::HullImpacts), as dynamics/hull_impacts.csv.
  py::list hullImpacts;
  if (const vessel::HullContact* hulls = m_sim->hullContact()) {
    const auto optional = [](double v) {
      return std::isfinite(v) ? py::object(py::float_(v)) : py::object(py::none());
    };
    for (const vessel::HullImpact& e : hulls->impacts().events()) {
      py::dict d;
      d["body_a"] = e.bodyA;
      d["body_b"] = e.bodyB;
      d["kind"] = e.impact ? (e.lineOnHull ? "line_impact" : "hull_impact")
                           : (e.lineOnHull ? "line_contact" : "hull_contact");
      d["start_time_s"] = e.startTime;
      d["end_time_s"] = e.endTime;
      d["position_m"] = py::make_tuple(e.position.x(), e.position.y(), e.position.z());
      d["impact_velocity_m_s"] = e.impactVelocity;
      d["rebound_velocity_m_s"] = optional(e.reboundVelocity);
      d["peak_force_N"] = e.peakForce;
      d["impulse_Ns"] = e.impulse;
      d["max_penetration_m"] = e.maxPenetration;
      d["bodies_effective_mass_kg"] = optional(e.bodiesMass);
      d["eq5_mass_kg"] = optional(e.eq5Mass);
      d["impact_energy_J"] = e.impact ? optional(e.impactEnergy) : py::object(py::none());
      d["open_at_end"] = e.open;
      hullImpacts.append(d);
    }
  }
  out["hull_impacts"] = hullImpacts;
  const auto nt = static_cast<py::ssize_t>(times.size());
  out["time_s"] = array(times, {nt});
  py::list lines;
  for (std::size_t l = 0; l < lineCount; ++l) {
    const model::Line& line = m.lines()[l];
    const auto n = static_cast<py::ssize_t>(line.nodeCount);
    const LineHistory& h = hist[l];
    py::dict d;
    d["name"] = line.name;
    d["arc_length_m"] = array(line.arcLength, {n});
    d["position_m"] = array(h.position, {nt, n, 3});
    d["effective_tension_N"] = array(h.tension, {nt, n});
    if (line.pipe) d["wall_tension_N"] = array(h.wallTension, {nt, n});
    d["bending_moment_Nm"] = array(h.moment, {nt, n});
    d["curvature_1_per_m"] = array(h.curvature, {nt, n});
    d["torque_Nm"] = array(h.torque, {nt, n});
    d["end_tension_N"] = array(h.endTension, {nt, 2});
    d["end_force_N"] = array(h.endForce, {nt, 2, 3});
    // Range graphs over every accepted step; means time-weighted (the initial state only: its values).
    const analysis::RangeGraphs::Range& r = ranges.ranges()[l];
    const auto mean = [&](const std::vector<double>& sum, const std::vector<double>& only) {
      std::vector<double> v(sum.size());
      for (std::size_t i = 0; i < v.size(); ++i) v[i] = ranges.mean(sum[i], only[i]);
      return array(v, {n});
    };
    py::dict range;
    range["effective_tension_min_N"] = array(r.tensionMin, {n});
    range["effective_tension_max_N"] = array(r.tensionMax, {n});
    range["effective_tension_mean_N"] = mean(r.tensionSum, r.tensionMin);
    if (!r.wallTensionSum.empty()) {
      range["wall_tension_min_N"] = array(r.wallTensionMin, {n});
      range["wall_tension_max_N"] = array(r.wallTensionMax, {n});
      range["wall_tension_mean_N"] = mean(r.wallTensionSum, r.wallTensionMin);
    }
    range["bending_moment_min_Nm"] = array(r.momentMin, {n});
    range["bending_moment_max_Nm"] = array(r.momentMax, {n});
    range["bending_moment_mean_Nm"] = mean(r.momentSum, r.momentMin);
    range["curvature_min_1_per_m"] = array(r.curvatureMin, {n});
    range["curvature_max_1_per_m"] = array(r.curvatureMax, {n});
    range["curvature_mean_1_per_m"] = mean(r.curvatureSum, r.curvatureMin);
    if (!r.seabedClearanceMin.empty()) range["seabed_clearance_min_m"] = array(r.seabedClearanceMin, {n});
    // Extremes over every accepted step and slack events, as dynamics/summary.json.
    d["end_a_max_tension_N"] = r.endTensionMaxA;
    d["end_a_min_tension_N"] = r.endTensionMinA;
    d["end_b_max_tension_N"] = r.endTensionMaxB;
    d["end_b_min_tension_N"] = r.endTensionMinB;
    d["slack_events"] = r.slackEvents;
    d["slack_time_s"] = r.slackTime;
    d["range"] = range;
    lines.append(d);
  }
  out["lines"] = lines;
  out["range_steps"] = ranges.stepCount();

  py::list vessels;
  for (int v = 0; v < static_cast<int>(m.vessels().size()); ++v) {
    std::vector<double> motion;
    const std::size_t stride = 6 * m.vessels().size();
    for (std::size_t t = 0; t < times.size(); ++t)
      for (std::size_t k = 0; k < 6; ++k)
        motion.push_back(vesselMotion[t * stride + 6 * static_cast<std::size_t>(v) + k]);
    py::dict d;
    d["name"] = m.vessels()[static_cast<std::size_t>(v)].name;
    d["motion"] = array(motion, {nt, 6});
    d["motion_columns"] = py::make_tuple("x_m", "y_m", "z_m", "rx_deg", "ry_deg", "rz_deg");
    vessels.append(d);
  }
  out["vessels"] = vessels;

  py::list events;
  if (m_sim->contact()) {
    for (const contact::ContactEvent& e : m_sim->contact()->events()) {
      py::dict d;
      d["line_1"] = m.lines()[static_cast<std::size_t>(e.lineA)].name;
      d["line_2"] = m.lines()[static_cast<std::size_t>(e.lineB)].name;
      d["kind"] = e.kind();
      d["start_time_s"] = e.startTime;
      d["end_time_s"] = e.endTime;
      d["arc_1_m"] = e.arcAStart;
      d["arc_2_m"] = e.arcBStart;
      d["position_m"] = vec3Array(e.positionStart);
      d["impact_velocity_m_per_s"] = e.impactVelocity;
      d["impact_energy_J"] = e.impactEnergy;
      d["peak_force_N"] = e.peakForce;
      d["peak_force_per_length_N_per_m"] = e.peakForcePerLength;
      d["impact_peak_force_N"] = e.impactPeakForce;
      d["mesh_impact_peak_force_N"] = e.meshImpactPeakForce;
      d["impulse_Ns"] = e.impulse;
      d["max_penetration_m"] = e.maxPenetration;
      d["effective_mass_1_kg"] = e.effectiveMassA;
      d["effective_mass_2_kg"] = e.effectiveMassB;
      d["energy_mass_kg"] = e.energyMass;
      d["energy_mass_basis"] = e.energyMassBasis;
      d["absorbed_energy_J"] = e.phaseWork;
      d["eq5_mass_kg"] = e.eq5Mass;
      d["work_mass_kg"] = e.workMass;
      d["event_eq5_mass_kg"] = e.eventEq5Mass;
      d["impact_phase_end_s"] = e.phaseEndTime;
      d["impact_phase_end"] = e.phaseEnd;
      d["mass_lower_bound_kg"] = e.massLowerBound;
      d["mass_upper_bound_kg"] = e.massUpperBound;
      d["energy_warning"] = e.energyWarning;
      d["mesh_mass_kg"] = e.meshMass;
      d["mesh_energy_J"] = e.meshEnergy;
      d["mesh_mass_basis"] = e.meshMassBasis;
      d["continuum_mass_kg"] = e.continuumMass;
      d["continuum_energy_J"] = e.continuumEnergy;
      d["continuum_length_1_m"] = e.continuumLengthA;
      d["continuum_length_2_m"] = e.continuumLengthB;
      d["continuum_note"] = e.continuumNote;
      d["impact"] = e.impact;
      d["sustained"] = e.sustained;
      d["open"] = e.open;
      events.append(d);
    }
  }
  out["contact_events"] = events;

  py::list clearance;
  if (envelope) {
    for (const contact::ClearanceEnvelope::Side& s : envelope->sides()) {
      const model::Line& line = m.lines()[static_cast<std::size_t>(s.line)];
      const auto n = static_cast<py::ssize_t>(line.nodeCount);
      py::dict d;
      d["line"] = line.name;
      d["other_line"] = m.lines()[static_cast<std::size_t>(s.other)].name;
      d["arc_length_m"] = array(line.arcLength, {n});
      d["static_clearance_m"] = array(s.staticClearance, {n});
      d["min_clearance_m"] = array(s.dynamicClearance, {n});
      d["time_of_min_s"] = array(s.timeOfMinimum, {n});
      clearance.append(d);
    }
  }
  out["clearance"] = clearance;
  return out;
}

}  // namespace tangle::python
