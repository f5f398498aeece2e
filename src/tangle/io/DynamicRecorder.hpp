#pragma once
/// @file DynamicRecorder.hpp
/// Records a dynamic run as it goes, so that a run stopped midway keeps everything up to then:
/// - `dynamics/<line>/<quantity>.csv`: time histories, one row per output time, one column per node
///   (x_m, y_m, z_m, effective_tension_N, bending_moment_Nm, curvature_1_per_m, bending moment
///   components bending_moment_{x,y,z}_Nm in global axes, torque_Nm; a cable line has no moments or
///   torque and no files for them);
/// - `dynamics/<line>/range.csv`: range graphs (min, max, time-weighted mean) along each line over every
///   accepted time step (accumulate()), not only the output times: a short impact between two output
///   times is in the range graph and the extremes;
/// - `dynamics/end_forces.csv`: end tension (at the end point, LineSnapshot::endTensionA) and the force
///   components on what holds each end, against time;
/// - `vtk/lines.pvd` + `vtk/lines_vtu/*.vtu`: ParaView series of the lines with per-node fields.
/// <line> is the line's unique file stem (io::lineFileStems). Every write is checked (OutputError).

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "tangle/analysis/RangeGraphs.hpp"
#include "tangle/core/OutputFile.hpp"
#include "tangle/io/VtkWriter.hpp"
#include "tangle/model/ModelSpec.hpp"
#include "tangle/solver/LineResults.hpp"

namespace tangle::io {

/// Streams dynamic results to disk.
class DynamicRecorder {
 public:
  /// @param dir output directory; @param initial the lines at t = 0 (names, arc lengths)
  /// @param vtkInterval time between ParaView frames [s] (<= 0: no ParaView output)
  /// @param timeHistories the dynamics/<line>/<quantity>.csv written (none: results.h5 holds them, or the
  ///        model asked for none; the range graphs and end_forces.csv are written either way)
  DynamicRecorder(const std::filesystem::path& dir, const std::vector<solver::LineSnapshot>& initial,
                  double vtkInterval, const model::TimeHistorySelection& timeHistories = {});
  ~DynamicRecorder();
  DynamicRecorder(const DynamicRecorder&) = delete;
  DynamicRecorder& operator=(const DynamicRecorder&) = delete;

  /// Appends one output time to the time histories (flushed to disk at once). May run on another thread
  /// than accumulate() (the run command's background writer): the two share no member.
  void record(double time, const std::vector<solver::LineSnapshot>& lines);
  /// See analysis::RangeGraphs::setSeabed (slack events count suspended nodes only).
  void setSeabed(analysis::RangeGraphs::SeabedNodes seabed) { m_ranges.setSeabed(std::move(seabed)); }
  /// Adds one accepted step (of length dt [s]; dt = 0 for the initial state) to the ranges and extremes
  /// (analysis::RangeGraphs::accumulate).
  void accumulate(const std::vector<solver::LineSnapshot>& lines, double dt) { m_ranges.accumulate(lines, dt); }
  /// Writes the range graphs of what was accumulated so far (call at the end, also after a failure).
  void writeRanges() const;
  /// Flushes and closes every time history (call at the end; errors throw OutputError).
  void close();
  /// Number of output records so far.
  int recordCount() const { return m_records; }
  /// Number of accumulated states (initial state + accepted steps).
  long stepCount() const { return m_ranges.stepCount(); }
  /// Time the means are weighted over [s] (0: only the initial state; then the means are its values).
  double meanWeight() const { return m_ranges.meanWeight(); }
  /// The range graphs, extremes and slack events of every line so far.
  const analysis::RangeGraphs& rangeGraphs() const { return m_ranges; }
  const std::vector<analysis::RangeGraphs::Range>& ranges() const { return m_ranges.ranges(); }

 private:
  std::filesystem::path m_dir;
  std::vector<std::string> m_stems;
  std::vector<std::vector<double>> m_arc;
  std::vector<int> m_quantities;  // the quantities written (indices of the CSV quantities)
  std::vector<std::vector<int>> m_lineQuantities;  // per line: those it has (a cable line no moments)
  std::vector<char> m_hasBending;                  // per line: LineSnapshot::hasBending
  std::vector<std::vector<std::unique_ptr<core::OutputFile>>> m_streams;  // per line, per written quantity
  std::unique_ptr<core::OutputFile> m_endForces;
  std::unique_ptr<PvdSeries> m_vtk;
  double m_vtkInterval;
  double m_nextVtk = 0.0;
  analysis::RangeGraphs m_ranges;
  int m_records = 0;
};

/// The lines of a snapshot as VTK polylines with tension, bending moment, torque and curvature fields.
std::vector<VtkPolyline> toPolylines(const std::vector<solver::LineSnapshot>& lines);

}  // namespace tangle::io
