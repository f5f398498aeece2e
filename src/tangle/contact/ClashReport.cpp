#include "tangle/contact/ClashReport.hpp"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>

#include "tangle/core/Error.hpp"
#include "tangle/core/JsonWriter.hpp"
#include "tangle/core/OutputFile.hpp"

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

void writeStats(core::JsonWriter& j, const char* key, const std::vector<double>& v) {
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

ClashReport::ClashReport(const model::Model& model, const LineContact& contact,
                         std::vector<std::array<int, 2>> pairs)
    : m_model(&model), m_contact(&contact), m_pairs(std::move(pairs)) {}

void ClashReport::recordClearance(const model::State& state) {
  const std::vector<std::array<double, 3>> clearances = m_contact->clearances(state, m_pairs);
  for (int p = 0; p < static_cast<int>(m_pairs.size()); ++p) {
    const std::array<double, 3>& c = clearances[static_cast<std::size_t>(p)];
    m_samples.push_back({state.time, p, c[0], c[1], c[2]});
    ForceSample f{state.time, p, 0.0, 0.0, 0.0, 0};
    for (const ContactPatch& patch : m_contact->patches()) {
      if (patch.lineA != m_pairs[p][0] || patch.lineB != m_pairs[p][1]) continue;
      f.force += patch.force;
      f.peakPerLength = std::max(f.peakPerLength, patch.peakForcePerLength);
      f.length += patch.length;
      ++f.patches;
    }
    m_forces.push_back(f);
  }
}

void ClashReport::write(const fs::path& dir) const {
  const fs::path out = dir / "contact";
  fs::create_directories(out);
  const auto& lines = m_model->lines();
  const auto& events = m_contact->events();
  {
    core::OutputFile file(out / "events.csv");
    std::ostream& f = file.stream();
    f << "event,line_1,line_2,kind,start_time_s,end_time_s,x_start_m,y_start_m,z_start_m,arc_1_start_m,"
         "arc_2_start_m,"
         "arc_1_min_m,arc_1_max_m,arc_2_min_m,arc_2_max_m,peak_force_N,peak_force_per_length_N_per_m,"
         "max_contact_length_m,impulse_Ns,impact_velocity_m_per_s,impact_energy_J,energy_mass_kg,"
         "energy_mass_basis,effective_mass_1_kg,effective_mass_2_kg,max_penetration_m,open,impact_phase_end_"
         "s,"
         "impact_phase_end,impact_phase_impulse_Ns,eq5_mass_kg,absorbed_energy_J,work_mass_kg,"
         "event_eq5_mass_kg,mass_lower_bound_kg,mass_upper_bound_kg,energy_warning,mesh_mass_kg,mesh_energy_"
         "J,"
         "mesh_mass_basis,continuum_mass_kg,continuum_energy_J,continuum_length_1_m,continuum_length_2_m,"
         "continuum_duration_s,continuum_peak_force_N,continuum_note,impact_peak_force_N,"
         "mesh_impact_peak_force_N\n";
    for (std::size_t i = 0; i < events.size(); ++i) {
      const ContactEvent& e = events[i];
      f << fmt::format(
          "{},{},{},{},{:.6f},{:.6f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.6e},"
          "{:.6e},{:.4f},{:.6e},{:.6e},{:.6e},{:.6e},{},{:.6e},{:.6e},{:.6e},{},{:.6f},{},{:.6e},{:.6e},"
          "{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},\"{}\",{:.6e},{:.6e},{},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},"
          "{:.6e},\"{}\",{:.6e},{:.6e}\n",
          i, lines[e.lineA].name, lines[e.lineB].name, e.kind(), e.startTime, e.endTime, e.positionStart.x(),
          e.positionStart.y(), e.positionStart.z(), e.arcAStart, e.arcBStart, e.arcAMin, e.arcAMax, e.arcBMin,
          e.arcBMax, e.peakForce, e.peakForcePerLength, e.maxContactLength, e.impulse, e.impactVelocity,
          e.impactEnergy, e.energyMass, e.energyMassBasis, e.effectiveMassA, e.effectiveMassB,
          e.maxPenetration, e.open ? "true" : "false", e.phaseEndTime, e.phaseEnd, e.phaseImpulse, e.eq5Mass,
          e.phaseWork, e.workMass, e.eventEq5Mass, e.massLowerBound, e.massUpperBound, e.energyWarning,
          e.meshMass, e.meshEnergy, e.meshMassBasis, e.continuumMass, e.continuumEnergy, e.continuumLengthA,
          e.continuumLengthB, e.continuumDuration, e.continuumPeakForce, e.continuumNote, e.impactPeakForce,
          e.meshImpactPeakForce);
    }
    file.close();
  }
  {
    core::OutputFile file(out / "event_paths.csv");
    file.write("event,time_s,arc_1_m,arc_2_m\n");
    std::string rows;  // as clearance.csv's
    for (std::size_t i = 0; i < events.size(); ++i)
      for (const auto& p : events[i].path) {
        fmt::format_to(std::back_inserter(rows), FMT_COMPILE("{},{:.6f},{:.4f},{:.4f}\n"), i, p[0], p[1],
                       p[2]);
        file.writeRows(rows);
      }
    file.writeRows(rows, true);
    file.close();
  }
  {
    core::OutputFile file(out / "clearance.csv");
    file.write("time_s,pair,min_clearance_m,arc_1_m,arc_2_m\n");
    // Rows formatted into one buffer by compiled formats, the pair names made once: a row per pair and
    // output time (12 lines, 66 pairs, 30 s: 40 000 rows, 0.2 G instructions as a string and a stream
    // write per row).
    std::vector<std::string> pairName;
    for (const auto& [a, b] : m_pairs) pairName.push_back(lines[a].name + "-" + lines[b].name);
    std::string rows;
    for (const ClearanceSample& s : m_samples) {
      const std::string& pair = pairName[static_cast<std::size_t>(s.pair)];
      if (std::isfinite(s.clearance)) {
        fmt::format_to(std::back_inserter(rows), FMT_COMPILE("{:.6f},{},{:.6e},{:.4f},{:.4f}\n"), s.time,
                       pair, s.clearance, s.arcA, s.arcB);
      } else {
        fmt::format_to(std::back_inserter(rows), FMT_COMPILE("{:.6f},{},inf,,\n"), s.time, pair);
      }
      file.writeRows(rows);
    }
    file.writeRows(rows, true);
    file.close();
  }
  {
    core::OutputFile file(out / "forces.csv");
    file.write("time_s,pair,total_force_N,peak_force_per_length_N_per_m,contact_length_m,patches\n");
    std::string rows;  // as clearance.csv's
    for (const ForceSample& s : m_forces) {
      fmt::format_to(std::back_inserter(rows), FMT_COMPILE("{:.6f},{}-{},{:.6e},{:.6e},{:.4f},{}\n"), s.time,
                     lines[m_pairs[s.pair][0]].name, lines[m_pairs[s.pair][1]].name, s.force, s.peakPerLength,
                     s.length, s.patches);
      file.writeRows(rows);
    }
    file.writeRows(rows, true);
    file.close();
  }
  core::OutputFile summary(out / "summary.json");
  core::JsonWriter j(summary.stream());
  j.beginObject();
  j.field("model", m_contact->spec().model != model::ImpactModel::Penalty ? "impulse"
                   : m_contact->distributed() ? "distributed penalty with barrier + hysteresis"
                                              : "penalty spring + dashpot");
  j.field("restitution", m_contact->spec().restitution);
  if (m_contact->distributed()) {
    // Restitution by hysteresis (ContactLaw.hpp HystereticRestitution): loading along (1 + a) f, unloading
    // along (1 - a) f.
    const double a = HystereticRestitution::amplitudeFor(m_contact->spec().restitution);
    j.field("loading_factor", 1.0 + a);
    j.field("unloading_factor", 1.0 - a);
  } else {
    j.field("damping_ratio", m_contact->dampingRatio());
  }
  j.field("clearance_margin_m", m_contact->spec().clearanceMargin);
  j.field("events", static_cast<int>(events.size()));
  j.key("pairs");
  j.beginArray();
  for (int p = 0; p < static_cast<int>(m_pairs.size()); ++p) {
    const int a = m_pairs[p][0], b = m_pairs[p][1];
    std::vector<double> velocity, energy, absorbed, force, impactForce;
    int sustained = 0, doubtful = 0;
    double peakSustained = 0.0, contactTime = 0.0;
    for (const ContactEvent& e : events) {
      if (e.lineA != a || e.lineB != b) continue;
      contactTime += e.endTime - e.startTime;
      if (e.sustained) {
        ++sustained;
        peakSustained = std::max(peakSustained, e.peakForce);
      }
      if (!e.impact) continue;  // the distributions are over impacts only
      velocity.push_back(e.impactVelocity);
      energy.push_back(e.impactEnergy);
      absorbed.push_back(e.phaseWork);
      force.push_back(e.peakForce);
      if (std::isfinite(e.impactPeakForce)) impactForce.push_back(e.impactPeakForce);  // not a jump's
      if (!e.energyWarning.empty()) ++doubtful;
    }
    const ClearanceSample* worst = nullptr;
    for (const ClearanceSample& s : m_samples)
      if (s.pair == p && (!worst || s.clearance < worst->clearance)) worst = &s;
    j.beginObject();
    j.field("line_1", lines[a].name);
    j.field("line_2", lines[b].name);
    j.field("stiffness_N_per_m", m_contact->pairStiffness(a, b));
    j.field("impacts", static_cast<int>(velocity.size()));
    j.field("sustained_contacts", sustained);
    j.field("sustained_peak_force_N", peakSustained);
    j.field("time_in_contact_s", contactTime);
    writeStats(j, "impact_velocity_m_per_s", velocity);
    writeStats(j, "impact_energy_J", energy);
    writeStats(j, "absorbed_energy_J", absorbed);
    j.field("impacts_with_energy_warning", doubtful);
    writeStats(j, "peak_force_N", force);
    writeStats(j, "impact_peak_force_N", impactForce);
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
    // Each event counted once (issue 45: an impact that then stayed in contact was counted as an impact and
    // as a sustained contact): impacts (and how many of them stayed), sustained contacts that began slowly,
    // and brief touches (neither).
    int count = 0, stayed = 0, sustained = 0, brief = 0;
    double vmax = 0.0, emax = 0.0, fmax = 0.0, fimpact = 0.0;
    for (const ContactEvent& e : m_contact->events()) {
      if (e.lineA != a || e.lineB != b) continue;
      fmax = std::max(fmax, e.peakForce);
      if (!e.impact) {
        ++(e.sustained ? sustained : brief);
        continue;
      }
      ++count;
      if (e.sustained) ++stayed;
      vmax = std::max(vmax, e.impactVelocity);
      emax = std::max(emax, e.impactEnergy);
      if (std::isfinite(e.impactPeakForce)) fimpact = std::max(fimpact, e.impactPeakForce);
    }
    // The smallest clearance after the ramp, as the extremes take it (RunOutputs; the ramp's start-up is
    // not the sea state); over the whole run when it ended within the ramp.
    const double ramp = m_model->spec().dynamics.rampTime - 1e-9;
    double minClear = std::numeric_limits<double>::infinity(), minClearRamp = minClear;
    bool afterRamp = false;
    for (const ClearanceSample& c : m_samples) {
      if (c.pair != p) continue;
      minClearRamp = std::min(minClearRamp, c.clearance);
      if (c.time < ramp) continue;
      afterRamp = true;
      minClear = std::min(minClear, c.clearance);
    }
    if (!afterRamp) minClear = minClearRamp;
    // The impacts' maxima only where there were impacts, the contact force only where there was contact.
    const std::string impacts =
        count > 0 ? fmt::format(
                        "; max impact velocity {:.3f} m/s, max impact energy {:.4g} J, max impact "
                        "force {:.4g} kN",
                        vmax, emax, fimpact / 1000.0)
                  : std::string();
    const std::string force =
        count + sustained + brief > 0 ? fmt::format(", max contact force {:.4g} kN", fmax / 1000.0) : "";
    s += fmt::format(
        "  {} / {}: {} impact(s){}, {} sustained contact(s) without an impact, {} brief touch(es){}{}; min "
        "clearance at the output times {} {}\n",
        lines[a].name, lines[b].name, count, stayed > 0 ? fmt::format(" ({} then sustained)", stayed) : "",
        sustained, brief, impacts, force, afterRamp ? "after the ramp" : "(the run ended within the ramp)",
        std::isfinite(minClear) ? fmt::format("{:.3f} m", minClear) : std::string("beyond margin"));
  }
  for (const ContactEvent& e : m_contact->events())
    if (!e.energyWarning.empty())
      s += fmt::format(
          "  warning: impact of {} / {} at t = {:.3f} s: {} (contact/events.csv; docs/theory.md 9.10)\n",
          lines[e.lineA].name, lines[e.lineB].name, e.startTime, e.energyWarning);
  return s;
}

}  // namespace tangle::contact
