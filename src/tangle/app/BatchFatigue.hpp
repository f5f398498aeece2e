#pragma once
/// @file BatchFatigue.hpp
/// Long-term fatigue of a batch (docs/batch.md): the cases are the sea states of a scatter diagram, each
/// with its `fatigue.occurrence`; their damages per year along every line add (Palmgren-Miner over the sea
/// states, DNV-RP-F204 (2017) 3.3). With seeds, the seeds of one case are realisations of one sea state:
/// their damages are averaged, not added. Written to fatigue_total/<line>.csv (arc length, damage per year,
/// life, the case with the largest share) and fatigue_total/summary.csv.

#include <filesystem>
#include <string>
#include <vector>

#include "tangle/app/BatchPlan.hpp"
#include "tangle/app/CaseSummary.hpp"

namespace tangle::app {

/// Sums the fatigue/<line>.csv of the completed cases in `caseDirs` (plan order) into `dir`/fatigue_total/.
/// A sea state counts when all its seeds completed (else it is named in the returned text and left out);
/// a line whose nodes differ between cases (another mesh) is left out with a note. Returns the terminal
/// text (empty when no case wrote fatigue results).
/// @throws OutputError on a failed write
std::string writeBatchFatigue(const std::filesystem::path& dir, const BatchPlan& plan,
                              const std::vector<std::filesystem::path>& caseDirs, const std::vector<CaseSummary>& rows);

}  // namespace tangle::app
