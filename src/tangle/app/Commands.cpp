#include "tangle/app/Commands.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <utility>

#include "tangle/analysis/MemoryEstimate.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/contact/ClearanceEnvelope.hpp"
#include "tangle/contact/LineContact.hpp"
#include "tangle/contact/StartShapeCrossings.hpp"
#include "tangle/core/Error.hpp"
#include "tangle/io/HtmlReport.hpp"
#include "tangle/io/ModelReader.hpp"
#include "tangle/io/MoorDynConversion.hpp"
#include "tangle/io/OutputFolder.hpp"
#include "tangle/results/RunLog.hpp"
#include "tangle/results/RunOutputs.hpp"
#include "tangle/results/RunText.hpp"

namespace tangle::app {

namespace fs = std::filesystem;

/// The memory estimate of a run of `sim` against what the machine has: (report, refusal); the refusal is
/// empty when the run fits (or the available memory is unknown).
std::pair<std::string, std::string> memoryCheck(analysis::Simulation& sim, const std::string& modelPath,
                                                double availableMb) {
  const analysis::MemoryEstimate estimate = analysis::estimateMemory(sim);
  const double available = availableMb > 0.0 ? availableMb * 1e6 : analysis::availableMemory();
  std::string report = fmt::format("memory: a run needs about {:.0f} MB{}\n{}", estimate.total() / 1e6,
                                   std::isfinite(available) ? fmt::format(" ({:.0f} MB available)", available / 1e6) : "",
                                   estimate.text());
  if (!(estimate.total() > available)) return {report, {}};
  return {report,
          fmt::format("{}: a run of this model needs about {:.0f} MB and the machine has {:.0f} MB available; the "
                      "largest needs:\n{}Remedies: fewer, longer elements; contact only between the lines that can "
                      "touch (contact.pairs); fewer line pairs in the clearance check; or a larger machine",
                      modelPath, estimate.total() / 1e6, available / 1e6, estimate.text())};
}

int runCheck(const CheckOptions& options) {
  analysis::Simulation sim(io::readModelFile(options.modelPath));
  const model::Model& m = sim.model();
  fmt::print("{}", results::modelSummary(m));
  std::cerr << results::warningText(m.spec());
  // The start shapes a run would lay one over the other before its statics (on a copy: check solves nothing).
  if (const contact::LineContact* contact = sim.contact()) {
    model::State start = sim.state();
    for (const contact::StartShapeLift& lift : contact::liftCrossedStartShapes(m, *contact, start))
      fmt::print("{}\n", lift.describe(m));
  }
  const auto [report, refusal] = memoryCheck(sim, options.modelPath, options.memoryAvailableMb);
  fmt::print("{}", report);
  if (!refusal.empty()) {
    std::cerr << "error: " << refusal << "\n";
    return 1;
  }
  fmt::print("model is valid{}\n",
             m.spec().warnings.empty() ? "" : fmt::format(" ({} warning(s))", m.spec().warnings.size()));
  return 0;
}

int runReport(const ReportOptions& options) {
  const fs::path dir(options.resultsDir);
  io::HtmlReport::rebuildPage(dir);
  fmt::print("report written to {}\n", (dir / "report.html").string());
  return 0;
}

int runView(const ViewOptions& options) {
  analysis::Simulation sim(io::readModelFile(options.modelPath));
  const model::Model& m = sim.model();
  std::cerr << results::warningText(m.spec());
  fs::path page = options.output;
  if (page.empty()) {
    const fs::path p(options.modelPath);
    page = p.parent_path() / (p.stem().string() + "_view.html");
  }
  io::HtmlReport report(m, "view", results::modelSummary(m));
  std::unique_ptr<contact::ClearanceEnvelope> envelope = std::make_unique<contact::ClearanceEnvelope>(
      m, sim.contact() ? sim.contact()->assessedPairs(sim.state()) : std::vector<std::array<int, 2>>{});
  if (envelope->empty()) envelope.reset();
  report.setStatics(sim.snapshot(), sim.state(), nullptr, envelope.get());
  report.setStatus("model before analysis (initial shapes)");
  io::HtmlReport::writePage(report.json(), "", page);
  fmt::print("view written to {}\n", page.string());
  return 0;
}

int runConvert(const ConvertOptions& options) {
  const io::MoorDynConversion conversion = io::convertMoorDynDeck(io::readMoorDynDeck(options.deckPath));
  fs::path out = options.output;
  if (out.empty()) {
    const fs::path p(options.deckPath);
    out = p.parent_path() / (p.stem().string() + ".yaml");
  }
  if (fs::exists(out) && !options.overwrite)
    throw InputError(out.string(), 0, "", "the output file exists: give --overwrite to replace it");
  // The model is read back before it is written: what convert writes is a model tangle runs.
  const model::ModelSpec spec = io::readModelString(conversion.yaml, out.string());
  analysis::Simulation check(spec);
  std::ofstream file(out, std::ios::binary);
  file << conversion.yaml;
  file.close();
  if (!file) throw OutputError(fmt::format("{}: cannot write the converted model", out.string()));
  for (const std::string& note : conversion.notes) std::cerr << "note: " << note << "\n";
  fmt::print("{}: {} line(s), {} point(s) of the MoorDyn deck -> {} tangle line(s); model written to {}\n",
             options.deckPath, conversion.lines.size(), conversion.points.size(), check.model().lines().size(),
             out.string());
  return 0;
}

int runAnalysis(const RunOptions& options) {
  analysis::Simulation sim(io::readModelFile(options.modelPath));
  // A run the machine cannot hold is refused before it starts (it ended in std::bad_alloc midway).
  if (const std::string refusal = memoryCheck(sim, options.modelPath, options.memoryAvailableMb).second; !refusal.empty()) {
    std::cerr << "error: " << refusal << "\n";
    return 1;
  }
  fs::path outDir = options.outputDir;
  if (outDir.empty()) {
    const fs::path p(options.modelPath);
    outDir = p.parent_path() / (p.stem().string() + "_results");
  }
  io::OutputFolder folder(outDir, options.modelPath, options.overwrite);
  results::RunLog log(options.quiet);
  log.open(outDir / "run.log");
  log.info(fmt::format("tangle {}\n", TANGLE_VERSION));
  results::RunOutputOptions outputOptions;
  outputOptions.staticsOnly = options.staticsOnly;
  outputOptions.noReport = options.noReport;
  outputOptions.noPlots = options.noPlots;
  outputOptions.progress = !options.quiet;
  outputOptions.plotScript = fs::path(TANGLE_PYTHON_DIR) / "tangle_plot.py";
  const int code = results::RunOutputs(sim, folder, log, outputOptions).run();
  log.close();
  return code;
}

}  // namespace tangle::app
