#include "tangle/app/Commands.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <iostream>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/contact/ClashReport.hpp"
#include "tangle/core/Error.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/geometry/Rotation.hpp"
#include "tangle/io/DynamicRecorder.hpp"
#include "tangle/io/JsonWriter.hpp"
#include "tangle/io/ModelReader.hpp"
#include "tangle/io/ResultWriter.hpp"

namespace tangle::app {

namespace fs = std::filesystem;

namespace {

const char* endKindName(model::EndKind k) {
  switch (k) {
    case model::EndKind::Anchored: return "anchored";
    case model::EndKind::Fixed: return "fixed";
    case model::EndKind::Pinned: return "pinned";
    case model::EndKind::Free: return "free";
    case model::EndKind::Vessel: return "vessel";
  }
  return "?";
}

void printSummary(const model::Model& m) {
  const auto& env = m.environment();
  fmt::print("model: {}\n", m.spec().sourceFile);
  if (!m.spec().title.empty()) fmt::print("title: {}\n", m.spec().title);
  fmt::print("environment: water depth {:.1f} m, water density {:.1f} kg/m3, gravity {:.5f} m/s2\n", env.waterDepth,
             env.waterDensity, env.gravity);
  int beams = 0;
  for (const auto& el : m.elements()) beams += el.isBeam() ? 1 : 0;
  fmt::print("{} line(s), {} elements ({} beam, {} bar), {} nodes, {} DOFs ({} free)\n", m.lines().size(),
             m.elements().size(), beams, static_cast<int>(m.elements().size()) - beams, m.nodeCount(),
             m.dofs().fullDofCount(), m.dofs().equationCount());
  for (int i = 0; i < static_cast<int>(m.lines().size()); ++i) {
    const model::Line& line = m.lines()[i];
    double weight = 0.0;
    for (int e = 0; e < line.elementCount; ++e) {
      const auto& el = m.elements()[line.firstElement + e];
      weight += el.type->submergedWeight(env.waterDensity, env.gravity) * el.restLength;
    }
    fmt::print("  line '{}': length {:.2f} m, {} sections, {} elements, mass {:.1f} t, submerged weight {:.1f} kN, "
               "end A {}, end B {}\n",
               line.name, line.length, line.spec->sections.size(), line.elementCount, m.lineMass(i) / 1000.0,
               weight / 1000.0, endKindName(line.spec->endA.kind), endKindName(line.spec->endB.kind));
  }
  const auto& d = m.spec().dynamics;
  if (d.enabled)
    fmt::print("dynamics: {:.2f} s at dt = {:.4g} s, output every {:.4g} s\n", d.duration, d.timeStep,
               d.outputInterval);
}

void writeDynamicSummary(const fs::path& dir, const time::DynamicResult& r, const io::DynamicRecorder& rec,
                         const std::vector<solver::LineSnapshot>& lines) {
  std::ofstream out(dir / "dynamics" / "summary.json");
  io::JsonWriter j(out);
  j.beginObject();
  j.field("completed", r.completed);
  j.field("end_time_s", r.endTime);
  j.field("steps", r.steps);
  j.field("step_cutbacks", r.cutbacks);
  j.field("newton_iterations", static_cast<double>(r.newtonIterations));
  j.field("wall_time_s", r.wallSeconds);
  j.field("real_time_factor", r.endTime / std::max(r.wallSeconds, 1e-9));
  j.field("message", r.message);
  j.key("lines");
  j.beginArray();
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const auto& range = rec.ranges()[l];
    j.beginObject();
    j.field("name", lines[l].name);
    j.field("max_tension_N", *std::max_element(range.tensionMax.begin(), range.tensionMax.end()));
    j.field("min_tension_N", *std::min_element(range.tensionMin.begin(), range.tensionMin.end()));
    j.field("max_bending_moment_Nm", *std::max_element(range.momentMax.begin(), range.momentMax.end()));
    j.endObject();
  }
  j.endArray();
  j.endObject();
}

void makePlots(const fs::path& outDir, bool quiet) {
  const fs::path script = fs::path(TANGLE_PYTHON_DIR) / "tangle_plot.py";
  if (!fs::exists("/usr/bin/python3") || !fs::exists(script)) {
    if (!quiet) fmt::print("plots skipped: /usr/bin/python3 or {} not found\n", script.string());
    return;
  }
  const std::string cmd = fmt::format("/usr/bin/python3 '{}' '{}' > '{}' 2>&1", script.string(), outDir.string(),
                                      (outDir / "plots.log").string());
  if (std::system(cmd.c_str()) != 0) {
    std::cerr << fmt::format("warning: plotting failed, see {}\n", (outDir / "plots.log").string());
  } else if (!quiet) {
    fmt::print("plots written to {}\n", (outDir / "plots").string());
  }
}

}  // namespace

int runCheck(const CheckOptions& options) {
  model::Model m(io::readModelFile(options.modelPath));
  printSummary(m);
  fmt::print("model is valid\n");
  return 0;
}

int runAnalysis(const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  analysis::Simulation sim(io::readModelFile(options.modelPath));
  const model::Model& m = sim.model();
  fs::path outDir = options.outputDir;
  if (outDir.empty()) {
    const fs::path p(options.modelPath);
    outDir = p.parent_path() / (p.stem().string() + "_results");
  }
  fs::create_directories(outDir);
  if (!options.quiet) printSummary(m);

  const solver::StaticResult result = sim.solveStatics();
  for (const std::string& w : result.warnings) std::cerr << "warning: " << w << "\n";
  const auto lines = sim.snapshot();
  io::writeStaticSummary(outDir, m, result, lines);
  if (!result.converged) {
    std::cerr << "error: " << result.message << "\n";
    std::cerr << fmt::format("no static results were written; the solver status is in {}\n",
                             (outDir / "summary.json").string());
    return 2;
  }
  io::writeStaticLineTables(outDir, lines);
  if (!options.quiet) {
    fmt::print("{}\n", result.message);
    for (const auto& s : lines) {
      fmt::print("  line '{}': end A tension {:.1f} kN, end B tension {:.1f} kN, max bending moment {:.2f} kN m",
                 s.name, s.tension.front() / 1000.0, s.tension.back() / 1000.0,
                 *std::max_element(s.bendingMoment.begin(), s.bendingMoment.end()) / 1000.0);
      if (s.touchdownArcLength >= 0.0) fmt::print(", touchdown at {:.1f} m from end A", s.touchdownArcLength);
      fmt::print("\n");
    }
  }

  int code = 0;
  if (m.spec().dynamics.enabled && !options.staticsOnly) {
    io::DynamicRecorder recorder(outDir, lines, m.spec().output.vtk ? m.spec().output.vtkInterval : 0.0);
    std::unique_ptr<contact::ClashReport> clash;
    if (sim.contact()) clash = std::make_unique<contact::ClashReport>(m, *sim.contact());
    // Vessel motions: position of the reference point and rotation (roll, pitch, yaw as a rotation
    // vector relative to the initial heading) against time.
    std::ofstream vesselFile;
    if (!m.vessels().empty()) {
      vesselFile.open(outDir / "dynamics" / "vessels.csv");
      vesselFile << "time_s";
      for (const auto& v : m.vessels())
        vesselFile << fmt::format(",{0}_x_m,{0}_y_m,{0}_z_m,{0}_rx_deg,{0}_ry_deg,{0}_rz_deg", v.name);
      vesselFile << "\n";
    }
    const time::DynamicResult dyn = sim.runDynamics(
        [&](const model::State& s, const VecX&) {
          recorder.record(s.time, sim.snapshot(true));
          if (clash) clash->recordClearance(s);
          if (vesselFile.is_open()) {
            vesselFile << fmt::format("{:.4f}", s.time);
            for (int v = 0; v < static_cast<int>(m.vessels().size()); ++v) {
              const int node = m.vesselNode(v);
              const Vec3 r = geometry::logMap(s.triad[node] * m.vesselRotation(v).transpose()) * 180.0 / kPi;
              vesselFile << fmt::format(",{:.4f},{:.4f},{:.4f},{:.5f},{:.5f},{:.5f}", s.position[node].x(),
                                        s.position[node].y(), s.position[node].z(), r.x(), r.y(), r.z());
            }
            vesselFile << "\n";
            vesselFile.flush();
          }
        },
        !options.quiet);
    recorder.writeRanges();
    if (clash) {
      clash->write(outDir);
      if (!options.quiet) fmt::print("{}", clash->terminalSummary());
    }
    writeDynamicSummary(outDir, dyn, recorder, lines);
    if (!dyn.completed) {
      std::cerr << "error: " << dyn.message << "\n";
      std::cerr << fmt::format("results up to t = {:.4g} s are in {}\n", dyn.endTime, outDir.string());
      code = 2;
    } else if (!options.quiet) {
      fmt::print("{}\n", dyn.message);
    }
  }
  if (m.spec().output.plots && !options.noPlots) makePlots(outDir, options.quiet);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!options.quiet) fmt::print("results written to {} ({:.2f} s)\n", outDir.string(), seconds);
  return code;
}

}  // namespace tangle::app
