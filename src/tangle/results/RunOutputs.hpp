#pragma once
/// @file RunOutputs.hpp
/// A run's outputs in one place: the static results, every step, every output time, the writer thread and
/// its step batches, and the files that close the run. The command line (`tangle run`) and the Python module
/// (`Model.run(folder)`) are short callers of it; later outputs (statistics, fatigue, audits) plug in here.
///
/// The life of a run (docs/architecture.md):
///  1. statics: Simulation::solveStatics, the equilibrium audit, summary.json, statics/*.csv, results.h5
///     /statics, the static contact report, the report's static page (a failed solve still writes
///     summary.json and a report page of where it stopped, then ends the run with exit code 2);
///  2. dynamics (when the model has them and the caller wants them): Simulation::runDynamics with a step
///     observer (every accepted step: a batch of positions for the writer thread, which accumulates the range
///     graphs, the clearance envelope and tensioner rows; vessel offsets; the energy account) and an output
///     observer (CSV rows, results.h5, vessels.csv on the writer thread; the report's frames);
///  3. finish: range graphs, clash report, dynamics/summary.json, clearance envelope, results.h5 closed on a
///     second thread while the report is written, plots, the folder's status.
/// A run that fails midway keeps every result already written.

#include <array>
#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/OutputFolder.hpp"
#include "tangle/results/RunLog.hpp"
#include "tangle/solver/ForceBalance.hpp"
#include "tangle/solver/LineResults.hpp"

namespace tangle::io {
class Hdf5Results;
class HtmlReport;
}  // namespace tangle::io
namespace tangle::contact {
class ClearanceEnvelope;
}  // namespace tangle::contact

namespace tangle::results {

/// What a run writes besides what the model asks for.
struct RunOutputOptions {
  bool staticsOnly = false;  ///< stop after the statics even if the model has dynamics
  bool noReport = false;     ///< no report.html
  bool noPlots = false;      ///< no plots (output.plots of the model otherwise)
  bool progress = true;      ///< progress lines of the dynamics on stderr
  /// The plotting script (python/tangle_plot.py); empty: no plots.
  std::filesystem::path plotScript;
  /// Asked before every step; true stops the dynamics there, as Ctrl-C does (the Python module's check of
  /// Python's signals). Empty: none.
  std::function<bool()> stop;
};

/// Runs a Simulation into an output folder and writes everything the run produces.
class RunOutputs {
 public:
  RunOutputs(analysis::Simulation& simulation, io::OutputFolder& folder, RunLog& log,
             RunOutputOptions options);
  ~RunOutputs();
  RunOutputs(const RunOutputs&) = delete;
  RunOutputs& operator=(const RunOutputs&) = delete;

  /// The whole run: statics, dynamics, finish. Returns the exit code: 0, or 2 when the statics did not
  /// converge or the dynamics stopped early (the folder's status and the log say which).
  /// @throws OutputError on a failed write, InputError on bad input found while running (recorded first in
  ///         the run log and as the folder's status "failed: ...")
  int run();

 private:
  /// Step 1 above; false when the statics did not converge (what could be written is).
  bool writeStatics();
  /// Step 2 above; false when the dynamics stopped early.
  bool runDynamics();
  /// Step 3 above.
  void finish(bool ok);
  /// Runs `work` and adds its duration to the report's collection time (the run log states what the report
  /// cost).
  template <class Work>
  void timed(Work&& work);

  analysis::Simulation* m_sim;
  io::OutputFolder* m_folder;
  RunLog* m_log;
  RunOutputOptions m_options;
  std::chrono::steady_clock::time_point m_start;
  std::vector<solver::LineSnapshot> m_static;  ///< the static solution's lines
  bool m_csv = true, m_hdf5 = true;            ///< output.format resolved (ResultFiles)
  std::unique_ptr<io::Hdf5Results> m_h5;
  std::unique_ptr<contact::ClearanceEnvelope> m_envelope;
  std::vector<std::array<int, 2>> m_assessedPairs;  // LineContact::assessedPairs at the static equilibrium
  std::unique_ptr<io::HtmlReport> m_report;
  std::chrono::steady_clock::duration m_reportTime{};
};

}  // namespace tangle::results
