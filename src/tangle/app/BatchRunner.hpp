#pragma once
/// @file BatchRunner.hpp
/// `tangle batch`: runs the cases of a batch file (BatchPlan.hpp), each as its own `tangle run` process,
/// so a case that fails or crashes never stops the others.
///
/// - On one machine: up to `jobs` cases at a time (default: one per core).
/// - Under `mpirun -np N tangle batch ...` (built with MPI): rank 0 hands out cases one at a time to
///   whichever rank asks (dynamic load balancing: a rank that finishes a short case takes the next one)
///   and runs cases itself between requests; every rank runs `jobs` cases at a time (default 1). The
///   output folder must be on a file system every rank sees (as on any cluster's shared home or scratch).
///
/// Output folder: models/<case>.yaml (the model of each case), cases/<case>/ (the results of
/// `tangle run`), logs/<case>.log (its terminal output), logs/<case>.row (its summary row),
/// summary.csv (one row per case, docs/batch.md). A rerun skips every case whose results folder says
/// "completed" for the same model text, and runs the others again.

#include <string>

namespace tangle::app {

struct BatchOptions {
  std::string batchPath;
  std::string outputDir;  ///< empty: <batch name>_results beside the batch file
  int jobs = 0;           ///< cases at a time per process (0: cores without MPI, 1 per rank with MPI)
  bool plots = false;     ///< PNG plots for every case (off: they cost more than small runs)
  bool reports = true;    ///< report.html for every case (1-4 MB each)
  bool quiet = false;
};

/// Runs the batch. @return 0 when every case completed, 2 when any failed (the others still ran).
/// @throws InputError for a bad batch file (nothing is run)
int runBatch(const BatchOptions& options);

}  // namespace tangle::app
