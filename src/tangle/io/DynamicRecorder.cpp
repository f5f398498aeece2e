#include "tangle/io/DynamicRecorder.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <limits>

#include "tangle/core/Error.hpp"
#include "tangle/io/ResultWriter.hpp"

namespace tangle::io {

namespace fs = std::filesystem;

namespace {
const char* const kQuantities[] = {"x_m", "y_m", "z_m", "effective_tension_N", "bending_moment_Nm",
                                   "curvature_1_per_m"};
constexpr int kQuantityCount = 6;

double quantity(const solver::LineSnapshot& s, int q, std::size_t i) {
  switch (q) {
    case 0: return s.position[i].x();
    case 1: return s.position[i].y();
    case 2: return s.position[i].z();
    case 3: return s.tension[i];
    case 4: return s.bendingMoment[i];
    default: return s.curvature[i];
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
                      {"curvature_1_per_m", s.curvature}};
    out.push_back(std::move(p));
  }
  return out;
}

DynamicRecorder::DynamicRecorder(const fs::path& dir, const std::vector<solver::LineSnapshot>& initial,
                                 double vtkInterval)
    : m_dir(dir), m_vtkInterval(vtkInterval) {
  const fs::path dyn = dir / "dynamics";
  fs::create_directories(dyn);
  m_endForces = std::make_unique<std::ofstream>(dyn / "end_forces.csv");
  if (!*m_endForces) throw Error("cannot write " + (dyn / "end_forces.csv").string());
  *m_endForces << "time_s";
  for (const solver::LineSnapshot& s : initial) {
    m_names.push_back(s.name);
    m_arc.push_back(s.arcLength);
    const fs::path ld = dyn / safeFileName(s.name);
    fs::create_directories(ld);
    std::vector<std::unique_ptr<std::ofstream>> streams;
    for (int q = 0; q < kQuantityCount; ++q) {
      auto f = std::make_unique<std::ofstream>(ld / (std::string(kQuantities[q]) + ".csv"));
      if (!*f) throw Error("cannot write in " + ld.string());
      *f << "time_s";
      for (double a : s.arcLength) *f << fmt::format(",s={:.3f}m", a);
      *f << "\n";
      streams.push_back(std::move(f));
    }
    m_streams.push_back(std::move(streams));
    *m_endForces << fmt::format(",{0}_end_a_tension_N,{0}_end_b_tension_N", s.name);
    const std::size_t n = s.arcLength.size();
    const double inf = std::numeric_limits<double>::infinity();
    m_ranges.push_back({std::vector<double>(n, inf), std::vector<double>(n, -inf), std::vector<double>(n, 0.0),
                        std::vector<double>(n, inf), std::vector<double>(n, -inf), std::vector<double>(n, 0.0),
                        std::vector<double>(n, inf), std::vector<double>(n, -inf), std::vector<double>(n, 0.0)});
  }
  *m_endForces << "\n";
  if (m_vtkInterval > 0.0) m_vtk = std::make_unique<PvdSeries>(dir / "vtk" / "lines.pvd");
}

DynamicRecorder::~DynamicRecorder() = default;

void DynamicRecorder::record(double time, const std::vector<solver::LineSnapshot>& lines) {
  *m_endForces << fmt::format("{:.6f}", time);
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const solver::LineSnapshot& s = lines[l];
    for (int q = 0; q < kQuantityCount; ++q) {
      std::ofstream& f = *m_streams[l][q];
      f << fmt::format("{:.6f}", time);
      for (std::size_t i = 0; i < s.arcLength.size(); ++i) f << fmt::format(",{:.6e}", quantity(s, q, i));
      f << "\n";
      f.flush();
    }
    Range& r = m_ranges[l];
    for (std::size_t i = 0; i < s.arcLength.size(); ++i) {
      r.tensionMin[i] = std::min(r.tensionMin[i], s.tension[i]);
      r.tensionMax[i] = std::max(r.tensionMax[i], s.tension[i]);
      r.tensionSum[i] += s.tension[i];
      r.momentMin[i] = std::min(r.momentMin[i], s.bendingMoment[i]);
      r.momentMax[i] = std::max(r.momentMax[i], s.bendingMoment[i]);
      r.momentSum[i] += s.bendingMoment[i];
      r.curvatureMin[i] = std::min(r.curvatureMin[i], s.curvature[i]);
      r.curvatureMax[i] = std::max(r.curvatureMax[i], s.curvature[i]);
      r.curvatureSum[i] += s.curvature[i];
    }
    *m_endForces << fmt::format(",{:.6e},{:.6e}", s.endForceA.norm(), s.endForceB.norm());
  }
  *m_endForces << "\n";
  m_endForces->flush();
  ++m_records;
  if (m_vtk && time >= m_nextVtk - 1e-9) {
    m_vtk->addStep(time, toPolylines(lines));
    m_nextVtk += m_vtkInterval;
  }
}

void DynamicRecorder::writeRanges() const {
  if (m_records == 0) return;
  for (std::size_t l = 0; l < m_names.size(); ++l) {
    const fs::path p = m_dir / "dynamics" / safeFileName(m_names[l]) / "range.csv";
    std::ofstream f(p);
    if (!f) throw Error("cannot write " + p.string());
    f << "arc_length_m,tension_min_N,tension_max_N,tension_mean_N,bending_moment_min_Nm,bending_moment_max_Nm,"
         "bending_moment_mean_Nm,curvature_min_1_per_m,curvature_max_1_per_m,curvature_mean_1_per_m\n";
    const Range& r = m_ranges[l];
    for (std::size_t i = 0; i < m_arc[l].size(); ++i) {
      f << fmt::format("{:.6f},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e}\n", m_arc[l][i],
                       r.tensionMin[i], r.tensionMax[i], r.tensionSum[i] / m_records, r.momentMin[i],
                       r.momentMax[i], r.momentSum[i] / m_records, r.curvatureMin[i], r.curvatureMax[i],
                       r.curvatureSum[i] / m_records);
    }
  }
}

}  // namespace tangle::io
