#include "tangle/analysis/SnCurve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace tangle::analysis {

namespace {
constexpr double kPaPerMPa = 1e6;
}

SnCurve SnCurve::dnvD(double thickness) {
  SnCurve c;
  c.name = "DNV D (air)";
  c.m1 = 3.0;
  c.logA1 = 12.164;
  c.m2 = 5.0;
  c.logA2 = 15.606;
  c.kneeCycles = 1e7;
  c.thicknessExponent = 0.20;
  c.referenceThickness = 0.025;
  c.thickness = thickness;
  return c;
}

namespace {
/// DNV-RP-C203 (2021) Table 2-1 (in air) and Table 2-2 (seawater with cathodic protection): class, m1,
/// log a1, log a2 (m2 = 5), k. The two segments meet at the knee (tested for every row).
struct DnvRow {
  const char* name;
  double m1, logA1, logA2, k;
};
constexpr DnvRow kAir[] = {
    {"b1", 4.0, 15.117, 17.146, 0.0},  {"b2", 4.0, 14.885, 16.856, 0.0},  {"c", 3.0, 12.592, 16.320, 0.05},
    {"c1", 3.0, 12.449, 16.081, 0.10}, {"c2", 3.0, 12.301, 15.835, 0.15}, {"d", 3.0, 12.164, 15.606, 0.20},
    {"e", 3.0, 12.010, 15.350, 0.20},  {"f", 3.0, 11.855, 15.091, 0.25},  {"f1", 3.0, 11.699, 14.832, 0.25},
    {"f3", 3.0, 11.546, 14.576, 0.25}, {"g", 3.0, 11.398, 14.330, 0.25},  {"w1", 3.0, 11.261, 14.101, 0.25},
    {"w2", 3.0, 11.107, 13.845, 0.25}, {"w3", 3.0, 10.970, 13.617, 0.25},
};
constexpr DnvRow kSeawaterCp[] = {
    {"b1", 4.0, 14.917, 17.146, 0.0},  {"c", 3.0, 12.192, 16.320, 0.05}, {"d", 3.0, 11.764, 15.606, 0.20},
    {"e", 3.0, 11.610, 15.350, 0.20},  {"f", 3.0, 11.455, 15.091, 0.25}, {"f1", 3.0, 11.299, 14.832, 0.25},
};
}  // namespace

std::optional<SnCurve> SnCurve::preset(std::string_view name) {
  const auto find = [&](const auto& table, std::string_view suffix, double knee) -> std::optional<SnCurve> {
    for (const DnvRow& r : table) {
      if (name != "dnv-" + std::string(r.name) + std::string(suffix)) continue;
      SnCurve c;
      c.name = std::string(name);
      c.m1 = r.m1;
      c.logA1 = r.logA1;
      c.m2 = 5.0;
      c.logA2 = r.logA2;
      c.kneeCycles = knee;
      c.thicknessExponent = r.k;
      c.referenceThickness = 0.025;
      return c;
    }
    return std::nullopt;
  };
  if (auto c = find(kAir, "-air", 1e7)) return c;
  return find(kSeawaterCp, "-seawater-cp", 1e6);
}

std::vector<std::string> SnCurve::presetNames() {
  std::vector<std::string> names;
  for (const DnvRow& r : kAir) names.push_back("dnv-" + std::string(r.name) + "-air");
  for (const DnvRow& r : kSeawaterCp) names.push_back("dnv-" + std::string(r.name) + "-seawater-cp");
  return names;
}

double SnCurve::cyclesToFailure(double range) const {
  if (!(range > 0.0)) return std::numeric_limits<double>::infinity();
  // DNV-RP-C203 eq. (2.4.3): log N = log a - m log(S (t / t_ref)^k), S in MPa, t / t_ref >= 1.
  const double correction = std::pow(std::max(1.0, thickness / referenceThickness), thicknessExponent);
  const double logS = std::log10(range / kPaPerMPa * correction);
  const double n1 = logA1 - m1 * logS;
  if (singleSlope || n1 <= std::log10(kneeCycles)) return std::pow(10.0, n1);
  return std::pow(10.0, logA2 - m2 * logS);
}

double SnCurve::kneeRange() const {
  const double correction = std::pow(std::max(1.0, thickness / referenceThickness), thicknessExponent);
  return std::pow(10.0, (logA1 - std::log10(kneeCycles)) / m1) * kPaPerMPa / correction;
}

std::optional<TnCurve> TnCurve::preset(std::string_view name) {
  TnCurve c;
  c.m = 3.0;
  if (name == "api-studlink") {
    c.aD = 1000.0;
  } else if (name == "api-studless") {
    c.aD = 316.0;
  } else if (name == "dnv-studlink") {
    c.aD = 1.2e11;
    c.stressBased = true;
  } else if (name == "dnv-studless") {
    c.aD = 6.0e10;
    c.stressBased = true;
  } else {
    return std::nullopt;
  }
  return c;
}

double TnCurve::cyclesToFailure(double tensionRange) const {
  if (!(tensionRange > 0.0)) return std::numeric_limits<double>::infinity();
  if (stressBased) return aD / std::pow(tensionRange / nominalArea / kPaPerMPa, m);
  return aD / std::pow(tensionRange / breakingStrength, m);
}

double minerDamage(const std::vector<RainflowCycle>& cycles, const SnCurve& curve) {
  double d = 0.0;
  for (const RainflowCycle& c : cycles) d += c.count / curve.cyclesToFailure(c.range);
  return d;
}

double minerDamage(const std::vector<RainflowCycle>& cycles, const TnCurve& curve) {
  double d = 0.0;
  for (const RainflowCycle& c : cycles) d += c.count / curve.cyclesToFailure(c.range);
  return d;
}

}  // namespace tangle::analysis
