/// @file main.cpp
/// The `tangle` command line.
///
/// Exit codes: 0 success; 1 bad input (model file or command line); 2 the analysis did not
/// converge (results computed until then are kept); 3 any other error (I/O, internal).

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <iostream>

#include "tangle/app/BatchRunner.hpp"
#include "tangle/app/Commands.hpp"
#include "tangle/core/Error.hpp"
#include "tangle/core/Interrupt.hpp"

int main(int argc, char** argv) {
  CLI::App app{"tangle: nonlinear static and dynamic analysis of offshore lines with line-to-line contact"};
  app.set_version_flag("--version", std::string("tangle ") + TANGLE_VERSION);
  app.require_subcommand(1);
  app.footer("Exit codes: 0 ok, 1 bad input, 2 analysis did not converge, 3 other error.");

  tangle::app::CheckOptions checkOptions;
  CLI::App* check = app.add_subcommand("check", "Validate a model file and print a summary of its mesh");
  check->add_option("model", checkOptions.modelPath, "Model file (YAML)")->required()->check(CLI::ExistingFile);
  check->add_option("--memory-available-mb", checkOptions.memoryAvailableMb,
                    "Memory the run may use [MB] (default: what the machine has available now; on a cluster, the "
                    "job's limit)")
      ->check(CLI::PositiveNumber);

  tangle::app::RunOptions runOptions;
  CLI::App* run = app.add_subcommand("run", "Run the analysis of a model (statics, then dynamics if requested)");
  run->add_option("model", runOptions.modelPath, "Model file (YAML, or a MoorDyn v2 input file)")->required()->check(CLI::ExistingFile);
  run->add_option("-o,--output", runOptions.outputDir, "Output directory (default: <model name>_results next to it)");
  run->add_flag("--statics-only", runOptions.staticsOnly, "Stop after the static analysis");
  run->add_option("--memory-available-mb", runOptions.memoryAvailableMb,
                  "Memory the run may use [MB]: a model estimated to need more is refused before it starts "
                  "(default: what the machine has available now)")
      ->check(CLI::PositiveNumber);
  run->add_flag("--no-plots", runOptions.noPlots, "Do not write PNG plots");
  run->add_flag("-q,--quiet", runOptions.quiet, "Print only errors");
  run->add_flag("--overwrite", runOptions.overwrite,
                "Replace the results of an earlier run in the output folder (refused without it)");
  run->add_flag("--no-report", runOptions.noReport, "Do not write report.html (the results report in the browser)");

  tangle::app::ReportOptions reportOptions;
  CLI::App* report =
      app.add_subcommand("report", "Write report.html of a results folder again (from report/data.json and run.log)");
  report->add_option("results", reportOptions.resultsDir, "Results folder of tangle run")
      ->required()
      ->check(CLI::ExistingDirectory);

  tangle::app::ViewOptions viewOptions;
  CLI::App* view = app.add_subcommand(
      "view", "Write the report page of a model before any analysis (initial shapes, vessels, current, waves)");
  view->add_option("model", viewOptions.modelPath, "Model file (YAML)")->required()->check(CLI::ExistingFile);
  view->add_option("-o,--output", viewOptions.output, "Page to write (default: <model name>_view.html next to it)");

  tangle::app::BatchOptions batchOptions;
  CLI::App* batch = app.add_subcommand(
      "batch", "Run the load cases of a batch file, in parallel processes (and across MPI ranks under mpirun)");
  batch->add_option("batch", batchOptions.batchPath, "Batch file (YAML, docs/batch.md)")->required()->check(CLI::ExistingFile);
  batch->add_option("-o,--output", batchOptions.outputDir, "Output directory (default: <batch name>_results next to it)");
  batch->add_option("-j,--jobs", batchOptions.jobs,
                    "Cases at a time per process (default: one per core; 1 per rank under mpirun)")
      ->check(CLI::Range(1, 1024));
  batch->add_flag("--plots", batchOptions.plots, "Write PNG plots for every case");
  bool noReports = false;
  batch->add_flag("--no-report", noReports, "Do not write report.html for every case");
  batch->add_flag("-q,--quiet", batchOptions.quiet, "Print only errors");

  tangle::app::ConvertOptions convertOptions;
  CLI::App* convert = app.add_subcommand(
      "convert", "Convert a MoorDyn v2 input file into a tangle model file (docs/moordyn.md)");
  convert->add_option("deck", convertOptions.deckPath, "MoorDyn input file")->required()->check(CLI::ExistingFile);
  convert->add_option("-o,--output", convertOptions.output, "Model file to write (default: <deck name>.yaml next to it)");
  convert->add_flag("--overwrite", convertOptions.overwrite, "Replace the output file if it exists");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 1;
  }
  try {
    if (*check) return tangle::app::runCheck(checkOptions);
    if (*report) return tangle::app::runReport(reportOptions);
    if (*view) return tangle::app::runView(viewOptions);
    if (*convert) return tangle::app::runConvert(convertOptions);
    if (*run) {
      // Ctrl-C ends the dynamics at the next step; every result so far (clash report included) is written.
      tangle::core::installInterruptHandler();
      return tangle::app::runAnalysis(runOptions);
    }
    if (*batch) {
      // Ctrl-C reaches the running cases too (same process group): they stop cleanly and keep their results;
      // no new case is started.
      tangle::core::installInterruptHandler();
      batchOptions.reports = !noReports;
      return tangle::app::runBatch(batchOptions);
    }
  } catch (const tangle::InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  } catch (const tangle::ConvergenceError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
