#include "tangle/analysis/FatigueDamage.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tangle/core/Units.hpp"

namespace tangle::analysis {

namespace {
constexpr double kSecondsPerYear = 365.25 * 86400.0;
}

FatigueDamage::FatigueDamage(const model::Model& model) : m_model(&model) {
  const model::ModelSpec& spec = model.spec();
  const model::FatigueSpec& f = spec.fatigue;
  if (!f.enabled) return;
  m_startTime = f.startTime >= 0.0 ? f.startTime : spec.dynamics.rampTime;
  for (const model::FatigueSectionSpec& fs : f.sections) {
    Section s;
    s.lineType = fs.lineType;
    s.tension = fs.tensionCurve;
    if (s.tension) {
      const auto& curve = *std::find_if(f.tnCurves.begin(), f.tnCurves.end(),
                                        [&](const model::TnCurveSpec& c) { return c.name == fs.curve; });
      s.tn.m = curve.m;
      s.tn.aD = curve.intercept;
      s.tn.stressBased = curve.stressBased;
      s.tn.breakingStrength = fs.breakingStrength;
      s.tn.nominalArea = fs.nominalArea;
    } else {
      const auto& curve = *std::find_if(f.snCurves.begin(), f.snCurves.end(),
                                        [&](const model::SnCurveSpec& c) { return c.name == fs.curve; });
      s.sn.name = curve.name;
      s.sn.m1 = curve.m1;
      s.sn.logA1 = curve.logA1;
      s.sn.m2 = curve.m2;
      s.sn.logA2 = curve.logA2;
      s.sn.kneeCycles = curve.kneeCycles;
      s.sn.thicknessExponent = curve.thicknessExponent;
      s.sn.referenceThickness = curve.referenceThickness;
      s.sn.singleSlope = curve.singleSlope;
      s.sn.thickness = fs.wallThickness;  // DNV-RP-C203 2.4.3: the thickness through which a crack grows
      const double d = fs.outerDiameter, di = d - 2.0 * fs.wallThickness;
      const double steelArea = kPi / 4.0 * (d * d - di * di);
      const double inertia = kPi / 64.0 * (d * d * d * d - di * di * di * di);
      const double radius = fs.innerSurface ? 0.5 * di : 0.5 * d;
      s.axial = fs.stressConcentration / steelArea;
      s.bending = fs.stressConcentration * radius / inertia;
      // Wall tension T_w = T_e + p_i A_i - p_e A_e (Sparks 1984) on this line type's areas, or T_e.
      const section::LineType& type = spec.lineTypes.at(fs.lineType);
      s.wallType = fs.wallTension ? &type : nullptr;
      s.points = type.isBeam() ? fs.points : 1;  // no bending: one stress
    }
    for (int k = 0; k < s.points; ++k) {
      const double theta = 2.0 * kPi * k / s.points;
      s.sinTheta.push_back(std::sin(theta));
      s.cosTheta.push_back(std::cos(theta));
    }
    m_sections.push_back(std::move(s));
  }
  const auto sectionOf = [&](const section::LineType* type) {
    for (std::size_t i = 0; i < m_sections.size(); ++i)
      if (m_sections[i].lineType == type->name) return static_cast<int>(i);
    return -1;
  };
  int histories = 0;
  for (int l = 0; l < static_cast<int>(model.lines().size()); ++l) {
    const model::Line& line = model.lines()[static_cast<std::size_t>(l)];
    for (int i = 0; i < line.nodeCount; ++i) {
      // The line types of the elements on either side of the node (one at the ends).
      int sections[2] = {-1, -1};
      if (i > 0) sections[0] = sectionOf(model.elements()[static_cast<std::size_t>(line.firstElement + i - 1)].type);
      if (i < line.elementCount)
        sections[1] = sectionOf(model.elements()[static_cast<std::size_t>(line.firstElement + i)].type);
      if (sections[1] == sections[0]) sections[1] = -1;
      for (const int s : sections) {
        if (s < 0) continue;
        Station st;
        st.line = l;
        st.node = i;
        st.globalNode = line.firstNode + i;
        st.section = s;
        st.points = m_sections[static_cast<std::size_t>(s)].points;
        st.firstHistory = histories;
        histories += st.points;
        m_stations.push_back(st);
      }
    }
  }
  m_counters.resize(static_cast<std::size_t>(histories));
  m_damage.assign(static_cast<std::size_t>(histories), 0.0);
  m_cycles.assign(static_cast<std::size_t>(histories), 0.0);
  m_largest.assign(static_cast<std::size_t>(histories), 0.0);
}

void FatigueDamage::addCycles(const Section& s, std::size_t history, double range, double count) {
  m_damage[history] += count / (s.tension ? s.tn.cyclesToFailure(range) : s.sn.cyclesToFailure(range));
  m_cycles[history] += count;
  m_largest[history] = std::max(m_largest[history], range);
}

void FatigueDamage::accumulate(const std::vector<solver::LineSnapshot>& lines, const model::State& state) {
  if (m_stations.empty() || state.time < m_startTime - 1e-9) return;
  if (!m_started) {
    m_started = true;
    m_firstTime = state.time;
  }
  m_lastTime = state.time;
  const model::EnvironmentSpec& env = m_model->environment();
  const double rhoG = env.waterDensity * env.gravity;
  for (const Station& st : m_stations) {
    const Section& s = m_sections[static_cast<std::size_t>(st.section)];
    const solver::LineSnapshot& snap = lines[static_cast<std::size_t>(st.line)];
    const auto node = static_cast<std::size_t>(st.node);
    const std::size_t first = static_cast<std::size_t>(st.firstHistory);
    const auto sink = [this, &s](std::size_t h) {
      return [this, &s, h](double range, double, double count) { addCycles(s, h, range, count); };
    };
    if (s.tension) {
      m_counters[first].add(snap.tension[node], sink(first));
      continue;
    }
    const Vec3& x = state.position[static_cast<std::size_t>(st.globalNode)];
    const double internal = snap.internalPressure.empty() ? 0.0 : snap.internalPressure[node];
    const double wallTension =
        snap.tension[node] + (s.wallType ? solver::wallTensionPressureTerm(*s.wallType, internal, x.z(), rhoG) : 0.0);
    const double axial = s.axial * wallTension;
    double m2 = 0.0, m3 = 0.0;
    if (st.points > 1) {
      // The moment in the node's material axes (columns 2 and 3 of its triad): the points turn with the
      // section, as its welds do.
      const Mat3& q = state.triad[static_cast<std::size_t>(st.globalNode)];
      const Vec3& moment = snap.bendingMomentVector[node];
      m2 = moment.dot(q.col(1));
      m3 = moment.dot(q.col(2));
    }
    for (int k = 0; k < st.points; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      // sigma = (M x n) . e / I r with n = cos t q2 + sin t q3, e = q1: M . (n x e) = M2 sin t - M3 cos t.
      const double stress = axial + s.bending * (m2 * s.sinTheta[kk] - m3 * s.cosTheta[kk]);
      m_counters[first + kk].add(stress, sink(first + kk));
    }
  }
}

std::vector<FatigueDamage::Line> FatigueDamage::finish() {
  std::vector<Line> out;
  for (const Station& st : m_stations) {
    const Section& s = m_sections[static_cast<std::size_t>(st.section)];
    // The worst point of this station.
    int worst = 0;
    for (int k = 0; k < st.points; ++k) {
      const auto h = static_cast<std::size_t>(st.firstHistory + k);
      m_counters[h].finish([&](double range, double, double count) { addCycles(s, h, range, count); });
      if (m_damage[h] > m_damage[static_cast<std::size_t>(st.firstHistory + worst)]) worst = k;
    }
    const auto h = static_cast<std::size_t>(st.firstHistory + worst);
    Node n;
    n.node = st.node;
    n.arcLength = m_model->lines()[static_cast<std::size_t>(st.line)].arcLength[static_cast<std::size_t>(st.node)];
    n.lineType = s.lineType;
    n.tension = s.tension;
    n.damage = m_damage[h];
    n.cycles = m_cycles[h];
    n.largestRange = m_largest[h];
    n.worstAngle = 360.0 * worst / st.points;
    if (out.empty() || out.back().line != st.line) {
      Line line;
      line.line = st.line;
      line.name = m_model->lines()[static_cast<std::size_t>(st.line)].name;
      out.push_back(std::move(line));
    }
    std::vector<Node>& nodes = out.back().nodes;
    if (!nodes.empty() && nodes.back().node == st.node) {  // the second section at a junction: the worse
      if (n.damage > nodes.back().damage) nodes.back() = n;
    } else {
      nodes.push_back(n);
    }
  }
  return out;
}

double FatigueDamage::annualFactor() const {
  const double duration = countedDuration();
  if (!(duration > 0.0)) return 0.0;
  return m_model->spec().fatigue.occurrence * kSecondsPerYear / duration;
}

double FatigueDamage::life(double damage) const {
  const double annual = damage * annualFactor() * m_model->spec().fatigue.designFactor;
  return annual > 0.0 ? 1.0 / annual : std::numeric_limits<double>::infinity();
}

}  // namespace tangle::analysis
