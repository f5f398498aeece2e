#include "tangle/app/Commands.hpp"

#include <chrono>
#include <filesystem>
#include <fmt/format.h>
#include <iostream>

#include "tangle/io/ModelReader.hpp"
#include "tangle/io/ResultWriter.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/solver/Assembler.hpp"
#include "tangle/solver/LineResults.hpp"
#include "tangle/solver/StaticSolver.hpp"

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
  model::Model m(io::readModelFile(options.modelPath));
  fs::path outDir = options.outputDir;
  if (outDir.empty()) {
    const fs::path p(options.modelPath);
    outDir = p.parent_path() / (p.stem().string() + "_results");
  }
  fs::create_directories(outDir);
  if (!options.quiet) printSummary(m);

  solver::Assembler assembler(m);
  model::State state = m.initialState();
  solver::StaticSolver statics(assembler, m.spec().statics);
  const solver::StaticResult result = statics.solve(state);
  VecX force;
  solver::AssemblyRequest request;
  request.wantMatrix = false;
  request.loadFactor = result.loadFraction;
  assembler.assemble(state, request, force, nullptr);
  const auto lines = solver::computeLineResults(m, assembler, state, force);
  io::writeStaticSummary(outDir, m, result, lines);
  if (!result.converged) {
    std::cerr << "error: " << result.message << "\n";
    std::cerr << fmt::format("no static results were written; the solver status is in {}\n",
                             (outDir / "summary.json").string());
    return 2;
  }
  io::writeStaticLineTables(outDir, lines);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!options.quiet) {
    fmt::print("{}\n", result.message);
    for (const auto& s : lines) {
      fmt::print("  line '{}': end A tension {:.1f} kN, end B tension {:.1f} kN, max bending moment {:.2f} kN m",
                 s.name, s.endForceA.norm() / 1000.0, s.endForceB.norm() / 1000.0,
                 *std::max_element(s.bendingMoment.begin(), s.bendingMoment.end()) / 1000.0);
      if (s.touchdownArcLength >= 0.0) fmt::print(", touchdown at {:.1f} m from end A", s.touchdownArcLength);
      fmt::print("\n");
    }
    fmt::print("results written to {} ({:.2f} s)\n", outDir.string(), seconds);
  }
  return 0;
}

}  // namespace tangle::app
