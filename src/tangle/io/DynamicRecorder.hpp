#pragma once
/// @file DynamicRecorder.hpp
/// Records a dynamic run as it goes, so that a run stopped midway keeps everything up to then:
/// - `dynamics/<line>/<quantity>.csv`: time histories, one row per output time, one column per node
///   (x_m, y_m, z_m, effective_tension_N, bending_moment_Nm, curvature_1_per_m);
/// - `dynamics/<line>/range.csv`: range graphs (min, max, mean over the run) along each line;
/// - `dynamics/end_forces.csv`: end tensions of every line against time;
/// - `vtk/lines.pvd` + `vtk/lines_vtu/*.vtu`: ParaView series of the lines with per-node fields.

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "tangle/io/VtkWriter.hpp"
#include "tangle/solver/LineResults.hpp"

namespace tangle::io {

/// Streams dynamic results to disk.
class DynamicRecorder {
 public:
  /// @param dir output directory; @param lineNames names of the lines in model order
  /// @param vtkInterval time between ParaView frames [s] (<= 0: no ParaView output)
  DynamicRecorder(const std::filesystem::path& dir, const std::vector<solver::LineSnapshot>& initial,
                  double vtkInterval);
  ~DynamicRecorder();
  DynamicRecorder(const DynamicRecorder&) = delete;
  DynamicRecorder& operator=(const DynamicRecorder&) = delete;

  /// Appends one output time (flushed to disk at once).
  void record(double time, const std::vector<solver::LineSnapshot>& lines);
  /// Writes the range graphs of what was recorded so far (call at the end, also after a failure).
  void writeRanges() const;
  /// Number of records so far.
  int recordCount() const { return m_records; }

  /// Min/max/mean accumulators of one line.
  struct Range {
    std::vector<double> tensionMin, tensionMax, tensionSum;
    std::vector<double> momentMin, momentMax, momentSum;
    std::vector<double> curvatureMin, curvatureMax, curvatureSum;
  };
  const std::vector<Range>& ranges() const { return m_ranges; }

 private:
  std::filesystem::path m_dir;
  std::vector<std::string> m_names;
  std::vector<std::vector<double>> m_arc;
  std::vector<std::vector<std::unique_ptr<std::ofstream>>> m_streams;  // per line, per quantity
  std::unique_ptr<std::ofstream> m_endForces;
  std::unique_ptr<PvdSeries> m_vtk;
  double m_vtkInterval;
  double m_nextVtk = 0.0;
  std::vector<Range> m_ranges;
  int m_records = 0;
};

/// The lines of a snapshot as VTK polylines with tension, bending moment and curvature fields.
std::vector<VtkPolyline> toPolylines(const std::vector<solver::LineSnapshot>& lines);

}  // namespace tangle::io
