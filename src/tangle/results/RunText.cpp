#include "tangle/results/RunText.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "tangle/core/Units.hpp"
#include "tangle/hydro/CurrentGrid.hpp"

namespace tangle::results {

namespace {

const char* endKindName(model::EndKind k) {
  switch (k) {
    case model::EndKind::Anchored:
      return "anchored";
    case model::EndKind::Fixed:
      return "fixed";
    case model::EndKind::Pinned:
      return "pinned";
    case model::EndKind::Free:
      return "free";
    case model::EndKind::Vessel:
      return "vessel";
    case model::EndKind::Point:
      return "point";
  }
  return "?";
}

const char* waveStretchingName(model::WaveStretching s) {
  switch (s) {
    case model::WaveStretching::None:
      return "none";
    case model::WaveStretching::Wheeler:
      return "wheeler";
    case model::WaveStretching::Extrapolation:
      return "vertical_extrapolation";
  }
  return "?";
}

}  // namespace

std::string modelSummary(const model::Model& m) {
  std::string out;
  const auto& env = m.environment();
  const model::ModelSpec& spec = m.spec();
  out += fmt::format("model: {}\n", spec.sourceFile);
  if (!spec.title.empty()) out += fmt::format("title: {}\n", spec.title);
  out += fmt::format("environment: water depth {:.1f} m, water density {:.1f} kg/m3, gravity {:.5f} m/s2\n",
                     env.waterDepth, env.waterDensity, env.gravity);
  if (!m.seabedSurface().isFlat()) out += fmt::format("seabed: {}\n", m.seabedSurface().describe());
  const model::WaveSpec& w = env.waves;
  switch (w.kind) {
    case model::WaveKind::None:
      out += "waves: none\n";
      break;
    case model::WaveKind::Airy:
      out += fmt::format(
          "waves: regular (Airy), H = {:.2f} m, T = {:.2f} s, towards {:.1f} deg, stretching {}\n", w.height,
          w.period, radToDeg(w.azimuth), waveStretchingName(w.stretching));
      break;
    case model::WaveKind::Jonswap:
      out += fmt::format(
          "waves: JONSWAP, Hs = {:.2f} m, Tp = {:.2f} s, gamma {:.2f}, {} components (seed {}), "
          "towards {:.1f} deg, stretching {}\n",
          w.significantHeight, w.peakPeriod, w.gamma, w.components, w.seed, radToDeg(w.azimuth),
          waveStretchingName(w.stretching));
      break;
    case model::WaveKind::Components: {
      double m0 = 0.0;
      for (const auto& c : w.componentTable) m0 += 0.5 * c[1] * c[1];
      out += fmt::format("waves: {} given components, Hs = 4 sqrt(m0) = {:.2f} m, stretching {}\n",
                         w.componentTable.size(), 4.0 * std::sqrt(m0), waveStretchingName(w.stretching));
      break;
    }
  }
  if (env.currentGrid) {
    const hydro::CurrentGrid& g = *env.currentGrid;
    out += fmt::format(
        "current: a grid of {} x {} x {} points at {} time(s), x {:.1f} to {:.1f} m, y {:.1f} to {:.1f} m, z "
        "{:.1f} "
        "to {:.1f} m, t to {:.1f} s\n",
        g.ticks(0).size(), g.ticks(1).size(), g.ticks(2).size(), g.ticks(3).size(), g.ticks(0).front(),
        g.ticks(0).back(), g.ticks(1).front(), g.ticks(1).back(), g.ticks(2).front(), g.ticks(2).back(),
        g.ticks(3).back());
  } else if (env.current.empty()) {
    out += "current: none\n";
  } else {
    out += fmt::format("current: {} level(s):", env.current.size());
    for (const model::CurrentLevel& c : env.current)
      out += fmt::format(" z = {:.1f} m: {:.2f} m/s towards {:.1f} deg;", c.z, c.speed, radToDeg(c.azimuth));
    out.back() = '\n';
    if (env.currentHistory.size() > 1)
      out += fmt::format("  (at t = 0: it changes in time, {} profiles to t = {:.1f} s)\n",
                         env.currentHistory.size(), env.currentHistory.back().time);
  }
  if (env.windSpeed > 0.0)
    out += fmt::format("wind: {:.2f} m/s towards {:.1f} deg\n", env.windSpeed, radToDeg(env.windAzimuth));
  // The mass only where it acts (a free vessel): a fixed or prescribed one read "mass 0.0 t".
  for (const model::VesselSpec& v : spec.vessels)
    out += fmt::format(
        "  vessel '{}': {}, at ({:.1f}, {:.1f}, {:.1f}) m, heading {:.1f} deg{}{}\n", v.name,
        model::vesselModeName(v.mode), v.position.x(), v.position.y(), v.position.z(), radToDeg(v.heading),
        v.mode == model::VesselMode::Free ? fmt::format(", mass {:.1f} t", v.mass / 1000.0) : "",
        v.heldInStatics ? ", held in statics" : "");
  int beams = 0;
  for (const auto& el : m.elements()) beams += el.isBeam() ? 1 : 0;
  out +=
      fmt::format("{} line(s), {} elements ({} beam, {} bar), {} nodes, {} DOFs ({} free)\n",
                  m.lines().size(), m.elements().size(), beams, static_cast<int>(m.elements().size()) - beams,
                  m.nodeCount(), m.dofs().fullDofCount(), m.dofs().equationCount());
  for (int i = 0; i < static_cast<int>(m.lines().size()); ++i) {
    const model::Line& line = m.lines()[i];
    double weight = 0.0, contents = 0.0;
    for (int e = 0; e < line.elementCount; ++e) {
      const auto& el = m.elements()[line.firstElement + e];
      weight += el.type->submergedWeight(env.waterDensity, env.gravity) * el.restLength;
      contents += el.type->contentsMassPerLength() * el.restLength;
    }
    const std::string withContents = contents > 0.0 ? fmt::format(" (contents {:.1f} t)", contents / 1000.0) : "";
    out += fmt::format(
        "  line '{}': length {:.2f} m, {} sections, {} elements, mass {:.1f} t{}, submerged weight "
        "{:.1f} kN, end A {}, end B {}\n",
        line.name, line.length, line.spec->sections.size(), line.elementCount, m.lineMass(i) / 1000.0,
        withContents, weight / 1000.0, endKindName(line.spec->endA.kind), endKindName(line.spec->endB.kind));
    if (line.pipe && (line.spec->contents.pressure != 0.0 || contents > 0.0))
      out += fmt::format("    contents: internal pressure {:.2f} MPa at z = {:.2f} m (gauge)\n",
                         line.spec->contents.pressure / 1e6, line.contentsReferenceZ);
  }
  if (!spec.contact.enabled) {
    out += "contact: off\n";
  } else if (spec.contact.pairs.empty()) {
    // What "every pair" means here: the lines that take part, and what the model excludes.
    std::size_t taking = 0;
    for (const model::LineSpec& line : spec.lines) taking += line.contact ? 1 : 0;
    std::string except;
    for (const auto& [a, b] : spec.contact.exclude) except += fmt::format("{}{}-{}", except.empty() ? "" : ", ", a, b);
    out += fmt::format(
        "contact: every pair of {}{}{}{}{}, restitution {:.2f}\n",
        taking == spec.lines.size() ? "lines" : fmt::format("the {} lines of {} that take part", taking, spec.lines.size()),
        spec.contact.selfContact ? " and each line with itself" : "", except.empty() ? "" : ", except " + except,
        spec.contact.exclusionZones.empty() ? ""
                                            : fmt::format(", {} exclusion zone(s)", spec.contact.exclusionZones.size()),
        spec.contact.excludeConnections ? "" : ", connections not excluded", spec.contact.restitution);
  } else {
    out += fmt::format("contact: {} pair(s):", spec.contact.pairs.size());
    for (const auto& [a, b] : spec.contact.pairs) out += fmt::format(" {}-{};", a, b);
    out.back() = '\n';
  }
  const auto& d = spec.dynamics;
  if (d.enabled)
    out += fmt::format("dynamics: {:.2f} s at dt = {:.4g} s, output every {:.4g} s\n", d.duration, d.timeStep,
                       d.outputInterval);
  if (const model::FatigueSpec& f = spec.fatigue; f.enabled) {
    out += "fatigue:";
    for (const model::FatigueSectionSpec& s : f.sections)
      out += fmt::format(" {} ({} curve '{}'{});", s.lineType, s.tensionCurve ? "T-N" : "S-N", s.curve,
                         s.tensionCurve ? "" : fmt::format(", SCF {:g}, {} points", s.stressConcentration, s.points));
    out.back() = '\n';
    out += fmt::format("  counted from t = {:g} s, occurrence {:g} of a year, design factor {:g}\n",
                       f.startTime >= 0.0 ? f.startTime : d.rampTime, f.occurrence, f.designFactor);
  }
  return out;
}

std::string warningText(const model::ModelSpec& spec) {
  std::string out;
  for (const std::string& w : spec.warnings) out += "warning: " + w + "\n";
  return out;
}

BreakingLoadUse breakingLoadUse(const model::Model& m, std::size_t lineIndex, const std::vector<double>& nodeTension) {
  BreakingLoadUse use;
  const model::Line& line = m.lines()[lineIndex];
  for (int i = 0; i < line.nodeCount && i < static_cast<int>(nodeTension.size()); ++i) {
    double mbl = 0.0;
    int weaker = -1;  // the element whose MBL it is: its line type is the one named
    for (const int e : {i - 1, i}) {
      if (e < 0 || e >= line.elementCount) continue;
      const double b = m.elements()[static_cast<std::size_t>(line.firstElement + e)].type->minimumBreakingLoad;
      if (b > 0.0 && (mbl == 0.0 || b < mbl)) {
        mbl = b;
        weaker = e;
      }
    }
    if (mbl <= 0.0) continue;
    const double ratio = nodeTension[static_cast<std::size_t>(i)] / mbl;
    if (ratio > use.ratio) {
      use.ratio = ratio;
      use.arc = line.arcLength[static_cast<std::size_t>(i)];
      use.tension = nodeTension[static_cast<std::size_t>(i)];
      use.mbl = mbl;
      use.lineType = m.elements()[static_cast<std::size_t>(line.firstElement + weaker)].type->name;
    }
  }
  return use;
}

std::string breakingLoadWarnings(const model::Model& m, const std::vector<BreakingLoadUse>& use, const std::string& when) {
  std::string out;
  for (std::size_t l = 0; l < use.size(); ++l)
    if (use[l].ratio > 1.0)
      out += fmt::format(
          "warning: line '{}': effective tension {:.1f} kN at {:.1f} m from end A {} exceeds the minimum breaking "
          "load of line type '{}' ({:.1f} kN, {:.0f} %)\n",
          m.lines()[l].name, use[l].tension / 1000.0, use[l].arc, when, use[l].lineType, use[l].mbl / 1000.0,
          100.0 * use[l].ratio);
  return out;
}

std::string strainWarnings(const model::Model& m, const std::vector<solver::LineSnapshot>& lines) {
  std::string out;
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const model::Line& line = m.lines()[l];
    // The element furthest beyond its line type's limit (strain over limit), if any.
    double worst = 1.0, strainThere = 0.0, where = 0.0;
    const section::LineType* type = nullptr;
    for (int e = 0; e < line.elementCount; ++e) {
      const auto& el = m.elements()[line.firstElement + e];
      const double t = 0.5 * (lines[l].tension[e] + lines[l].tension[e + 1]);
      const double strain = t / el.type->axialStiffness;
      const double over = strain / el.type->strainWarningLimit();
      if (over > worst) {
        worst = over;
        strainThere = strain;
        type = el.type;
        where = 0.5 * (line.arcLength[e] + line.arcLength[e + 1]);
      }
    }
    if (type)
      out += fmt::format(
          "warning: line '{}': axial strain {:.2f} % at {:.1f} m from end A, above {:.2g} % ({} of line type "
          "'{}'): check the line length against the distance between its ends, and axial_stiffness\n",
          line.name, 100.0 * strainThere, where, 100.0 * type->strainWarningLimit(),
          type->maximumStrain > 0.0 ? "the maximum_strain"
                                    : (type->isBeam() ? "the default for a beam" : "the default for a cable"),
          type->name);
  }
  return out;
}

std::string tensionerText(const model::Model& m,
                          const std::vector<vessel::VesselSystem::TensionerReading>& readings) {
  std::string out;
  for (const auto& r : readings) {
    const bool onStop = std::abs(r.stroke) > r.halfStroke;
    out += fmt::format(
        "  tensioner of line '{}' end {}: stroke {:+.3f} m of +-{:.3f} m, force {:.1f} kN{}\n",
        m.lines()[r.line].name, r.end == 0 ? 'A' : 'B', r.stroke, r.halfStroke, r.force / 1000.0,
        onStop ? fmt::format(", ON ITS END STOP (stop force {:.1f} kN)", r.stopForce / 1000.0) : "");
  }
  return out;
}

}  // namespace tangle::results
