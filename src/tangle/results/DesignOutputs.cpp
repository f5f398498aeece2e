#include "tangle/results/DesignOutputs.hpp"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

#include "tangle/analysis/ExtremeStatistics.hpp"
#include "tangle/core/Csv.hpp"
#include "tangle/core/OutputFile.hpp"
#include "tangle/io/ResultWriter.hpp"

namespace tangle::results {

namespace fs = std::filesystem;

namespace {

/// The columns of an extreme estimate, each after a comma: mean, sd, Tz, peaks, largest (whenever there are
/// samples), then the Rayleigh sigma and MPM and the Weibull scale, shape and MPM only where the fit is
/// credible (ExtremeEstimate::credible), and a note that says why they are empty otherwise. The values are
/// times `sign` (-1: the statistics of a minimum, tracked as the peaks of -x). Always 11 fields
/// (issue 45: an absent fit dropped a field and shifted the largest value into the peaks column).
std::string estimateFields(const analysis::ExtremeEstimate& e, long samples, double sign = 1.0) {
  std::string out;
  const auto field = [&](const std::string& text) { out += "," + text; };
  const bool any = samples > 0;
  const bool moments = any && e.peaks.upcrossingPeriod > 0.0;
  field(any ? fmt::format("{:.6e}", sign * e.peaks.mean) : "");
  field(any ? fmt::format("{:.6e}", e.peaks.standardDeviation) : "");
  field(moments ? fmt::format("{:.6f}", e.peaks.upcrossingPeriod) : "");
  field(any ? fmt::format("{}", e.peaks.peaks.size()) : "");
  field(any ? fmt::format("{:.6e}", sign * e.maximum) : "");
  const bool fit = e.credible();
  field(fit ? fmt::format("{:.6e}", e.rayleigh.scale / std::sqrt(2.0)) : "");
  field(fit ? fmt::format("{:.6e}", sign * e.rayleighMpm) : "");
  field(fit ? fmt::format("{:.6e}", e.weibull.scale) : "");
  field(fit ? fmt::format("{:.6f}", e.weibull.shape) : "");
  field(fit ? fmt::format("{:.6e}", sign * e.weibullMpm) : "");
  field(core::csvField(any ? e.doubt : std::string("no samples")));
  return out;
}

/// The 11 fields of a quantity the line does not have (the bending moment of a cable): ten empty, and why.
std::string absentFields(const std::string& why) { return std::string(11, ',') + core::csvField(why); }

/// "; no storm extreme: why" for an estimate that is not credible, else "".
std::string roughness(const analysis::ExtremeEstimate& e) {
  return e.credible() ? std::string() : "; no storm extreme: " + e.doubt;
}

/// The header of estimateFields; `minimum`: the columns of a minimum (min, most probable minimum "mp_min").
std::string estimateHeader(const std::string& prefix, const std::string& unit, bool minimum = false) {
  return fmt::format(
      ",{0}mean_{1},{0}standard_deviation_{1},{0}upcrossing_period_s,{0}peaks,{0}{2}_{1},"
      "{0}rayleigh_sigma_{1},{0}rayleigh_{3}_{1},{0}weibull_scale_{1},{0}weibull_shape,{0}weibull_{3}_{1},"
      "{0}note",
      prefix, unit, minimum ? "min" : "max", minimum ? "mp_min" : "mpm");
}

}  // namespace

std::string writeExtremeStatistics(const fs::path& dir, const model::Model& model,
                                   const std::vector<solver::LineSnapshot>& lines,
                                   const analysis::ResponseStatistics& statistics,
                                   const std::vector<analysis::PeakTracker>& offsets,
                                   const std::vector<std::array<int, 2>>& pairs,
                                   const std::vector<analysis::PeakTracker>& clearance, double storm) {
  std::string text;
  // Without a single credible fit the log says so once, and whether the run is a transient (a drift, a
  // release, an accident: a line end's tension not stationary), and lists the largest values seen, not
  // every item's reason (the files keep them, item by item).
  bool anyCredible = false, transient = false;
  std::string largest;
  // Line ends (the fairlead and anchor tensions of DNV-OS-E301 and API RP 2SK).
  {
    core::OutputFile out(dir / "dynamics" / "statistics.csv");
    out.write("line,end,samples,duration_s,storm_duration_s" + estimateHeader("", "N") + "\n");
    for (std::size_t l = 0; l < lines.size(); ++l) {
      const analysis::ResponseStatistics::Line& t = statistics.lines()[l];
      const analysis::PeakTracker* trackers[2] = {&t.endA, &t.endB};
      analysis::ExtremeEstimate estimates[2];
      for (int end = 0; end < 2; ++end) {
        const analysis::PeakTracker& tracker = *trackers[end];
        estimates[end] = analysis::extremeEstimate(tracker, storm);
        out.write(fmt::format("{},{},{},{:.6f},{:.1f}", core::csvField(lines[l].name), end == 0 ? 'A' : 'B',
                              tracker.samples(), tracker.duration(), storm) +
                  estimateFields(estimates[end], tracker.samples()) + "\n");
      }
      // The log names the end with the larger tension: the fairlead or hang-off, whichever end a model puts
      // it at (tangle's examples at end B, OrcaFlex's convention at end A).
      const bool endA = trackers[0]->samples() > 0 &&
                        (trackers[1]->samples() == 0 || estimates[0].maximum > estimates[1].maximum);
      const analysis::PeakTracker& tracker = *trackers[endA ? 0 : 1];
      const analysis::ExtremeEstimate& e = estimates[endA ? 0 : 1];
      const char name = endA ? 'A' : 'B';
      if (tracker.samples() > 0) {
        largest += fmt::format("  line '{}' end {}: {:.1f} kN\n", lines[l].name, name, e.maximum / 1000.0);
        transient = transient || e.transient();
      }
      if (e.credible()) {
        anyCredible = true;
        text += fmt::format(
            "  line '{}' end {}: {} peaks (Tz {:.2f} s), most probable maximum of a {:.1f} h storm "
            "{:.1f} kN (Rayleigh) / {:.1f} kN (Weibull, shape {:.2f}); largest in the run {:.1f} kN\n",
            lines[l].name, name, e.peaks.peaks.size(), e.peaks.upcrossingPeriod, storm / 3600.0,
            e.rayleighMpm / 1000.0, e.weibullMpm / 1000.0, e.weibull.shape, e.maximum / 1000.0);
      } else if (tracker.samples() > 0)
        text += fmt::format("  line '{}' end {}: largest in the run {:.1f} kN; no storm extreme: {}\n",
                            lines[l].name, name, e.maximum / 1000.0, e.doubt);
    }
    out.close();
  }
  // Along every line: the range graph's statistical counterpart.
  const std::vector<std::string> stems = io::lineFileStems(lines);
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const analysis::ResponseStatistics::Line& t = statistics.lines()[l];
    fs::create_directories(dir / "dynamics" / stems[l]);
    core::OutputFile out(dir / "dynamics" / stems[l] / "statistics.csv");
    out.write("arc_length_m" + estimateHeader("tension_", "N") + estimateHeader("moment_", "Nm") + "\n");
    // The log names the largest most probable maxima among the credible fits only.
    double worstTension = 0.0, worstMoment = 0.0, tensionAt = 0.0, momentAt = 0.0;
    for (std::size_t i = 0; i < t.tension.size(); ++i) {
      const analysis::ExtremeEstimate te = analysis::extremeEstimate(t.tension[i], storm);
      std::string row =
          fmt::format("{:.4f}", lines[l].arcLength[i]) + estimateFields(te, t.tension[i].samples());
      if (te.credible() && te.weibullMpm > worstTension) {
        worstTension = te.weibullMpm;
        tensionAt = lines[l].arcLength[i];
      }
      if (t.moment.empty()) {
        row += absentFields("a line without bending stiffness");
      } else {
        const analysis::ExtremeEstimate me = analysis::extremeEstimate(t.moment[i], storm);
        row += estimateFields(me, t.moment[i].samples());
        if (me.credible() && me.weibullMpm > worstMoment) {
          worstMoment = me.weibullMpm;
          momentAt = lines[l].arcLength[i];
        }
      }
      out.write(row + "\n");
    }
    out.close();
    if (worstTension > 0.0 || worstMoment > 0.0) anyCredible = true;
    if (worstTension == 0.0 && worstMoment == 0.0)
      text += fmt::format(
          "  line '{}' along its length: no storm extreme at any node (dynamics/{}/statistics.csv says "
          "why, node by node)\n",
          lines[l].name, stems[l]);
    else
      text += fmt::format(
          "  line '{}' along its length: most probable maximum tension {} at {:.1f} m{} "
          "(Weibull, where the fit is credible; dynamics/{}/statistics.csv)\n",
          lines[l].name, worstTension > 0.0 ? fmt::format("{:.1f} kN", worstTension / 1000.0) : "-",
          tensionAt,
          worstMoment > 0.0
              ? fmt::format(", bending moment {:.2f} kN m at {:.1f} m", worstMoment / 1000.0, momentAt)
              : std::string(),
          stems[l]);
  }
  if (!offsets.empty()) {
    core::OutputFile out(dir / "dynamics" / "vessel_statistics.csv");
    out.write("vessel,samples,duration_s,storm_duration_s" + estimateHeader("offset_", "m") + "\n");
    for (std::size_t v = 0; v < offsets.size(); ++v) {
      const analysis::ExtremeEstimate e = analysis::extremeEstimate(offsets[v], storm);
      out.write(fmt::format("{},{},{:.6f},{:.1f}", core::csvField(model.vessels()[v].name),
                            offsets[v].samples(), offsets[v].duration(), storm) +
                estimateFields(e, offsets[v].samples()) + "\n");
      if (offsets[v].samples() > 0)
        largest += fmt::format("  vessel '{}': offset {:.2f} m\n", model.vessels()[v].name, e.maximum);
      anyCredible = anyCredible || e.credible();
      if (e.credible())
        text += fmt::format(
            "  vessel '{}': most probable maximum offset {:.2f} m (Weibull), largest in the run {:.2f} m\n",
            model.vessels()[v].name, e.weibullMpm, e.maximum);
      else if (offsets[v].samples() > 0)
        text += fmt::format("  vessel '{}': largest offset in the run {:.2f} m{}\n", model.vessels()[v].name,
                            e.maximum, roughness(e));
    }
    out.close();
  }
  if (!pairs.empty()) {
    // The minimum clearance: the peaks of minus the clearance, reported with their sign turned back.
    fs::create_directories(dir / "contact");
    core::OutputFile out(dir / "contact" / "clearance_statistics.csv");
    out.write("line_1,line_2,samples,duration_s,storm_duration_s" + estimateHeader("clearance_", "m", true) +
              "\n");
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      const analysis::ExtremeEstimate e = analysis::extremeEstimate(clearance[p], storm);
      const std::string& a = model.lines()[static_cast<std::size_t>(pairs[p][0])].name;
      const std::string& b = model.lines()[static_cast<std::size_t>(pairs[p][1])].name;
      out.write(fmt::format("{},{},{},{:.6f},{:.1f}", core::csvField(a), core::csvField(b),
                            clearance[p].samples(), clearance[p].duration(), storm) +
                estimateFields(e, clearance[p].samples(), -1.0) + "\n");
      const double margin = model.spec().contact.clearanceMargin;
      // Beyond the margin the clearance is recorded as the margin (RunOutputs): not a clearance to report.
      const bool beyondMargin = -e.maximum >= margin * (1.0 - 1e-12);
      anyCredible = anyCredible || e.credible();
      if (clearance[p].samples() > 0 && !beyondMargin)
        largest += fmt::format(
            "  lines '{}' / '{}': smallest clearance at the output times after the ramp {:.3f} m\n", a, b,
            -e.maximum);
      if (clearance[p].samples() > 0 && beyondMargin)
        text +=
            fmt::format("  lines '{}' / '{}': never within the clearance margin ({:g} m)\n", a, b, margin);
      else if (e.credible())
        text += fmt::format(
            "  lines '{}' / '{}': most probable minimum clearance {:.3f} m (Weibull), smallest at the "
            "output times after the ramp {:.3f} m\n",
            a, b, -e.weibullMpm, -e.maximum);
      else if (clearance[p].samples() > 0)
        text += fmt::format(
            "  lines '{}' / '{}': smallest clearance at the output times after the ramp {:.3f} m{}\n", a, b,
            -e.maximum, roughness(e));
    }
    out.close();
  }
  if (text.empty()) return {};
  if (!anyCredible)
    return fmt::format(
               "extreme statistics (dynamics/statistics.csv): none: {}; each file says why, item by item. "
               "The "
               "largest values in the run:\n",
               transient
                   ? "the run is a transient, not a stationary storm (a drift, a release, an accident: the "
                     "mean of a line end's tension moves between the record's halves)"
                   : "no record of the run gives a credible fit (too few peaks, a Weibull shape out of "
                     "range, or a steady response)") +
           largest;
  return "extreme statistics (dynamics/statistics.csv):\n" + text;
}

std::string writeFatigue(const fs::path& dir, const model::Model& model,
                         const analysis::FatigueDamage& fatigue,
                         const std::vector<analysis::FatigueDamage::Line>& damage) {
  if (damage.empty()) return {};
  const model::FatigueSpec& spec = model.spec().fatigue;
  const double factor = fatigue.annualFactor();
  std::vector<std::string> names;
  for (const model::Line& l : model.lines()) names.push_back(l.name);
  const std::vector<std::string> stems = io::uniqueFileStems(names);
  const auto number = [](double v) {
    return std::isfinite(v) ? fmt::format("{:.6e}", v) : std::string("inf");
  };
  std::string text = fmt::format(
      "fatigue (fatigue/): {:.1f} s counted from t = {:.1f} s, scaled to a year by occurrence {:g}, design "
      "factor {:g}\n",
      fatigue.countedDuration(), fatigue.firstCountedTime(), spec.occurrence, spec.designFactor);
  fs::create_directories(dir / "fatigue");
  core::OutputFile summary(dir / "fatigue" / "summary.csv");
  summary.write(
      "line,arc_length_m,line_type,curve,damage_run,damage_per_year,life_years,counted_duration_s,occurrence,"
      "design_factor\n");
  for (const analysis::FatigueDamage::Line& line : damage) {
    core::OutputFile out(dir / "fatigue" / (stems[static_cast<std::size_t>(line.line)] + ".csv"));
    out.write(
        "arc_length_m,line_type,curve,damage_run,damage_per_year,life_years,cycles,largest_stress_range_MPa,"
        "largest_tension_range_kN,worst_point_deg\n");
    const analysis::FatigueDamage::Node* worst = nullptr;
    for (const analysis::FatigueDamage::Node& n : line.nodes) {
      out.write(fmt::format("{:.4f},{},{},{:.6e},{},{},{:.1f},{},{},{:.1f}\n", n.arcLength,
                            core::csvField(n.lineType), n.tension ? "T-N" : "S-N", n.damage,
                            number(n.damage * factor), number(fatigue.life(n.damage)), n.cycles,
                            n.tension ? "" : fmt::format("{:.6g}", n.largestRange / 1e6),
                            n.tension ? fmt::format("{:.6g}", n.largestRange / 1e3) : "", n.worstAngle));
      if (!worst || n.damage > worst->damage) worst = &n;
    }
    out.close();
    summary.write(fmt::format("{},{:.4f},{},{},{:.6e},{},{},{:.6f},{:g},{:g}\n", core::csvField(line.name),
                              worst->arcLength, core::csvField(worst->lineType),
                              worst->tension ? "T-N" : "S-N", worst->damage, number(worst->damage * factor),
                              number(fatigue.life(worst->damage)), fatigue.countedDuration(), spec.occurrence,
                              spec.designFactor));
    text += fmt::format(
        "  line '{}': shortest life {} years at {:.1f} m from end A (line type '{}', {}{}), "
        "damage {:.3e} per year\n",
        line.name, fmt::format("{:.4g}", fatigue.life(worst->damage)), worst->arcLength, worst->lineType,
        worst->tension ? fmt::format("largest tension range {:.1f} kN", worst->largestRange / 1e3)
                       : fmt::format("largest stress range {:.1f} MPa", worst->largestRange / 1e6),
        worst->tension ? "" : fmt::format(" at the point at {:.0f} deg", worst->worstAngle),
        worst->damage * factor);
  }
  summary.close();
  return text;
}

std::string writeClashDamage(const fs::path& dir, const model::Model& model,
                             const std::vector<analysis::LineClashDamage>& damage, double energyThreshold) {
  fs::create_directories(dir / "contact");
  core::OutputFile out(dir / "contact" / "clash_damage.csv");
  out.write(fmt::format(
      "line,from_m,to_m,impacts,impacts_above_{:g}_J,energy_J,largest_energy_J,largest_velocity_m_s\n",
      energyThreshold));
  std::string text;
  std::string rows;  // a row per bin of every line, by compiled formats (OutputFile::writeRows)
  for (const analysis::LineClashDamage& d : damage) {
    const std::string& name = model.lines()[static_cast<std::size_t>(d.line)].name;
    const std::string field = core::csvField(name);
    const analysis::ClashDamageBin* worst = nullptr;
    int above = 0;
    for (const analysis::ClashDamageBin& b : d.bins) {
      fmt::format_to(std::back_inserter(rows), FMT_COMPILE("{},{:.4f},{:.4f},{},{},{:.6e},{:.6e},{:.6e}\n"),
                     field, b.from, b.to, b.impacts, b.impactsAbove, b.energy, b.largestEnergy,
                     b.largestVelocity);
      out.writeRows(rows);
      if (b.impacts > 0 && (!worst || b.energy > worst->energy)) worst = &b;
      above += b.impactsAbove;
    }
    if (worst)
      text += fmt::format(
          "  line '{}': {} impacts ({} above {:g} J); most energy {:.4g} J in {} impacts at {:.1f}-{:.1f} "
          "m\n",
          name, d.impacts(), above, energyThreshold, worst->energy, worst->impacts, worst->from, worst->to);
  }
  out.writeRows(rows, true);
  out.close();
  return text.empty() ? std::string() : "clash damage (contact/clash_damage.csv):\n" + text;
}

}  // namespace tangle::results
