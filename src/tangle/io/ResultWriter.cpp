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
  j.key("tangle_version");
  j.value(TANGLE_VERSION);
  j.key("model");
  j.value(model.spec().sourceFile);
  j.key("title");
  j.value(model.spec().title);
  j.key("water_depth_m");
  j.value(model.environment().waterDepth);
  j.key("units");
  j.value("SI: N, m, kg, s; angles in degrees");
  j.key("statics");
  j.beginObject();
  j.key("converged");
  j.value(result.converged);
  j.key("iterations");
  j.value(result.iterations);
  j.key("load_fraction");
  j.value(result.loadFraction);
  j.key("max_out_of_balance_N");
  j.value(result.residual);
  j.key("message");
  j.value(result.message);
  j.endObject();
  j.key("lines");
  j.beginArray();
  for (const solver::LineSnapshot& s : lines) {
    j.beginObject();
    j.key("name");
    j.value(s.name);
    j.key("length_m");
    j.value(s.arcLength.back());
    for (int end = 0; end < 2; ++end) {
      const Vec3& f = end == 0 ? s.endForceA : s.endForceB;
      j.key(end == 0 ? "end_a" : "end_b");
      j.beginObject();
      j.key("tension_N");
      j.value(end == 0 ? s.tension.front() : s.tension.back());
      j.key("reaction_magnitude_N");
      j.value(f.norm());
      j.key("force_on_support_N");
      j.value(std::vector<double>{f.x(), f.y(), f.z()});
      j.key("horizontal_force_N");
      j.value(std::hypot(f.x(), f.y()));
      j.key("vertical_force_N");
      j.value(f.z());
      j.key("angle_from_horizontal_deg");
      j.value(elevationAngleDeg(f));
      j.key("angle_from_vertical_deg");
      j.value(90.0 - std::abs(elevationAngleDeg(f)));
      j.endObject();
    }
    j.key("touchdown_arc_length_m");
    if (s.touchdownArcLength >= 0.0) {
      j.value(s.touchdownArcLength);
    } else {
      j.value(std::nan(""));
    }
    j.key("nodes_on_seabed");
    j.value(s.seabedNodes);
    j.key("max_tension_N");
    j.value(*std::max_element(s.tension.begin(), s.tension.end()));
    j.key("min_tension_N");
    j.value(*std::min_element(s.tension.begin(), s.tension.end()));
    j.key("max_bending_moment_Nm");
    j.value(*std::max_element(s.bendingMoment.begin(), s.bendingMoment.end()));
    j.endObject();
  }
  j.endArray();
  j.endObject();
}

}  // namespace tangle::io
