// Fatigue damage along lines (analysis/FatigueDamage) and clash damage (analysis/ClashDamage), issue 32,
// each against a hand computation: the stress of a steel pipe section from its bending moment (sigma = M r
// / I) and wall tension, the S-N and T-N formulas with the cycles of a constant-amplitude history counted
// by hand, and impacts binned by hand. The histories are fed as a run feeds them (snapshots and states),
// without a solver.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "support/ModelFactory.hpp"
#include "tangle/analysis/ClashDamage.hpp"
#include "tangle/analysis/FatigueDamage.hpp"
#include "tangle/analysis/Rainflow.hpp"
#include "tangle/analysis/SnCurve.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/model/State.hpp"

namespace tangle::analysis {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kD = 0.2731, kT = 0.0159;  // steel pipe OD and wall [m]
constexpr double kScf = 1.2;
constexpr double kPeriod = 10.0;      // s
constexpr int kSamplesPerPeriod = 20;
constexpr int kPeriods = 50;
constexpr double kStart = 30.0;       // fatigue.start_time [s]

/// One straight line of `types` (one 10 m section of 2 elements each) along x at height z, with the fatigue
/// section(s) `sections`.
model::ModelSpec pipeModel(std::vector<std::string> types, std::vector<model::FatigueSectionSpec> sections,
                           double z = 5.0) {
  model::ModelSpec spec;
  spec.sourceFile = "fatigue (test)";
  spec.environment.waterDepth = 100.0;
  spec.lineTypes["pipe"] = test::solidRodType("pipe", kD, 2.07e11, 7850.0);
  spec.lineTypes["other"] = test::solidRodType("other", kD, 2.07e11, 7850.0);
  spec.lineTypes["chain"] = test::cableType("chain", 0.137, 115.0, 5.0e8);
  model::LineSpec l = test::simpleLine("riser", types[0], 10.0, 2, model::EndKind::Pinned, Vec3(0, 0, z),
                                       model::EndKind::Pinned, Vec3(10.0 * static_cast<double>(types.size()), 0, z));
  for (std::size_t i = 1; i < types.size(); ++i) l.sections.push_back({types[i], 10.0, 2});
  spec.lines.push_back(l);
  spec.dynamics.enabled = true;
  spec.dynamics.duration = kStart + kPeriods * kPeriod;
  model::FatigueSpec& f = spec.fatigue;
  f.enabled = true;
  f.startTime = kStart;
  f.occurrence = 0.2;
  f.designFactor = 3.0;
  model::SnCurveSpec e;  // DNV-RP-C203 (2021) Table 2-2, curve E in seawater with cathodic protection
  e.name = "E";
  e.m1 = 3.0;
  e.logA1 = 11.610;
  e.m2 = 5.0;
  e.logA2 = 15.350;
  e.kneeCycles = 1e6;
  e.thicknessExponent = 0.20;
  f.snCurves.push_back(e);
  model::TnCurveSpec api;  // API RP 2SK studless chain
  api.name = "studless";
  api.m = 3.0;
  api.intercept = 316.0;
  f.tnCurves.push_back(api);
  f.sections = std::move(sections);
  return spec;
}

model::FatigueSectionSpec pipeSection(const std::string& type = "pipe") {
  model::FatigueSectionSpec s;
  s.lineType = type;
  s.curve = "E";
  s.outerDiameter = kD;
  s.wallThickness = kT;
  s.stressConcentration = kScf;
  s.points = 16;
  s.wallTension = false;
  return s;
}

/// Feeds `kPeriods` periods of a sine (and one large cycle before the start time, which must not count):
/// `set(snapshot, state, s)` sets the history's value s = sin(2 pi t / T) at every node.
template <class Set>
void feed(const model::Model& m, FatigueDamage& fatigue, Set set) {
  const int nodes = m.lines()[0].nodeCount;
  std::vector<solver::LineSnapshot> lines(1);
  solver::LineSnapshot& snap = lines[0];
  snap.tension.assign(nodes, 1.0e5);
  snap.bendingMomentVector.assign(nodes, Vec3::Zero());
  model::State state;
  state.position.assign(nodes, Vec3(0, 0, 5.0));
  state.triad.assign(nodes, Mat3::Identity());
  // Before the start time: a cycle ten times larger (the ramp's transient).
  for (int k = 0; k <= kSamplesPerPeriod; ++k) {
    state.time = kStart - kPeriod + k * kPeriod / kSamplesPerPeriod - 1.0;
    set(snap, state, 10.0 * std::sin(2.0 * kPi * k / kSamplesPerPeriod));
    fatigue.accumulate(lines, state);
  }
  for (int k = 0; k <= kPeriods * kSamplesPerPeriod; ++k) {
    state.time = kStart + k * kPeriod / kSamplesPerPeriod;
    set(snap, state, std::sin(2.0 * kPi * k / kSamplesPerPeriod));
    fatigue.accumulate(lines, state);
  }
}

// The sine's rainflow count by hand: turning points 0, A, -A, ..., A, -A, 0 (kPeriods maxima and minima):
// 2 kPeriods - 1 ranges 2A are (2 kPeriods - 1) / 2 cycles; 0 -> A and -A -> 0 are half cycles of range A.
// Miner with slope m: damage = ((2 kPeriods - 1) / 2 (2A)^m + 2 x 0.5 A^m) / a.
double sineDamage(double amplitude, double m, double a) {
  return ((2.0 * kPeriods - 1.0) / 2.0 * std::pow(2.0 * amplitude, m) + std::pow(amplitude, m)) / a;
}

TEST(FatigueDamage, BendingStressOfAPipeAgainstMrOverIAndTheSnCurve) {
  const model::Model m(pipeModel({"pipe"}, {pipeSection()}));
  FatigueDamage fatigue(m);
  ASSERT_FALSE(fatigue.empty());
  EXPECT_EQ(fatigue.historyCount(), 3u * 16u);
  const double moment = 6.0e4;  // N m amplitude about the section's axis 2 (global y)
  feed(m, fatigue, [&](solver::LineSnapshot& snap, model::State&, double s) {
    for (Vec3& v : snap.bendingMomentVector) v = Vec3(0, moment * s, 0);
  });
  const std::vector<FatigueDamage::Line> damage = fatigue.finish();
  ASSERT_EQ(damage.size(), 1u);
  ASSERT_EQ(damage[0].nodes.size(), 3u);
  // sigma = SCF M r / I at the outer surface (the constant tension adds no range).
  const double di = kD - 2.0 * kT;
  const double inertia = kPi / 64.0 * (std::pow(kD, 4) - std::pow(di, 4));
  const double amplitudeMPa = kScf * moment * (kD / 2.0) / inertia / 1e6;
  // Curve E above its knee range (74.1 MPa at 1e6 cycles; here A = 92 MPa, 2A = 184 MPa): slope 3 for
  // every range counted; no thickness correction (t = 15.9 mm < t_ref = 25 mm).
  const double expected = sineDamage(amplitudeMPa, 3.0, std::pow(10.0, 11.610));
  for (const FatigueDamage::Node& n : damage[0].nodes) {
    EXPECT_NEAR(n.damage / expected, 1.0, 1e-9);
    EXPECT_NEAR(n.largestRange, 2e6 * amplitudeMPa, 1e-6 * 2e6 * amplitudeMPa);
    EXPECT_DOUBLE_EQ(n.cycles, kPeriods + 0.5);  // 49.5 cycles of 2A and two halves of A
    // The bending stress is largest where the moment about axis 2 bends the fibre on axis 3: 90 or 270
    // degrees (both see the same range).
    EXPECT_TRUE(n.worstAngle == 90.0 || n.worstAngle == 270.0) << n.worstAngle;
    EXPECT_FALSE(n.tension);
  }
  EXPECT_EQ(damage[0].nodes[1].arcLength, 5.0);
  // Annual damage and life: occurrence 0.2 of a year over the counted 500 s; DFF 3.
  EXPECT_NEAR(fatigue.countedDuration(), kPeriods * kPeriod, 1e-9);
  const double perYear = expected * 0.2 * 365.25 * 86400.0 / (kPeriods * kPeriod);
  EXPECT_NEAR(fatigue.annualFactor() * expected / perYear, 1.0, 1e-12);
  EXPECT_NEAR(fatigue.life(expected) * 3.0 * perYear, 1.0, 1e-12);
  EXPECT_EQ(fatigue.life(0.0), std::numeric_limits<double>::infinity());
}

TEST(FatigueDamage, InnerSurfaceAndTheMomentsOtherAxis) {
  model::FatigueSectionSpec s = pipeSection();
  s.innerSurface = true;
  const model::Model m(pipeModel({"pipe"}, {s}));
  FatigueDamage fatigue(m);
  const double moment = 6.0e4;  // A = 81.5 MPa at the inner surface: still above the knee
  feed(m, fatigue, [&](solver::LineSnapshot& snap, model::State&, double v) {
    for (Vec3& x : snap.bendingMomentVector) x = Vec3(0, 0, moment * v);  // about axis 3
  });
  const std::vector<FatigueDamage::Line> damage = fatigue.finish();
  const double di = kD - 2.0 * kT;
  const double inertia = kPi / 64.0 * (std::pow(kD, 4) - std::pow(di, 4));
  const double amplitudeMPa = kScf * moment * (di / 2.0) / inertia / 1e6;
  const double expected = sineDamage(amplitudeMPa, 3.0, std::pow(10.0, 11.610));
  for (const FatigueDamage::Node& n : damage[0].nodes) {
    EXPECT_NEAR(n.damage / expected, 1.0, 1e-9);
    EXPECT_TRUE(n.worstAngle == 0.0 || n.worstAngle == 180.0) << n.worstAngle;
  }
}

TEST(FatigueDamage, WallTensionAddsTheExternalPressureOfAHeavingNode) {
  model::FatigueSectionSpec s = pipeSection();
  s.wallTension = true;
  const model::Model m(pipeModel({"pipe"}, {s}, -50.0));
  FatigueDamage fatigue(m);
  const double heave = 2.0;  // m amplitude of a node at 50 m depth; effective tension constant
  feed(m, fatigue, [&](solver::LineSnapshot&, model::State& state, double v) {
    for (Vec3& x : state.position) x = Vec3(0, 0, -50.0 + heave * v);
  });
  const std::vector<FatigueDamage::Line> damage = fatigue.finish();
  // T_w = T_e - rho g d A_e (A_e of the buoyancy diameter, the pipe's): range 2 rho g heave A_e.
  const double di = kD - 2.0 * kT;
  const double steel = kPi / 4.0 * (kD * kD - di * di);
  const double amplitudeMPa = kScf * 1025.0 * 9.80665 * heave * (kPi / 4.0 * kD * kD) / steel / 1e6;
  // 2A = 1.5 MPa is beyond the knee (74 MPa at 1e6): the second slope, m = 5.
  const double expected = sineDamage(amplitudeMPa, 5.0, std::pow(10.0, 15.350));
  for (const FatigueDamage::Node& n : damage[0].nodes) EXPECT_NEAR(n.damage / expected, 1.0, 1e-9);
}

TEST(FatigueDamage, WallTensionHasBothPressuresWithTheirSigns) {
  // A heaving node with contents and internal pressure, its effective tension rising as it rises:
  // T_w = T_e + p_i A_i - p_e A_e with p_i = p_ref + rho_c g (z_ref - z) and p_e = rho g (-z) (Sparks 1984),
  // so dT_w/dz = dT_e/dz - rho_c g A_i + rho g A_e: the amplitude a + h g (rho A_e - rho_c A_i) for an
  // effective tension amplitude a and a heave h in phase. A wrong sign of either pressure changes it.
  model::FatigueSectionSpec s = pipeSection();
  s.wallTension = true;
  model::ModelSpec spec = pipeModel({"pipe"}, {s}, -50.0);
  const double bore = kD - 2.0 * kT;
  spec.lineTypes["pipe"].internalDiameter = bore;
  spec.lines[0].contents.density = 2000.0;  // a heavy mud: the internal term outweighs the external one
  spec.lines[0].contents.pressure = 3.0e7;
  spec.lines[0].contents.referenceZ = 0.0;
  const model::Model m(std::move(spec));
  FatigueDamage fatigue(m);
  const double heave = 2.0, amplitude = 2.0e4;  // m; N
  feed(m, fatigue, [&](solver::LineSnapshot& snap, model::State& state, double v) {
    for (Vec3& x : state.position) x = Vec3(0, 0, -50.0 + heave * v);
    for (double& t : snap.tension) t = 1.0e5 + amplitude * v;
    m.internalPressure(0, state.position, snap.internalPressure);
  });
  const std::vector<FatigueDamage::Line> damage = fatigue.finish();
  const double g = 9.80665;
  const double ai = kPi / 4.0 * bore * bore, ae = kPi / 4.0 * kD * kD;
  const double wallAmplitude = amplitude + heave * g * (1025.0 * ae - 2000.0 * ai);
  const double steel = kPi / 4.0 * (kD * kD - bore * bore);
  const double amplitudeMPa = kScf * std::abs(wallAmplitude) / steel / 1e6;
  // 2A = 3.6 MPa is below the knee (74 MPa at 1e6 cycles): the second slope, m = 5.
  const double expected = sineDamage(amplitudeMPa, 5.0, std::pow(10.0, 15.350));
  for (const FatigueDamage::Node& n : damage[0].nodes) EXPECT_NEAR(n.damage / expected, 1.0, 1e-9);
}

TEST(FatigueDamage, ChainTensionAgainstTheApiTnCurve) {
  model::FatigueSectionSpec s;
  s.lineType = "chain";
  s.curve = "studless";
  s.tensionCurve = true;
  s.breakingStrength = 6.0e6;
  const model::Model m(pipeModel({"chain"}, {s}));
  FatigueDamage fatigue(m);
  EXPECT_EQ(fatigue.historyCount(), 3u);  // no bending: one history per node
  const double amplitude = 3.0e5;  // N
  feed(m, fatigue, [&](solver::LineSnapshot& snap, model::State&, double v) {
    for (double& t : snap.tension) t = 1.0e6 + amplitude * v;
  });
  const std::vector<FatigueDamage::Line> damage = fatigue.finish();
  // N R^3 = 316 with R = range / MBS (API RP 2SK 7.5).
  const double expected = sineDamage(amplitude / 6.0e6, 3.0, 316.0);
  for (const FatigueDamage::Node& n : damage[0].nodes) {
    EXPECT_NEAR(n.damage / expected, 1.0, 1e-9);
    EXPECT_TRUE(n.tension);
    EXPECT_NEAR(n.largestRange, 2.0 * amplitude, 1e-6);
  }
}

TEST(FatigueDamage, OnlyLineTypesWithFatigueCountAndAJunctionReportsTheWorse) {
  // pipe | other | pipe, fatigue on `pipe` only: the nodes of `other` inside are not counted; the junction
  // nodes are (they belong to a pipe element).
  {
    const model::Model m(pipeModel({"pipe", "other", "pipe"}, {pipeSection()}));
    FatigueDamage fatigue(m);
    feed(m, fatigue, [&](solver::LineSnapshot& snap, model::State&, double v) {
      for (Vec3& x : snap.bendingMomentVector) x = Vec3(0, 1e4 * v, 0);
    });
    const std::vector<FatigueDamage::Line> damage = fatigue.finish();
    std::vector<double> arcs;
    for (const FatigueDamage::Node& n : damage[0].nodes) arcs.push_back(n.arcLength);
    EXPECT_EQ(arcs, (std::vector<double>{0, 5, 10, 20, 25, 30}));
  }
  // Both with fatigue, `other` with twice the SCF: the junction reports other's damage, as other's own nodes.
  {
    model::FatigueSectionSpec other = pipeSection("other");
    other.stressConcentration = 2.0 * kScf;
    const model::Model m(pipeModel({"pipe", "other"}, {pipeSection(), other}));
    FatigueDamage fatigue(m);
    feed(m, fatigue, [&](solver::LineSnapshot& snap, model::State&, double v) {
      for (Vec3& x : snap.bendingMomentVector) x = Vec3(0, 1e4 * v, 0);
    });
    const std::vector<FatigueDamage::Line> damage = fatigue.finish();
    ASSERT_EQ(damage[0].nodes.size(), 5u);
    EXPECT_EQ(damage[0].nodes[2].lineType, "other");
    EXPECT_EQ(damage[0].nodes[2].damage, damage[0].nodes[3].damage);
    EXPECT_GT(damage[0].nodes[2].damage, 7.0 * damage[0].nodes[1].damage);
    EXPECT_EQ(damage[0].nodes[1].lineType, "pipe");
  }
}

TEST(RainflowCounter, AFinelySampledHistoryWithPlateausCountsAsItsTurningPoints) {
  // ASTM E1049-85 Fig. 6 with every range sampled at 7 points and a plateau at each turning point: the
  // counter must find the same turning points and so the standard's counts.
  const std::vector<double> points{-2, 1, -3, 5, -1, 3, -4, 4, -2};
  std::vector<double> history;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    for (int k = 0; k < 7; ++k) history.push_back(points[i] + (points[i + 1] - points[i]) * k / 7.0);
    history.push_back(points[i + 1]);
    history.push_back(points[i + 1]);
  }
  std::map<double, double> counts;
  RainflowCounter counter;
  const auto sink = [&](double range, double, double count) { counts[range] += count; };
  for (const double x : history) counter.add(x, sink);
  counter.finish(sink);
  const std::map<double, double> expected{{3.0, 0.5}, {4.0, 1.5}, {6.0, 0.5}, {8.0, 1.0}, {9.0, 0.5}};
  EXPECT_EQ(counts, expected);
  EXPECT_EQ(counter.residueSize(), 0u);  // finish empties it for a new history
}

TEST(SnCurve, EveryDnvPresetIsContinuousAtItsKnee) {
  // DNV-RP-C203 (2021) Tables 2-1 and 2-2 give log a1 and log a2 to three decimals; the two segments meet
  // at the knee (1e7 cycles in air, 1e6 in seawater with CP) to that rounding: |log N2 - log knee| < 3e-3
  // (5 x the 5e-4 rounding of log a1 carried through log S). A mistyped constant is off by 0.01 or more.
  const std::vector<std::string> names = SnCurve::presetNames();
  EXPECT_EQ(names.size(), 20u);
  for (const std::string& name : names) {
    const std::optional<SnCurve> c = SnCurve::preset(name);
    ASSERT_TRUE(c.has_value()) << name;
    const double knee = c->kneeRange();
    const double logS = std::log10(knee / 1e6);
    EXPECT_NEAR(c->logA1 - c->m1 * logS, std::log10(c->kneeCycles), 1e-12) << name;
    EXPECT_NEAR(c->logA2 - c->m2 * logS, std::log10(c->kneeCycles), 3e-3) << name;
  }
  EXPECT_FALSE(SnCurve::preset("dnv-d").has_value());
  // Curve D in air is the dnvD preset.
  EXPECT_EQ(SnCurve::preset("dnv-d-air")->logA1, SnCurve::dnvD().logA1);
}

TEST(TnCurve, DnvChainCurveOnTheNominalStress) {
  TnCurve c = *TnCurve::preset("dnv-studless");
  c.nominalArea = kPi * 0.076 * 0.076 / 2.0;  // 76 mm chain, two legs
  // DNV-OS-E301 (2021) Ch.2 Sec.2 [6.2]: N = 6.0e10 s^-3, s in MPa.
  const double range = 1.0e6;  // N
  const double s = range / c.nominalArea / 1e6;
  EXPECT_NEAR(c.cyclesToFailure(range) / (6.0e10 / (s * s * s)), 1.0, 1e-12);
}

contact::ContactEvent impact(int a, int b, double arcA, double arcB, double energy, double velocity, bool isImpact) {
  contact::ContactEvent e;
  e.lineA = a;
  e.lineB = b;
  e.arcAStart = arcA;
  e.arcBStart = arcB;
  e.impactEnergy = energy;
  e.impactVelocity = velocity;
  e.impact = isImpact;
  return e;
}

TEST(ClashDamage, ImpactsBinnedOnBothLinesByHand) {
  model::ModelSpec spec = pipeModel({"pipe", "pipe"}, {});  // 20 m
  spec.lines.push_back(test::simpleLine("flexible", "pipe", 7.5, 3, model::EndKind::Pinned, Vec3(0, 5, 5),
                                        model::EndKind::Pinned, Vec3(7.5, 5, 5)));
  const model::Model m(spec);
  const std::vector<contact::ContactEvent> events{
      impact(0, 1, 3.2, 1.0, 100.0, 0.5, true), impact(0, 1, 3.9, 6.9, 300.0, 0.8, true),
      impact(0, 1, 19.99, 7.5, 50.0, 0.3, true),
      impact(0, 1, 3.5, 1.0, 1e6, 2.0, false),  // a sustained contact, not an impact: not counted
  };
  const std::vector<LineClashDamage> d = clashDamage(m, {0, 1}, events, 2.0, 120.0);
  ASSERT_EQ(d.size(), 2u);
  ASSERT_EQ(d[0].bins.size(), 10u);
  ASSERT_EQ(d[1].bins.size(), 4u);  // 7.5 m: three bins of 2 m and one of 1.5 m
  EXPECT_EQ(d[1].bins[3].from, 6.0);
  EXPECT_EQ(d[1].bins[3].to, 7.5);
  const ClashDamageBin& b = d[0].bins[1];  // [2, 4): the first two
  EXPECT_EQ(b.impacts, 2);
  EXPECT_EQ(b.impactsAbove, 1);
  EXPECT_EQ(b.energy, 400.0);
  EXPECT_EQ(b.largestEnergy, 300.0);
  EXPECT_EQ(b.largestVelocity, 0.8);
  EXPECT_EQ(d[0].bins[9].impacts, 1);  // 19.99 m
  EXPECT_EQ(d[1].bins[0].impacts, 1);
  EXPECT_EQ(d[1].bins[3].impacts, 2);  // 6.9 m and the end, 7.5 m
  EXPECT_EQ(d[1].bins[3].energy, 350.0);
  EXPECT_EQ(d[0].impacts(), 3);
  EXPECT_EQ(d[1].energy(), 450.0);
}

}  // namespace
}  // namespace tangle::analysis
