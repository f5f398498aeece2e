/// @file CaseSummary.cpp
/// Summary rows of batch cases (see CaseSummary.hpp).

#include "tangle/app/CaseSummary.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>

#include "tangle/core/Csv.hpp"
#include "tangle/core/OutputFile.hpp"

namespace tangle::app {

namespace fs = std::filesystem;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// A JSON file as a YAML tree (JSON is YAML); an undefined node when absent or unreadable.
YAML::Node readJson(const fs::path& file) {
  if (!fs::exists(file)) return YAML::Node(YAML::NodeType::Undefined);
  try {
    return YAML::LoadFile(file.string());
  } catch (const YAML::Exception&) {
    return YAML::Node(YAML::NodeType::Undefined);
  }
}

/// A number of a JSON tree (null, absent or not a number: NaN).
double number(const YAML::Node& n) {
  if (!n || !n.IsScalar()) return kNaN;
  try {
    return n.as<double>();
  } catch (const YAML::Exception&) {
    return kNaN;
  }
}

std::string numberText(double v) { return std::isfinite(v) ? fmt::format("{:.6g}", v) : ""; }

}  // namespace

CaseSummary readCaseSummary(const fs::path& caseDir, const fs::path& log) {
  CaseSummary row;
  row.minClearance = kNaN;
  if (const YAML::Node manifest = readJson(caseDir / "tangle-run.json"); manifest && manifest["status"])
    row.status = manifest["status"].as<std::string>();
  const YAML::Node statics = readJson(caseDir / "summary.json");
  if (statics && statics["statics"]) row.staticsConverged = statics["statics"]["converged"].as<bool>(false);
  const YAML::Node dynamics = readJson(caseDir / "dynamics" / "summary.json");
  row.maxOffset = kNaN;
  if (dynamics && dynamics["lines"] && row.staticsConverged) {
    for (const auto& line : dynamics["lines"])
      row.lines.push_back({line["name"].as<std::string>(), number(line["max_tension_N"]),
                           number(line["min_tension_N"]), number(line["end_a_max_tension_N"]),
                           number(line["end_b_max_tension_N"]), number(line["slack_events"])});
    if (dynamics["vessels"])
      for (const auto& v : dynamics["vessels"]) {
        const double offset = number(v["max_offset_m"]);
        if (std::isfinite(offset)) row.maxOffset = std::isfinite(row.maxOffset) ? std::max(row.maxOffset, offset) : offset;
      }
  } else if (statics && statics["lines"] && row.staticsConverged) {
    for (const auto& line : statics["lines"])
      row.lines.push_back({line["name"].as<std::string>(), number(line["max_tension_N"]),
                           number(line["min_tension_N"]), number(line["end_a"]["tension_N"]),
                           number(line["end_b"]["tension_N"]), kNaN});
  }
  // Clearance: the envelope over every node and step when it exists, else the clash report's samples.
  if (const YAML::Node c = readJson(caseDir / "clearance" / "summary.json"); c && c["pairs"]) {
    for (const auto& p : c["pairs"]) {
      const double v = number(p["min_clearance_m"]);
      if (std::isfinite(v)) row.minClearance = std::isfinite(row.minClearance) ? std::min(row.minClearance, v) : v;
    }
  }
  if (const YAML::Node c = readJson(caseDir / "contact" / "summary.json"); c && c["pairs"]) {
    for (const auto& p : c["pairs"]) {
      row.impacts += p["impacts"].as<int>(0);
      const double peak = std::max(p["peak_force_N"] ? number(p["peak_force_N"]["max"]) : kNaN,
                                   number(p["sustained_peak_force_N"]));
      if (std::isfinite(peak)) row.maxContactForce = std::max(row.maxContactForce, peak);
      const double v = p["min_clearance"] ? number(p["min_clearance"]["clearance_m"]) : kNaN;
      if (std::isfinite(v) && !fs::exists(caseDir / "clearance" / "summary.json"))
        row.minClearance = std::isfinite(row.minClearance) ? std::min(row.minClearance, v) : v;
    }
  }
  if (!log.empty() && fs::exists(log)) {
    std::ifstream in(log);
    std::string text;
    while (std::getline(in, text))
      if (text.rfind("error: ", 0) == 0) {
        row.message = text.substr(7);
        break;
      }
  }
  return row;
}

std::string CaseSummary::serialise() const {
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << name;
  out << YAML::Key << "parameters" << YAML::Value << YAML::Flow << parameterValues;
  out << YAML::Key << "status" << YAML::Value << status;
  out << YAML::Key << "exit_code" << YAML::Value << exitCode;
  out << YAML::Key << "wall_s" << YAML::Value << wallSeconds;
  out << YAML::Key << "reused" << YAML::Value << reused;
  out << YAML::Key << "rank" << YAML::Value << rank;
  out << YAML::Key << "statics_converged" << YAML::Value << staticsConverged;
  out << YAML::Key << "lines" << YAML::Value << YAML::BeginSeq;
  for (const LineRow& l : lines)
    out << YAML::Flow << YAML::BeginSeq << l.name << l.maxTension << l.minTension << l.endAMax << l.endBMax
        << l.slackEvents << YAML::EndSeq;
  out << YAML::EndSeq;
  out << YAML::Key << "max_offset" << YAML::Value << maxOffset;
  out << YAML::Key << "min_clearance" << YAML::Value << minClearance;
  out << YAML::Key << "impacts" << YAML::Value << impacts;
  out << YAML::Key << "max_contact_force" << YAML::Value << maxContactForce;
  out << YAML::Key << "message" << YAML::Value << message;
  out << YAML::EndMap;
  return out.c_str();
}

CaseSummary CaseSummary::deserialise(const std::string& text) {
  const YAML::Node n = YAML::Load(text);
  CaseSummary row;
  row.name = n["name"].as<std::string>();
  row.parameterValues = n["parameters"].as<std::vector<std::string>>(std::vector<std::string>{});
  row.status = n["status"].as<std::string>("");
  row.exitCode = n["exit_code"].as<int>();
  row.wallSeconds = n["wall_s"].as<double>();
  row.reused = n["reused"].as<bool>();
  row.rank = n["rank"].as<int>(0);
  row.staticsConverged = n["statics_converged"].as<bool>();
  for (const auto& t : n["lines"])
    row.lines.push_back({t[0].as<std::string>(), number(t[1]), number(t[2]), number(t[3]), number(t[4]), number(t[5])});
  row.maxOffset = number(n["max_offset"]);
  row.minClearance = number(n["min_clearance"]);
  row.impacts = n["impacts"].as<int>();
  row.maxContactForce = number(n["max_contact_force"]);
  row.message = n["message"].as<std::string>("");
  return row;
}

std::string writeSummaryTable(const fs::path& file, const std::vector<std::string>& parameterNames,
                              const std::vector<std::string>& lineNames, const std::vector<CaseSummary>& rows) {
  std::vector<std::string> lines = lineNames;  // then any a case gave that the models did not name
  for (const CaseSummary& r : rows)
    for (const CaseSummary::LineRow& l : r.lines)
      if (std::find(lines.begin(), lines.end(), l.name) == lines.end()) lines.push_back(l.name);
  core::OutputFile out(file);
  std::string header = "case";
  for (const std::string& p : parameterNames) header += "," + core::csvField(p);
  header += ",status,exit_code,statics_converged";
  for (const std::string& l : lines)
    for (const char* q : {"_max_tension_N", "_min_tension_N", "_end_a_max_tension_N", "_end_b_max_tension_N",
                          "_slack_events"})
      header += "," + core::csvField(l + q);
  header += ",max_offset_m,min_clearance_m,impacts,max_contact_force_N,wall_time_s,reused,rank,message\n";
  out.write(header);
  std::string table = fmt::format("{:<36} {:<24} {:>14} {:>12} {:>8} {:>9}\n", "case", "status", "max tension kN",
                                  "clearance m", "impacts", "wall s");
  int failed = 0;
  for (const CaseSummary& r : rows) {
    std::string row = core::csvField(r.name);
    for (std::size_t k = 0; k < parameterNames.size(); ++k)
      row += "," + core::csvField(k < r.parameterValues.size() ? r.parameterValues[k] : "");
    row += fmt::format(",{},{},{}", core::csvField(r.status), r.exitCode, r.staticsConverged ? "true" : "false");
    double worst = kNaN;
    for (const std::string& l : lines) {
      CaseSummary::LineRow values{l, kNaN, kNaN, kNaN, kNaN, kNaN};
      for (const CaseSummary::LineRow& v : r.lines)
        if (v.name == l) values = v;
      if (std::isfinite(values.maxTension))
        worst = std::isfinite(worst) ? std::max(worst, values.maxTension) : values.maxTension;
      for (const double v : {values.maxTension, values.minTension, values.endAMax, values.endBMax, values.slackEvents})
        row += "," + numberText(v);
    }
    row += fmt::format(",{},{},{},{},{:.3f},{},{},{}\n", numberText(r.maxOffset), numberText(r.minClearance), r.impacts,
                       numberText(r.maxContactForce), r.wallSeconds, r.reused ? "true" : "false", r.rank,
                       core::csvField(r.message));
    out.write(row);
    if (r.exitCode != 0) ++failed;
    table += fmt::format("{:<36} {:<24} {:>14} {:>12} {:>8} {:>9.2f}\n", r.name.substr(0, 36), r.status.substr(0, 24),
                         std::isfinite(worst) ? fmt::format("{:.1f}", worst / 1000.0) : "-",
                         std::isfinite(r.minClearance) ? fmt::format("{:.3f}", r.minClearance) : "-", r.impacts,
                         r.wallSeconds);
  }
  out.close();
  table += fmt::format("{} case(s), {} failed; table in {}\n", rows.size(), failed, file.string());
  return table;
}

}  // namespace tangle::app
