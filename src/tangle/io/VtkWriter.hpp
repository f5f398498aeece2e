#pragma once
/// @file VtkWriter.hpp
/// ParaView output: VTK XML UnstructuredGrid files (.vtu, ASCII) holding lines as poly-line cells or
/// contact points as vertex cells, and the .pvd "Collection" file that strings them into a time series.
///
/// Self-contained: it knows nothing of the model classes; callers convert their results into
/// VtkPolyline / point lists. All quantities are written as given (SI units: m, N, N m, s); the
/// unit is carried by the field name (e.g. "tension_N"). Every .vtu also holds the field-data array
/// "TimeValue" [s], which ParaView uses when a single file is opened on its own.

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "tangle/core/Types.hpp"

namespace tangle::io {

/// A named per-point scalar field, e.g. {"tension_N", {...one value per point...}}.
using VtkScalarField = std::pair<std::string, std::vector<double>>;

/// One line (mooring line, riser) as an ordered chain of points.
struct VtkPolyline {
  std::string name;          ///< line name (listed in an XML comment; VTK has no string cell data)
  std::vector<Vec3> points;  ///< node positions [m], in order along the line
  std::vector<VtkScalarField> pointScalars;  ///< per-point fields, each with points.size() values
};

/// Writes one VTK XML UnstructuredGrid (.vtu, ASCII) holding each polyline as one VTK_POLY_LINE cell
/// (type 4), in the order given.
///
/// Point data: every scalar field that appears on any line (Float64, in order of first appearance),
/// plus "line_id" (Int32, index of the line in `lines`) and "arc_index" (Int32, index of the point
/// along its line, 0 at the first point). A field missing on a line is written as 0 for that line's
/// points. Cell data: "line_id". Field data: "TimeValue" = `time` [s].
/// Numbers are written with 9 significant digits (coordinates and time with 12). Non-finite values are
/// written as "nan", "inf", "-inf" (VTK 9.1's reader loads nan and inf, but reads -inf as +inf).
/// Parent directories are created. The file is written to a temporary name and renamed, so a reader
/// never sees a half-written file.
///
/// Throws tangle::Error when a line has no points, a field's length differs from its line's point
/// count, a field name is empty, repeated on one line or reserved ("line_id", "arc_index"), or on
/// any I/O failure (message names the file).
void writeVtu(const std::filesystem::path& file, const std::vector<VtkPolyline>& lines, double time);

/// Writes one VTK XML UnstructuredGrid (.vtu, ASCII) holding each point as one VTK_VERTEX cell
/// (type 1), e.g. the contact points of a clash report, to be shown with ParaView's Glyph filter.
///
/// Point data: every field of `scalars` (Float64, each with points.size() values) plus "point_id"
/// (Int32, index in `points`). Field data: "TimeValue" = `time` [s]. An empty `points` gives a valid
/// empty grid (no contact at this time). Same number format, atomic write and errors as writeVtu
/// (the reserved name here is "point_id").
void writeVtuPoints(const std::filesystem::path& file, const std::vector<Vec3>& points,
                    const std::vector<VtkScalarField>& scalars, double time);

/// Collects a time series of .vtu files and keeps the ParaView .pvd collection file that lists them.
///
/// The .vtu files go to `<pvd parent>/<pvd stem>_vtu/<pvd stem>_NNNNNN.vtu` (NNNNNN = step index from
/// 0) and are listed in the .pvd with paths relative to the .pvd file, so the output directory can be
/// moved. The .pvd is valid XML after every step (the closing tags are rewritten after each entry),
/// so an interrupted run still opens in ParaView with every step written so far.
///
/// Usage:
///   PvdSeries series(dir / "lines.pvd");
///   for (...) series.addStep(t, lines);
///   series.close();
class PvdSeries {
 public:
  /// Creates the .vtu directory and writes an empty (valid) collection to `pvdFile`, replacing any
  /// previous one. Throws tangle::Error when the directory or file cannot be written.
  explicit PvdSeries(std::filesystem::path pvdFile);
  ~PvdSeries();
  PvdSeries(const PvdSeries&) = delete;
  PvdSeries& operator=(const PvdSeries&) = delete;
  PvdSeries(PvdSeries&&) noexcept;
  PvdSeries& operator=(PvdSeries&&) noexcept;

  /// Writes the lines at time `time` [s] as the next .vtu (see writeVtu), appends it to the .pvd and
  /// returns the path of the .vtu written. Throws tangle::Error on bad input, I/O failure, a
  /// non-finite time or after close().
  std::filesystem::path addStep(double time, const std::vector<VtkPolyline>& lines);

  /// Same as addStep, for a point set (see writeVtuPoints), e.g. a series of contact points. Do not
  /// mix line steps and point steps in one series.
  std::filesystem::path addPointStep(double time, const std::vector<Vec3>& points,
                                     const std::vector<VtkScalarField>& scalars);

  /// Flushes and closes the .pvd. Further addStep calls throw. Called by the destructor (which
  /// swallows errors); call it explicitly to see I/O errors. Idempotent.
  void close();

  /// Path of the .pvd file.
  const std::filesystem::path& pvdFile() const { return m_pvdFile; }
  /// Directory the .vtu files are written to.
  const std::filesystem::path& vtuDirectory() const { return m_vtuDir; }
  /// Number of steps written so far.
  std::size_t stepCount() const { return m_steps; }

 private:
  std::filesystem::path nextVtuPath(double time) const;
  void appendEntry(double time, const std::filesystem::path& vtu);

  std::filesystem::path m_pvdFile;
  std::filesystem::path m_vtuDir;
  std::fstream m_pvd;
  std::streampos m_footerPos{};  // where the closing tags start; the next entry overwrites them
  std::size_t m_steps = 0;
  bool m_open = false;
};

}  // namespace tangle::io
