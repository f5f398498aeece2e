#include "tangle/io/DynamicRecorder.hpp"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <string_view>

#include "tangle/core/Error.hpp"
#include "tangle/io/ResultWriter.hpp"

namespace tangle::io {

namespace fs = std::filesystem;

namespace {
const char* const kQuantities[] = {"x_m", "y_m", "z_m", "effective_tension_N", "bending_moment_Nm",
                                   "curvature_1_per_m", "bending_moment_x_Nm", "bending_moment_y_Nm",
                                   "bending_moment_z_Nm", "torque_Nm", "wall_tension_N"};
constexpr int kQuantityCount = 11;
constexpr int kWallTension = 10;  // pipe lines only

/// The bending moment, its components and the torque: results of beam elements only.
bool isBendingQuantity(int q) { return q == 4 || (q >= 6 && q <= 9); }

double quantity(const solver::LineSnapshot& s, int q, std::size_t i) {
  switch (q) {
    case 0: return s.position[i].x();
    case 1: return s.position[i].y();
    case 2: return s.position[i].z();
    case 3: return s.tension[i];
    case 4: return s.bendingMoment[i];
    case 5: return s.curvature[i];
    case 6: return s.bendingMomentVector[i].x();
    case 7: return s.bendingMomentVector[i].y();
    case 8: return s.bendingMomentVector[i].z();
    case 9: return s.torque[i];
    default: return s.wallTension[i];
  }
}
}  // namespace

std::vector<VtkPolyline> toPolylines(const std::vector<solver::LineSnapshot>& lines) {
  std::vector<VtkPolyline> out;
  for (const solver::LineSnapshot& s : lines) {
    VtkPolyline p;
    p.name = s.name;
    p.points = s.position;
    p.pointScalars = {{"arc_length_m", s.arcLength},
                      {"effective_tension_N", s.tension},
                      {"bending_moment_Nm", s.bendingMoment},
                      {"torque_Nm", s.torque},
                      {"curvature_1_per_m", s.curvature}};
    out.push_back(std::move(p));
  }
  return out;
}

DynamicRecorder::DynamicRecorder(const fs::path& dir, const std::vector<solver::LineSnapshot>& initial,
                                 double vtkInterval, const model::TimeHistorySelection& timeHistories)
    : m_dir(dir), m_stems(lineFileStems(initial)), m_vtkInterval(vtkInterval), m_ranges(initial) {
  const model::TimeHistorySelection& t = timeHistories;
  // kQuantities: x, y, z, tension, moment, curvature, moment x, y, z, torque.
  const bool selected[kQuantityCount] = {t.position,      t.position,  t.position,
                                         t.effectiveTension, t.bendingMoment, t.curvature,
                                         t.bendingMomentVector, t.bendingMomentVector, t.bendingMomentVector,
                                         t.torque,   t.wallTension};
  for (int q = 0; q < kQuantityCount; ++q)
    if (selected[q]) m_quantities.push_back(q);
  const fs::path dyn = dir / "dynamics";
  fs::create_directories(dyn);
  m_endForces = std::make_unique<core::OutputFile>(dyn / "end_forces.csv");
  std::string header = "time_s";
  for (std::size_t l = 0; l < initial.size(); ++l) {
    const solver::LineSnapshot& s = initial[l];
    m_arc.push_back(s.arcLength);
    m_hasBending.push_back(s.hasBending);
    const fs::path ld = dyn / m_stems[l];
    fs::create_directories(ld);
    std::vector<std::unique_ptr<core::OutputFile>> streams;
    // A cable line has no bending moment (nor its components) or torque: no file for them.
    std::vector<int> quantities;
    // Nor has a line without a bore a wall tension.
    for (const int q : m_quantities)
      if ((s.hasBending || !isBendingQuantity(q)) && (q != kWallTension || !s.wallTension.empty()))
        quantities.push_back(q);
    m_lineQuantities.push_back(quantities);
    for (const int q : quantities) {
      auto f = std::make_unique<core::OutputFile>(ld / (std::string(kQuantities[q]) + ".csv"));
      std::string row = "time_s";
      for (double a : s.arcLength) row += fmt::format(",s={:.3f}m", a);
      f->write(row + "\n");
      streams.push_back(std::move(f));
    }
    m_streams.push_back(std::move(streams));
    for (const char* end : {"end_a", "end_b"})
      header += fmt::format(",{0}_{1}_tension_N,{0}_{1}_fx_N,{0}_{1}_fy_N,{0}_{1}_fz_N", m_stems[l], end);
  }
  m_endForces->write(header + "\n");
  if (m_vtkInterval > 0.0) m_vtk = std::make_unique<PvdSeries>(dir / "vtk" / "lines.pvd");
}

DynamicRecorder::~DynamicRecorder() = default;

void DynamicRecorder::record(double time, const std::vector<solver::LineSnapshot>& lines) {
  std::string forces = fmt::format("{:.6f}", time);
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const solver::LineSnapshot& s = lines[l];
    for (std::size_t q = 0; q < m_streams[l].size(); ++q) {
      // Compiled format strings into one buffer: formatting value by value through fmt::format parsed a format and
      // built a string per value (docs/performance.md).
      fmt::memory_buffer row;
      fmt::format_to(std::back_inserter(row), FMT_COMPILE("{:.6f}"), time);
      for (std::size_t i = 0; i < s.arcLength.size(); ++i) {
        const double value = quantity(s, m_lineQuantities[l][q], i);
        // Exact zeros (the moments and torque of cable lines: 5 of the 11 quantities) as the text fmt would
        // give, without formatting them.
        if (value == 0.0 && !std::signbit(value)) {
          constexpr std::string_view kZero = ",0.000000e+00";
          row.append(kZero.data(), kZero.data() + kZero.size());
        } else {
          fmt::format_to(std::back_inserter(row), FMT_COMPILE(",{:.6e}"), value);
        }
      }
      row.push_back('\n');
      m_streams[l][q]->write(std::string_view(row.data(), row.size()));
      m_streams[l][q]->flush();
    }
    for (int end = 0; end < 2; ++end) {
      const Vec3& f = end == 0 ? s.endTensionForceA : s.endTensionForceB;
      forces += fmt::format(",{:.6e},{:.6e},{:.6e},{:.6e}", end == 0 ? s.endTensionA : s.endTensionB, f.x(), f.y(),
                            f.z());
    }
  }
  m_endForces->write(forces + "\n");
  m_endForces->flush();
  ++m_records;
  if (m_vtk && time >= m_nextVtk - 1e-9) {
    m_vtk->addStep(time, toPolylines(lines));
    m_nextVtk += m_vtkInterval;
  }
}

void DynamicRecorder::writeRanges() const {
  if (m_ranges.stepCount() == 0) return;
  // Only the initial state seen (no step): its values are the means, i.e. min (= max).
  auto mean = [&](double sum, double only) { return m_ranges.mean(sum, only); };
  for (std::size_t l = 0; l < m_stems.size(); ++l) {
    core::OutputFile f(m_dir / "dynamics" / m_stems[l] / "range.csv");
    const analysis::RangeGraphs::Range& r = m_ranges.ranges()[l];
    const bool bending = m_hasBending[l];  // a cable line: no bending moment columns
    const bool wall = !r.wallTensionSum.empty();  // a pipe line: its wall tension too
    f.write(std::string("arc_length_m,tension_min_N,tension_max_N,tension_mean_N,") +
            (wall ? "wall_tension_min_N,wall_tension_max_N,wall_tension_mean_N," : "") +
            (bending ? "bending_moment_min_Nm,bending_moment_max_Nm,bending_moment_mean_Nm," : "") +
            "curvature_min_1_per_m,curvature_max_1_per_m,curvature_mean_1_per_m" +
            (r.seabedClearanceMin.empty() ? "" : ",seabed_clearance_min_m") + "\n");
    for (std::size_t i = 0; i < m_arc[l].size(); ++i) {
      std::string row = fmt::format("{:.6f},{:.6e},{:.6e},{:.6e},", m_arc[l][i], r.tensionMin[i], r.tensionMax[i],
                                    mean(r.tensionSum[i], r.tensionMin[i]));
      if (wall)
        row += fmt::format("{:.6e},{:.6e},{:.6e},", r.wallTensionMin[i], r.wallTensionMax[i],
                           mean(r.wallTensionSum[i], r.wallTensionMin[i]));
      if (bending)
        row += fmt::format("{:.6e},{:.6e},{:.6e},", r.momentMin[i], r.momentMax[i],
                           mean(r.momentSum[i], r.momentMin[i]));
      row += fmt::format("{:.6e},{:.6e},{:.6e}", r.curvatureMin[i], r.curvatureMax[i],
                         mean(r.curvatureSum[i], r.curvatureMin[i]));
      if (!r.seabedClearanceMin.empty()) row += fmt::format(",{:.6f}", r.seabedClearanceMin[i]);
      f.write(row + "\n");
    }
    f.close();
  }
}

void DynamicRecorder::close() {
  for (auto& streams : m_streams)
    for (auto& f : streams) f->close();
  m_endForces->close();
  if (m_vtk) m_vtk->close();
}

}  // namespace tangle::io
