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
  /// Per line, the same numbers as the case's own summary (dynamics/summary.json over every accepted step,
  /// else the statics' summary.json); NaN where the case has none.
  struct LineRow {
    std::string name;
    double maxTension = 0.0;   ///< largest effective tension along the line, ends included [N]
    double minTension = 0.0;   ///< smallest [N]
    double endAMax = 0.0;      ///< largest end tension at end A [N]
    double endBMax = 0.0;      ///< at end B [N]
    double slackEvents = 0.0;  ///< slack (snap) events of the dynamics (NaN for statics)
  };
  std::vector<LineRow> lines;
  double maxOffset = 0.0;     ///< largest horizontal vessel offset over the dynamics [m] (NaN: no vessel/dynamics)
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

/// Writes the summary table (CSV, one row per case in plan order) and returns a short terminal table. The
/// columns are fixed by the batch, not by what the cases gave: per line of `lineNames` (the lines of the
/// cases' models) `<line>_max_tension_N`, `_min_tension_N`, `_end_a_max_tension_N`, `_end_b_max_tension_N`,
/// `_slack_events`, then `max_offset_m`; a failed case leaves its cells empty.
std::string writeSummaryTable(const std::filesystem::path& file, const std::vector<std::string>& parameterNames,
                              const std::vector<std::string>& lineNames, const std::vector<CaseSummary>& rows);

}  // namespace tangle::app
