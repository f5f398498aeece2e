#pragma once
/// @file Commands.hpp
/// The CLI subcommands. Each returns the process exit code (see main.cpp).

#include <string>

namespace tangle::app {

/// Options of `tangle check`.
struct CheckOptions {
  std::string modelPath;
  double memoryAvailableMb = 0.0;  ///< [MB]; 0: what the machine has available
};

/// Options of `tangle run`.
struct RunOptions {
  std::string modelPath;
  std::string outputDir;  ///< empty: <model stem>_results beside the model file
  bool staticsOnly = false;
  double memoryAvailableMb = 0.0;  ///< [MB]; 0: what the machine has available (refusal above it)
  bool noPlots = false;
  bool quiet = false;
  bool overwrite = false;  ///< clear an output folder of an earlier tangle run instead of refusing it
  bool noReport = false;   ///< do not write report.html
};

/// Options of `tangle report`.
struct ReportOptions {
  std::string resultsDir;
};

/// Options of `tangle view`.
struct ViewOptions {
  std::string modelPath;
  std::string output;  ///< page to write; empty: <model stem>_view.html beside the model file
};

/// Options of `tangle convert`.
struct ConvertOptions {
  std::string deckPath;
  std::string output;      ///< model file to write; empty: <deck stem>.yaml beside the deck
  bool overwrite = false;  ///< replace an existing output file
};

/// Validates a model and prints a summary (lines, elements, DOFs, masses, lengths).
int runCheck(const CheckOptions& options);
/// Runs the analysis and writes results.
int runAnalysis(const RunOptions& options);
/// Rebuilds report.html of a results folder from its report data and run log.
int runReport(const ReportOptions& options);
/// Writes the report page of a model before any analysis (initial shapes, vessels, environment).
int runView(const ViewOptions& options);
/// Converts a MoorDyn v2 input file into a tangle model file (docs/moordyn.md), checked by the model reader.
int runConvert(const ConvertOptions& options);

}  // namespace tangle::app
