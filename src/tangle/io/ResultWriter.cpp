#include "tangle/io/ResultWriter.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fmt/format.h>
#include <fstream>

#include "tangle/core/Error.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/io/JsonWriter.hpp"

namespace tangle::io {

namespace fs = std::filesystem;

std::string safeFileName(const std::string& name) {
  std::string s = name;
  for (char& c : s) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.')) c = '_';
  }
  return s.empty() ? "line" : s;
}

double elevationAngleDeg(const Vec3& f) {
  return radToDeg(std::atan2(f.z(), std::hypot(f.x(), f.y())));
}

std::vector<fs::path> writeStaticLineTables(const fs::path& dir, const std::vector<solver::LineSnapshot>& lines) {
  const fs::path sub = dir / "statics";
  fs::create_directories(sub);
  std::vector<fs::path> written;
  for (const solver::LineSnapshot& s : lines) {
    const fs::path p = sub / (safeFileName(s.name) + ".csv");
    std::ofstream out(p);
    if (!out) throw Error("cannot write " + p.string());
    out << "arc_length_m,x_m,y_m,z_m,effective_tension_N,bending_moment_Nm,curvature_1_per_m\n";
    for (std::size_t i = 0; i < s.arcLength.size(); ++i) {
      out << fmt::format("{:.6f},{:.6f},{:.6f},{:.6f},{:.6e},{:.6e},{:.6e}\n", s.arcLength[i], s.position[i].x(),
                         s.position[i].y(), s.position[i].z(), s.tension[i], s.bendingMoment[i], s.curvature[i]);
    }
    written.push_back(p);
  }
  return written;
}

void writeStaticSummary(const fs::path& dir, const model::Model& model, const solver::StaticResult& result,
                        const std::vector<solver::LineSnapshot>& lines) {
  fs::create_directories(dir);
  std::ofstream out(dir / "summary.json");
  if (!out) throw Error("cannot write " + (dir / "summary.json").string());
  JsonWriter j(out);
  j.beginObject();
  j.field("tangle_version", TANGLE_VERSION);
  j.field("model", model.spec().sourceFile);
  j.field("title", model.spec().title);
  j.field("water_depth_m", model.environment().waterDepth);
  j.field("units", "SI: N, m, kg, s; angles in degrees");
  j.key("statics");
  j.beginObject();
  j.field("converged", result.converged);
  j.field("iterations", result.iterations);
  j.field("load_fraction", result.loadFraction);
  j.field("max_out_of_balance_N", result.residual);
  j.field("message", result.message);
  j.endObject();
  j.key("lines");
  j.beginArray();
  for (const solver::LineSnapshot& s : lines) {
    j.beginObject();
    j.field("name", s.name);
    j.field("length_m", s.arcLength.back());
    for (int end = 0; end < 2; ++end) {
      const Vec3& f = end == 0 ? s.endForceA : s.endForceB;
      j.key(end == 0 ? "end_a" : "end_b");
      j.beginObject();
      j.field("tension_N", end == 0 ? s.tension.front() : s.tension.back());
      j.field("reaction_magnitude_N", f.norm());
      j.field("force_on_support_N", std::vector<double>{f.x(), f.y(), f.z()});
      j.field("horizontal_force_N", std::hypot(f.x(), f.y()));
      j.field("vertical_force_N", f.z());
      j.field("angle_from_horizontal_deg", elevationAngleDeg(f));
      j.field("angle_from_vertical_deg", 90.0 - std::abs(elevationAngleDeg(f)));
      j.endObject();
    }
    j.key("touchdown_arc_length_m");
    if (s.touchdownArcLength >= 0.0) {
      j.value(s.touchdownArcLength);
    } else {
      j.value(std::nan(""));
    }
    j.field("nodes_on_seabed", s.seabedNodes);
    j.field("max_tension_N", *std::max_element(s.tension.begin(), s.tension.end()));
    j.field("min_tension_N", *std::min_element(s.tension.begin(), s.tension.end()));
    j.field("max_bending_moment_Nm", *std::max_element(s.bendingMoment.begin(), s.bendingMoment.end()));
    j.endObject();
  }
  j.endArray();
  j.endObject();
}

}  // namespace tangle::io
