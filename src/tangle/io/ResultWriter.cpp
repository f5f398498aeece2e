#include "tangle/io/ResultWriter.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fmt/format.h>
#include <set>

#include "tangle/core/Error.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/core/JsonWriter.hpp"
#include "tangle/core/OutputFile.hpp"

namespace tangle::io {

namespace fs = std::filesystem;

std::string safeFileName(const std::string& name) {
  constexpr std::size_t kMaxLength = 64;
  std::string s;
  for (char c : name) {
    const unsigned char u = static_cast<unsigned char>(c);
    const bool ascii = u < 0x80;
    s += ascii && (std::isalnum(u) || c == '-' || c == '_' || c == '.') ? c : '_';
    if (s.size() == kMaxLength) break;
  }
  if (!s.empty() && s.front() == '.') s.front() = '_';
  return s.empty() ? "line" : s;
}

std::vector<std::string> uniqueFileStems(const std::vector<std::string>& names) {
  std::vector<std::string> stems;
  std::set<std::string> taken;  // lower case: unique on case-insensitive file systems too
  auto lower = [](std::string t) {
    for (char& c : t) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return t;
  };
  for (const std::string& name : names) {
    const std::string base = safeFileName(name);
    std::string stem = base;
    for (int k = 2; taken.contains(lower(stem)); ++k) stem = base + "-" + std::to_string(k);
    taken.insert(lower(stem));
    stems.push_back(stem);
  }
  return stems;
}

std::vector<std::string> lineFileStems(const std::vector<solver::LineSnapshot>& lines) {
  std::vector<std::string> names;
  for (const solver::LineSnapshot& s : lines) names.push_back(s.name);
  return uniqueFileStems(names);
}

double elevationAngleDeg(const Vec3& f) {
  return radToDeg(std::atan2(f.z(), std::hypot(f.x(), f.y())));
}

std::vector<fs::path> writeStaticLineTables(const fs::path& dir, const std::vector<solver::LineSnapshot>& lines) {
  const fs::path sub = dir / "statics";
  fs::create_directories(sub);
  std::vector<fs::path> written;
  const std::vector<std::string> stems = lineFileStems(lines);
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const solver::LineSnapshot& s = lines[l];
    core::OutputFile out(sub / (stems[l] + ".csv"));
    // A cable line has no bending moment, torque or node rotation: its table leaves them out.
    const bool bending = s.hasBending;
    const bool pipe = !s.wallTension.empty();  // a pipe: its internal pressure and wall tension too
    out.write(std::string("arc_length_m,x_m,y_m,z_m,effective_tension_N,") +
              (pipe ? "wall_tension_N,internal_pressure_Pa," : "") + (bending ? "bending_moment_Nm," : "") +
              "curvature_1_per_m" +
              (bending ? ",bending_moment_x_Nm,bending_moment_y_Nm,bending_moment_z_Nm,torque_Nm,rotation_x_deg,"
                         "rotation_y_deg,rotation_z_deg"
                       : "") +
              "\n");
    for (std::size_t i = 0; i < s.arcLength.size(); ++i) {
      std::string row = fmt::format("{:.6f},{:.6f},{:.6f},{:.6f},{:.6e},", s.arcLength[i], s.position[i].x(),
                                    s.position[i].y(), s.position[i].z(), s.tension[i]);
      if (pipe) row += fmt::format("{:.6e},{:.6e},", s.wallTension[i], s.internalPressure[i]);
      if (bending) row += fmt::format("{:.6e},", s.bendingMoment[i]);
      row += fmt::format("{:.6e}", s.curvature[i]);
      if (bending) {
        const Vec3& m = s.bendingMomentVector[i];
        const Vec3& r = s.rotation[i];
        row += fmt::format(",{:.6e},{:.6e},{:.6e},{:.6e},{:.6f},{:.6f},{:.6f}", m.x(), m.y(), m.z(), s.torque[i],
                           r.x(), r.y(), r.z());
      }
      out.write(row + "\n");
    }
    out.close();
    written.push_back(out.path());
  }
  return written;
}

void writeStaticSummary(const fs::path& dir, const model::Model& model, const solver::StaticResult& result,
                        const std::vector<solver::LineSnapshot>& lines, const solver::EquilibriumAudit* audit) {
  fs::create_directories(dir);
  core::OutputFile file(dir / "summary.json");
  core::JsonWriter j(file.stream());
  j.beginObject();
  j.field("tangle_version", TANGLE_VERSION);
  j.field("model", model.spec().sourceFile);
  j.field("title", model.spec().title);
  j.field("water_depth_m", model.environment().waterDepth);
  j.field("seabed", model.seabedSurface().describe());
  j.field("units", "SI: N, m, kg, s; angles in degrees");
  j.field("end_tension_definition",
          "effective tension at the end point: element force vectors extrapolated linearly in arc length to "
          "the end node; force_N is the force the line exerts on what is at its end");
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
  const std::vector<std::string> stems = lineFileStems(lines);
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const solver::LineSnapshot& s = lines[l];
    j.beginObject();
    j.field("name", s.name);
    j.field("file_stem", stems[l]);
    j.field("length_m", s.arcLength.back());
    for (int end = 0; end < 2; ++end) {
      const Vec3& f = end == 0 ? s.endTensionForceA : s.endTensionForceB;
      const Vec3& reaction = end == 0 ? s.endForceA : s.endForceB;
      j.key(end == 0 ? "end_a" : "end_b");
      j.beginObject();
      j.field("tension_N", end == 0 ? s.endTensionA : s.endTensionB);
      j.field("force_N", std::vector<double>{f.x(), f.y(), f.z()});
      j.field("horizontal_force_N", std::hypot(f.x(), f.y()));
      j.field("vertical_force_N", f.z());
      j.field("angle_from_horizontal_deg", elevationAngleDeg(f));
      j.field("angle_from_vertical_deg", 90.0 - std::abs(elevationAngleDeg(f)));
      j.field("support_reaction_N", std::vector<double>{reaction.x(), reaction.y(), reaction.z()});
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
  if (!model.points().empty()) {
    // Free points (ModelSpec::points): where each came to rest and the line ends it joins.
    j.key("points");
    j.beginArray();
    for (const model::JunctionPoint& p : model.points()) {
      j.beginObject();
      j.field("name", p.name);
      const int l = model.lineOfNode(p.node);
      const model::Line& line = model.lines()[static_cast<std::size_t>(l)];
      const Vec3& x =
          lines[static_cast<std::size_t>(l)].position[static_cast<std::size_t>(p.node - line.firstNode)];
      j.field("position_m", std::vector<double>{x.x(), x.y(), x.z()});
      j.key("line_ends");
      j.beginArray();
      for (const int node : p.endNodes) {
        const model::Line& at = model.lines()[static_cast<std::size_t>(model.lineOfNode(node))];
        j.value(at.name + (node == at.firstNode ? " end_a" : " end_b"));
      }
      j.endArray();
      j.endObject();
    }
    j.endArray();
  }
  if (audit) {
    j.key("equilibrium_audit");
    j.beginObject();
    j.field("definition",
            "per body the forces on it by source [N] (end forces: minus the reported force_N) and their sum; "
            "relative residual = |sum| / reference force (a line's submerged weight)");
    j.field("worst_relative_residual", audit->worstRelativeResidual());
    const auto bodies = [&j](const char* key, const std::vector<solver::ForceBalance>& list) {
      j.key(key);
      j.beginArray();
      for (const solver::ForceBalance& b : list) {
        j.beginObject();
        j.field("name", b.name);
        j.key("forces_N");
        j.beginObject();
        for (const auto& [name, f] : b.terms) j.field(name, std::vector<double>{f.x(), f.y(), f.z()});
        j.endObject();
        j.field("residual_N", std::vector<double>{b.residual.x(), b.residual.y(), b.residual.z()});
        j.field("reference_force_N", b.scale);
        j.field("relative_residual", b.relativeResidual());
        j.field("tolerance", b.tolerance);
        j.endObject();
      }
      j.endArray();
    };
    bodies("lines", audit->lines);
    bodies("vessels", audit->vessels);
    if (!audit->points.empty()) bodies("points", audit->points);
    j.endObject();
  }
  j.endObject();
  file.close();
}

}  // namespace tangle::io
