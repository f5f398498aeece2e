#pragma once
/// @file ResultWriter.hpp
/// Writes results: per-line CSV tables (header row names each quantity and its unit) and a
/// machine-readable JSON summary.

#include <filesystem>
#include <string>
#include <vector>

#include "tangle/model/Model.hpp"
#include "tangle/solver/LineResults.hpp"
#include "tangle/solver/StaticSolver.hpp"

namespace tangle::io {

/// A file-system-safe version of a name (letters, digits, '-', '_', '.').
std::string safeFileName(const std::string& name);

/// Writes `dir/statics/<line>.csv` for every line and returns the paths written.
std::vector<std::filesystem::path> writeStaticLineTables(const std::filesystem::path& dir,
                                                         const std::vector<solver::LineSnapshot>& lines);

/// Writes `dir/summary.json`: solver outcome, and per line end tensions, end angles, touchdown point,
/// tension and bending-moment extremes.
void writeStaticSummary(const std::filesystem::path& dir, const model::Model& model,
                        const solver::StaticResult& result, const std::vector<solver::LineSnapshot>& lines);

/// Angle of a force from the horizontal plane [deg] (positive when the line pulls upward on the support).
double elevationAngleDeg(const Vec3& force);

}  // namespace tangle::io
