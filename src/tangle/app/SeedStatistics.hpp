#pragma once
/// @file SeedStatistics.hpp
/// The statistics of a batch over its seeds (`seeds` in the batch file, docs/batch.md): for every case and
/// every quantity of the summary table that is a maximum (per line the largest tension and the largest
/// end tensions, the vessels' largest offset, the largest contact force), the seeds' maxima, their mean
/// and standard deviation, and their Gumbel fit by the method of moments (docs/theory.md 13.4) with its
/// most probable maximum and the value at the batch's non-exceedance probability.

#include <filesystem>
#include <string>
#include <vector>

#include "tangle/app/BatchPlan.hpp"
#include "tangle/app/CaseSummary.hpp"

namespace tangle::app {

/// Writes summary_statistics.csv for a plan with seeds (rows in plan order, the seed the fastest parameter:
/// each run of `plan.seeds.size()` rows is one case) and returns a short terminal table. Only completed
/// seeds count; a case with fewer than two leaves the statistics empty.
std::string writeSeedStatistics(const std::filesystem::path& file, const BatchPlan& plan,
                                const std::vector<std::string>& lineNames, const std::vector<CaseSummary>& rows);

}  // namespace tangle::app
