#include "tangle/contact/ClashReport.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <limits>

#include "tangle/core/Error.hpp"
#include "tangle/io/JsonWriter.hpp"
#include "tangle/io/OutputFile.hpp"

namespace tangle::contact {

namespace fs = std::filesystem;

namespace {
/// Minimum, mean, maximum and the 50/90 % quantiles of a sample (linear interpolation).
struct Stats {
  double min = 0.0, mean = 0.0, max = 0.0, p50 = 0.0, p90 = 0.0;
};
Stats statistics(std::vector<double> v) {
  Stats s;
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  s.min = v.front();
  s.max = v.back();
  double sum = 0.0;
  for (double x : v) sum += x;
  s.mean = sum / static_cast<double>(v.size());
  auto q = [&](double p) {
    const double pos = p * static_cast<double>(v.size() - 1);
    const std::size_t i = static_cast<std::size_t>(pos);
    const double f = pos - static_cast<double>(i);
    return i + 1 < v.size() ? v[i] * (1.0 - f) + v[i + 1] * f : v[i];
  };
  s.p50 = q(0.5);
  s.p90 = q(0.9);
  return s;
}

void writeStats(io::JsonWriter& j, const char* key, const std::vector<double>& v) {
  const Stats s = statistics(v);
  j.key(key);
  j.beginObject();
  j.field("min", s.min);
  j.field("mean", s.mean);
  j.field("p50", s.p50);
  j.field("p90", s.p90);
  j.field("max", s.max);
  j.field("values", v);
  j.endObject();
}
}  // namespace

ClashReport::ClashReport(const model::Model& model, const LineContact& contact) : m_model(&model), m_contact(&contact) {
  const int n = static_cast<int>(model.lines().size());
  for (int a = 0; a < n; ++a)
    for (int b = a; b < n; ++b)
      if (contact.pairAllowed(a, b)) m_pairs.push_back({a, b});
}

void ClashReport::recordClearance(const model::State& state) {
  for (int p = 0; p < static_cast<int>(m_pairs.size()); ++p) {
    const auto c = m_contact->clearance(state, m_pairs[p][0], m_pairs[p][1]);
    m_samples.push_back({state.time, p, c[0], c[1], c[2]});
  }
}

void ClashReport::write(const fs::path& dir) const {
  const fs::path out = dir / "contact";
  fs::create_directories(out);
  const auto& lines = m_model->lines();
  const auto& events = m_contact->events();
  {
    io::OutputFile file(out / "events.csv");
    std::ostream& f = file.stream();
    f << "event,line_1,line_2,start_time_s,end_time_s,arc_1_start_m,arc_2_start_m,arc_1_min_m,arc_1_max_m,"
         "arc_2_min_m,arc_2_max_m,peak_force_N,impulse_Ns,impact_velocity_m_per_s,impact_energy_J,"
         "effective_mass_1_kg,effective_mass_2_kg,lumped_mass_1_kg,lumped_mass_2_kg,max_penetration_m,open\n";
    for (std::size_t i = 0; i < events.size(); ++i) {
      const ContactEvent& e = events[i];
      f << fmt::format("{},{},{},{:.6f},{:.6f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.6e},{:.6e},{:.6e},{:.6e},"
                       "{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{}\n",
                       i, lines[e.lineA].name, lines[e.lineB].name, e.startTime, e.endTime, e.arcAStart, e.arcBStart,
                       e.arcAMin, e.arcAMax, e.arcBMin, e.arcBMax, e.peakForce, e.impulse, e.impactVelocity,
                       e.impactEnergy, e.effectiveMassA, e.effectiveMassB, e.lumpedMassA, e.lumpedMassB,
                       e.maxPenetration, e.open ? "true" : "false");
    }
    file.close();
  }
  {
    io::OutputFile file(out / "event_paths.csv");
    std::ostream& f = file.stream();
    f << "event,time_s,arc_1_m,arc_2_m\n";
    for (std::size_t i = 0; i < events.size(); ++i)
      for (const auto& p : events[i].path) f << fmt::format("{},{:.6f},{:.4f},{:.4f}\n", i, p[0], p[1], p[2]);
    file.close();
  }
  {
    io::OutputFile file(out / "clearance.csv");
    std::ostream& f = file.stream();
    f << "time_s,pair,min_clearance_m,arc_1_m,arc_2_m\n";
    for (const ClearanceSample& s : m_samples) {
      const std::string pair = lines[m_pairs[s.pair][0]].name + "-" + lines[m_pairs[s.pair][1]].name;
      if (std::isfinite(s.clearance)) {
        f << fmt::format("{:.6f},{},{:.6e},{:.4f},{:.4f}\n", s.time, pair, s.clearance, s.arcA, s.arcB);
      } else {
        f << fmt::format("{:.6f},{},inf,,\n", s.time, pair);
      }
    }
    file.close();
  }
  io::OutputFile summary(out / "summary.json");
  io::JsonWriter j(summary.stream());
  j.beginObject();
  j.field("model", m_contact->spec().model == model::ImpactModel::Penalty ? "penalty spring + dashpot" : "impulse");
  j.field("restitution", m_contact->spec().restitution);
  j.field("damping_ratio", m_contact->dampingRatio());
  j.field("clearance_margin_m", m_contact->spec().clearanceMargin);
  j.field("events", static_cast<int>(events.size()));
  j.key("pairs");
  j.beginArray();
  for (int p = 0; p < static_cast<int>(m_pairs.size()); ++p) {
    const int a = m_pairs[p][0], b = m_pairs[p][1];
    std::vector<double> velocity, energy, force;
    for (const ContactEvent& e : events) {
      if (e.lineA != a || e.lineB != b) continue;
      velocity.push_back(e.impactVelocity);
      energy.push_back(e.impactEnergy);
      force.push_back(e.peakForce);
    }
    const ClearanceSample* worst = nullptr;
    for (const ClearanceSample& s : m_samples)
      if (s.pair == p && (!worst || s.clearance < worst->clearance)) worst = &s;
    j.beginObject();
    j.field("line_1", lines[a].name);
    j.field("line_2", lines[b].name);
    j.field("stiffness_N_per_m", m_contact->stiffness(a, b));
    j.field("impacts", static_cast<int>(velocity.size()));
    writeStats(j, "impact_velocity_m_per_s", velocity);
    writeStats(j, "impact_energy_J", energy);
    writeStats(j, "peak_force_N", force);
    j.key("min_clearance");
    j.beginObject();
    j.field("clearance_m", worst ? worst->clearance : std::numeric_limits<double>::infinity());
    j.field("time_s", worst ? worst->time : std::nan(""));
    j.field("arc_1_m", worst && std::isfinite(worst->clearance) ? worst->arcA : std::nan(""));
    j.field("arc_2_m", worst && std::isfinite(worst->clearance) ? worst->arcB : std::nan(""));
    j.endObject();
    j.endObject();
  }
  j.endArray();
  j.endObject();
  summary.close();  // every write is checked: a full disk is an OutputError naming the file
}

std::string ClashReport::terminalSummary() const {
  const auto& lines = m_model->lines();
  std::string s = fmt::format("clash report: {} contact event(s)\n", m_contact->events().size());
  for (int p = 0; p < static_cast<int>(m_pairs.size()); ++p) {
    const int a = m_pairs[p][0], b = m_pairs[p][1];
    int count = 0;
    double vmax = 0.0, emax = 0.0, fmax = 0.0;
    for (const ContactEvent& e : m_contact->events()) {
      if (e.lineA != a || e.lineB != b) continue;
      ++count;
      vmax = std::max(vmax, e.impactVelocity);
      emax = std::max(emax, e.impactEnergy);
      fmax = std::max(fmax, e.peakForce);
    }
    double minClear = std::numeric_limits<double>::infinity();
    for (const ClearanceSample& c : m_samples)
      if (c.pair == p) minClear = std::min(minClear, c.clearance);
    s += fmt::format("  {} / {}: {} impact(s), max impact velocity {:.3f} m/s, max impact energy {:.4g} J, "
                     "max contact force {:.4g} kN, min clearance {}\n",
                     lines[a].name, lines[b].name, count, vmax, emax, fmax / 1000.0,
                     std::isfinite(minClear) ? fmt::format("{:.3f} m", minClear) : std::string("beyond margin"));
  }
  return s;
}

}  // namespace tangle::contact
