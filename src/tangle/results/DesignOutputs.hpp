#pragma once
/// @file DesignOutputs.hpp
/// The design answers of a dynamic run as files (docs/theory.md section 13): the extreme statistics of the
/// end tensions (dynamics/statistics.csv), the fatigue damage along the lines (fatigue/<line>.csv,
/// fatigue/summary.csv) and the clash damage along the lines (contact/clash_damage.csv). Each writer
/// returns the lines it adds to the run log.

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "tangle/analysis/ClashDamage.hpp"
#include "tangle/analysis/FatigueDamage.hpp"
#include "tangle/analysis/ResponseStatistics.hpp"
#include "tangle/solver/LineResults.hpp"

namespace tangle::results {

/// The extreme statistics of a run (theory 13.3) for a storm of `storm` [s]: dynamics/statistics.csv (per
/// line end: tension), dynamics/<line>/statistics.csv (per node: effective tension and bending moment),
/// dynamics/vessel_statistics.csv (horizontal offset of each vessel, `offsets` in the order of the model's
/// vessels; none without vessels) and contact/clearance_statistics.csv (the minimum clearance of each pair,
/// `clearance` per pair of `pairs`: the peaks of minus the clearance; none without pairs). Returns the log's
/// lines.
std::string writeExtremeStatistics(const std::filesystem::path& dir, const model::Model& model,
                                   const std::vector<solver::LineSnapshot>& lines,
                                   const analysis::ResponseStatistics& statistics,
                                   const std::vector<analysis::PeakTracker>& offsets,
                                   const std::vector<std::array<int, 2>>& pairs,
                                   const std::vector<analysis::PeakTracker>& clearance, double storm);

/// fatigue/<line>.csv (per node: arc length, line type, damage of the run and per year, life, cycles,
/// largest range, worst point) and fatigue/summary.csv (the shortest life of each line) of `damage`
/// (FatigueDamage::finish of `fatigue`).
std::string writeFatigue(const std::filesystem::path& dir, const model::Model& model,
                         const analysis::FatigueDamage& fatigue,
                         const std::vector<analysis::FatigueDamage::Line>& damage);

/// contact/clash_damage.csv: per line and bin, the impacts, those above the energy threshold, the
/// accumulated and largest energy and the largest impact velocity.
std::string writeClashDamage(const std::filesystem::path& dir, const model::Model& model,
                             const std::vector<analysis::LineClashDamage>& damage, double energyThreshold);

}  // namespace tangle::results
