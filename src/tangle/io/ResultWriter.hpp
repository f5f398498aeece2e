#pragma once
/// @file ResultWriter.hpp
/// Writes results: per-line CSV tables (header row names each quantity and its unit) and a
/// machine-readable JSON summary.

#include <filesystem>
#include <string>
#include <vector>

#include "tangle/model/Model.hpp"
#include "tangle/solver/ForceBalance.hpp"
#include "tangle/solver/LineResults.hpp"
#include "tangle/solver/StaticSolver.hpp"

namespace tangle::io {

/// A file-system-safe version of a name: ASCII letters, digits, '-', '_' and '.' kept, every other byte
/// (separators, spaces, non-ASCII) becomes '_'; a leading '.' becomes '_' (no hidden files, no "..");
/// at most 64 characters; "line" for an empty name.
std::string safeFileName(const std::string& name);

/// File stems for a list of names, safe (safeFileName) and unique even on case-insensitive file
/// systems: a stem already taken gets "-2", "-3", ... (`riser/1` and `riser_1` give riser_1, riser_1-2).
/// The same names in the same order always give the same stems.
std::vector<std::string> uniqueFileStems(const std::vector<std::string>& names);

/// uniqueFileStems of the names of `lines`.
std::vector<std::string> lineFileStems(const std::vector<solver::LineSnapshot>& lines);

/// Writes `dir/statics/<line stem>.csv` for every line and returns the paths written.
/// @throws OutputError naming the file when a write fails
std::vector<std::filesystem::path> writeStaticLineTables(const std::filesystem::path& dir,
                                                         const std::vector<solver::LineSnapshot>& lines);

/// Writes `dir/summary.json`: solver outcome, and per line end tensions, end angles, touchdown point,
/// tension and bending-moment extremes. End tension: LineSnapshot::endTensionA/B (at the end point).
/// @throws OutputError naming the file when a write fails
/// With `audit`, also its balances (`equilibrium_audit`).
void writeStaticSummary(const std::filesystem::path& dir, const model::Model& model,
                        const solver::StaticResult& result, const std::vector<solver::LineSnapshot>& lines,
                        const solver::EquilibriumAudit* audit = nullptr);

/// Angle of a force from the horizontal plane [deg] (positive when the line pulls upward on the support).
double elevationAngleDeg(const Vec3& force);

}  // namespace tangle::io
