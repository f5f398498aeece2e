#pragma once
/// @file CaseSummary.hpp
/// One row of a batch's summary table, read from the results folder of one case (summary.json,
/// dynamics/summary.json, contact/summary.json, clearance/summary.json, tangle-run.json).

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace tangle::app {

struct CaseSummary {
  std::string name;
  std::vector<std::string> parameterValues;
  std::string status;         ///< "completed", "completed (statics)", "failed: ...", "not run"
  int exitCode = -1;          ///< of `tangle run` (0 ok, 1 bad input, 2 no convergence, 3 other; -1 not run)
  double wallSeconds = 0.0;   ///< [s] of the run (of the earlier run when reused)
  bool reused = false;        ///< finished by an earlier batch run with the same model: not run again
  int rank = 0;               ///< MPI rank that ran the case (0 without MPI)
  bool staticsConverged = false;
  std::vector<std::pair<std::string, double>> maxTension;  ///< per line: largest effective tension [N]
  double minClearance = 0.0;  ///< smallest clearance over the checked pairs [m] (NaN: none checked)
  int impacts = 0;            ///< contact events counted as impacts
  double maxContactForce = 0.0;  ///< largest contact force of any event [N]
  std::string message;        ///< the error (first "error:" line of the case log) when failed

  /// Round trip through text (how MPI ranks send rows to rank 0).
  std::string serialise() const;
  static CaseSummary deserialise(const std::string& text);
};

/// Reads the row of a finished case from its results folder. Missing files leave their fields at the
/// defaults (a case that failed in statics has no dynamics summary). `log` (may be empty) is searched
/// for the first "error:" line.
CaseSummary readCaseSummary(const std::filesystem::path& caseDir, const std::filesystem::path& log);

/// Writes the summary table (CSV, one row per case in plan order; the line columns are the union of the
/// cases' lines) and returns a short terminal table.
std::string writeSummaryTable(const std::filesystem::path& file, const std::vector<std::string>& parameterNames,
                              const std::vector<CaseSummary>& rows);

}  // namespace tangle::app
