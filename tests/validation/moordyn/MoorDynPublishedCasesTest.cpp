/// @file MoorDynPublishedCasesTest.cpp
/// MoorDyn's own published test cases (its repository's tests/Mooring decks and reference data, v2.7.1,
/// BSD 3-Clause; copied to tests/data/moordyn, see the README there) read by tangle's deck reader and
/// driven through analysis::CoupledRun exactly as MoorDyn's tests drive MoorDyn through its C API
/// (tests/lowe_and_langley_2006.cpp, tests/quasi_static_chain.cpp): same decks, same host motions, same
/// reference values. Tolerances are MoorDyn's own acceptance limits unless a comment says otherwise;
/// docs/moordyn.md records the values tangle reaches.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "TestPaths.hpp"
#include "tangle/analysis/CoupledRun.hpp"
#include "tangle/io/MoorDynCoupling.hpp"

namespace tangle {
namespace {

std::string dataPath(const std::string& name) { return std::string(test::kTestDataDir) + "/moordyn/" + name; }

/// Rows of numbers separated by tabs, commas or spaces.
std::vector<std::vector<double>> readTable(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    for (char& c : line)
      if (c == ',' || c == '\t') c = ' ';
    std::istringstream words(line);
    std::vector<double> row;
    double v = 0.0;
    while (words >> v) row.push_back(v);
    if (!row.empty()) rows.push_back(std::move(row));
  }
  return rows;
}

std::unique_ptr<analysis::CoupledRun> coupledRun(const std::string& deck) {
  io::DeckCoupling d = io::loadMoorDynCoupling(dataPath(deck));
  return std::make_unique<analysis::CoupledRun>(d.spec, d.points);
}

/// The Lowe & Langley (2006) flexible jumper: 170 m, EI 120.8 kN m^2, between an anchor at (-100, 0, -55) and
/// a coupled top at (0, 0, -5). MoorDyn's test "Stationary": the top and bottom end forces [kN] of the static
/// shape, (11.40, 0, 45.71) and (-11.40, 0, 24.04) as reactions, within 0.2 kN (its tolerance; 0.4 % of the
/// top tension).
TEST(MoorDynPublishedCases, LoweLangleyJumperStaticEndForces) {
  auto run = coupledRun("lowe_langley_jumper.txt");
  ASSERT_EQ(run->pointCount(), 1);
  const std::vector<double> x = run->modelPositions();
  run->initialize(x, std::vector<double>(3, 0.0));
  // The force of the line on the coupled top (MoorDyn_GetPointForce): minus the reaction of the reference.
  const std::vector<double>& top = run->forces();
  ::testing::Test::RecordProperty("top_force_kN",
                                  std::to_string(1e-3 * top[0]) + " " + std::to_string(1e-3 * top[2]));
  EXPECT_NEAR(1e-3 * top[0], -11.40, 0.2);
  EXPECT_NEAR(1e-3 * top[1], 0.0, 0.2);
  EXPECT_NEAR(1e-3 * top[2], -45.71, 0.2);
  // The force of the line on its anchor (MoorDyn_GetLineNodeForce at node 0).
  const solver::LineSnapshot& line = run->lineResults().at(0);
  EXPECT_NEAR(1e-3 * line.endForceA.x(), 11.40, 0.2);
  EXPECT_NEAR(1e-3 * line.endForceA.y(), 0.0, 0.2);
  EXPECT_NEAR(1e-3 * line.endForceA.z(), -24.04, 0.2);
}

/// MoorDyn's test "Case 1..3": the top moved harmonically along x, y or z (amplitude 10 m, period 27 s) after
/// a ramp of one period (smoothstep x^3 (6x^2 - 15x + 10) on the amplitude), the host stepping at 0.005 s;
/// the top tension against Lowe & Langley's (2006) published time history over 80 s, within 1 kN at every
/// reference time (MoorDyn's tolerance; 1.5-2 % of the tension).
void loweLangleyCase(int direction, const char* reference) {
  auto run = coupledRun("lowe_langley_jumper.txt");
  const std::vector<double> x0 = run->modelPositions();
  run->initialize(x0, std::vector<double>(3, 0.0));
  const std::vector<std::vector<double>> ref = readTable(dataPath(reference));
  ASSERT_GT(ref.size(), 100u);
  const double amplitude = 10.0, period = 27.0, dt = 0.005, ramp = period;
  std::size_t next = 0;
  double worst = 0.0, worstTime = 0.0;
  std::vector<double> x = x0, v(3, 0.0);
  while (next < ref.size()) {
    const double t = run->time();
    // The host's motion as MoorDyn's test gives it: the position reached at t + dt, the velocity that gets
    // there.
    double f = t >= ramp ? 1.0 : t / ramp;
    f = f * f * f * (6.0 * f * f - 15.0 * f + 10.0);
    const double target = x0[static_cast<std::size_t>(direction)] +
                          f * amplitude * std::sin(2.0 * std::numbers::pi / period * (t + dt));
    const Vec3 here = run->pointPosition(0);
    std::fill(v.begin(), v.end(), 0.0);
    for (int k = 0; k < 3; ++k) x[static_cast<std::size_t>(k)] = here[k];
    v[static_cast<std::size_t>(direction)] = (target - here[direction]) / dt;
    run->step(x, v, dt);
    const double tRef = run->time() - ramp;
    if (tRef >= ref[next][0] - 1e-9) {
      const double tension = 1e-3 * run->lineResults().at(0).endTensionB;
      const double error = std::abs(tension - ref[next][1]);
      if (error > worst) {
        worst = error;
        worstTime = tRef;
      }
      ++next;
    }
  }
  ::testing::Test::RecordProperty("largest_difference_kN", std::to_string(worst));
  EXPECT_LT(worst, 1.0) << "largest difference " << worst << " kN at t = " << worstTime
                        << " s after the ramp";
}

TEST(MoorDynPublishedCases, LoweLangleyJumperCase1SurgeMotion) {
  loweLangleyCase(0, "lowe_langley_case1.csv");
}
TEST(MoorDynPublishedCases, LoweLangleyJumperCase2SwayMotion) {
  loweLangleyCase(1, "lowe_langley_case2.csv");
}
TEST(MoorDynPublishedCases, LoweLangleyJumperCase3HeaveMotion) {
  loweLangleyCase(2, "lowe_langley_case3.csv");
}

/// MoorDyn's test "Case 4..6": the jumper's top held still in a regular wave (amplitude 5 m, period 10 s,
/// deep-water dispersion k = omega^2 / 9.81 in 100 m, travelling at 0, 45 and 90 degrees with phases 230,
/// 165 and 0 degrees), the linear-wave kinematics given by the host at every node (MoorDyn's WaveKin 1,
/// here hydro::HydroLoads::setNodeKinematics, which the C API's MoorDyn_ExternalWaveKinSet calls) at mid
/// step, host steps of 0.005 s, the full wave from t = 0 (no ramp) and the comparison from two periods on:
/// the top tension against Lowe & Langley's published history over 30 s within 1 kN (MoorDyn's tolerance).
void loweLangleyWaveCase(int caseNumber, double phaseDegrees, const char* reference) {
  auto run = coupledRun("lowe_langley_jumper.txt");
  const std::vector<double> x0 = run->modelPositions();
  run->initialize(x0, std::vector<double>(3, 0.0));
  const std::vector<std::vector<double>> ref = readTable(dataPath(reference));
  ASSERT_GT(ref.size(), 50u);
  const double amplitude = 5.0, period = 10.0, dt = 0.005, settle = 2.0 * period, depth = 100.0;
  const double omega = 2.0 * std::numbers::pi / period, k = omega * omega / 9.81;
  const double heading = (caseNumber - 4) * 0.25 * std::numbers::pi,
               phase = phaseDegrees * std::numbers::pi / 180.0;
  analysis::Simulation& sim = run->simulation();
  const std::size_t nodes = static_cast<std::size_t>(sim.model().nodeCount());
  std::vector<Vec3> u(nodes), a(nodes);
  std::size_t next = 0;
  double worst = 0.0, worstTime = 0.0;
  const std::vector<double> still(3, 0.0);
  while (next < ref.size()) {
    const double t = run->time() + 0.5 * dt;
    for (std::size_t n = 0; n < nodes; ++n) {
      const Vec3& r = sim.state().position[n];
      const double s = r.x() * std::cos(heading) + r.y() * std::sin(heading);
      const double c = std::cos(k * s - omega * t + phase), sn = std::sin(k * s - omega * t + phase);
      const double ch = std::cosh(k * (r.z() + depth)) / std::cosh(k * depth);
      const double sh = std::sinh(k * (r.z() + depth)) / std::cosh(k * depth);
      u[n] = omega * amplitude * Vec3(c * ch * std::cos(heading), c * ch * std::sin(heading), sn * sh);
      a[n] =
          omega * omega * amplitude * Vec3(sn * ch * std::cos(heading), sn * ch * std::sin(heading), -c * sh);
    }
    sim.hydro().setNodeKinematics(u, a);
    run->step(x0, still, dt);
    const double tRef = run->time() - settle;
    if (tRef >= ref[next][0] - 1e-9) {
      const double error = std::abs(1e-3 * run->lineResults().at(0).endTensionB - ref[next][1]);
      if (error > worst) {
        worst = error;
        worstTime = tRef;
      }
      ++next;
    }
  }
  ::testing::Test::RecordProperty("largest_difference_kN", std::to_string(worst));
  EXPECT_LT(worst, 1.0) << "largest difference " << worst << " kN at t = " << worstTime
                        << " s after two periods";
}

TEST(MoorDynPublishedCases, LoweLangleyJumperCase4WaveAlongX) {
  loweLangleyWaveCase(4, 230.0, "lowe_langley_case4.csv");
}
// Case 5 misses MoorDyn's 1 kN by 6 %: largest difference 1.056 kN, 1.3 s after the two settling periods
// (RMS over the 30 s 0.32 kN); unchanged with spectral radius 1 and a Newton tolerance of 1e-8 (1.056 kN),
// half the host step (1.048 kN) or twice the elements (1.038 kN): a difference of the model (tangle's
// element-wise Morison loads and co-rotational beams against MoorDyn's node-wise loads and bending), largest
// in the start transient of the wave switched on at t = 0 without a ramp. Kept here with its numbers
// (docs/moordyn.md), run by ctest as expected to fail (validation.moordyn_lowe_langley_case5_expected_fail)
// rather than with a wider tolerance (measured 2026-11-30: 1.0556 kN).
TEST(MoorDynPublishedCasesKnownFailures, LoweLangleyJumperCase5WaveAt45Degrees) {
  loweLangleyWaveCase(5, 165.0, "lowe_langley_case5.csv");
}
TEST(MoorDynPublishedCases, LoweLangleyJumperCase6WaveAlongY) {
  loweLangleyWaveCase(6, 0.0, "lowe_langley_case6.csv");
}

/// MoorDyn's "quasi_static_chain": a 410 m chain (d 0.252 m, 390 kg/m) in 50, 200 and 600 m of water, the
/// static fairlead and anchor tensions against quasi-static codes, within 10 % (MoorDyn's limit), then the
/// fairlead moved along the published surge history (motion ZZP1_A1, 0.1 s host steps): the fairlead tension
/// change against the quasi-static prediction within 15 % of twice its largest excursion (MoorDyn's metric
/// and limit: a quasi-static reference leaves out drag and inertia, which a dynamic model has).
void quasiStaticChain(const std::string& depth, double fairlead, double anchor) {
  auto run = coupledRun("WD" + depth + "_Chain.txt");
  ASSERT_EQ(run->pointCount(), 1);
  run->initialize(std::vector<double>(3, 0.0), std::vector<double>(3, 0.0));
  const solver::LineSnapshot& s = run->lineResults().at(0);
  const double fair0 = s.endTensionB, anch0 = s.endTensionA;
  EXPECT_NEAR(fair0 / (1e3 * fairlead), 1.0, 0.10) << depth << " m: fairlead " << fair0;
  EXPECT_NEAR(anch0 / (1e3 * anchor), 1.0, 0.10) << depth << " m: anchor " << anch0;
  const auto motion = readTable(dataPath("qs_ZZP1_A1.txt"));
  const auto ref = readTable(dataPath("qs_WD" + depth + "_Chain_ZZP1_A1.txt"));
  const double dt = 0.1;
  double worst = 0.0, largest = 0.0;
  std::size_t r = 0;
  for (std::size_t i = 0; i + 1 < motion.size() && r < ref.size(); ++i) {
    std::vector<double> x(3), v(3);
    for (std::size_t k = 0; k < 3; ++k) {
      x[k] = motion[i][k + 1];
      v[k] = (motion[i + 1][k + 1] - x[k]) / dt;
    }
    run->step(x, v, dt);
    if (motion[i][0] < 0.0) continue;  // MoorDyn's test: the first 10 s settle the motion in
    const double change = run->lineResults().at(0).endTensionB - fair0;
    const double refChange = 1e3 * ref[r][3] - 1e3 * fairlead;
    worst = std::max(worst, std::abs(change - refChange));
    largest = std::max(largest, std::abs(refChange));
    ++r;
  }
  ASSERT_GT(r, 100u);
  ::testing::Test::RecordProperty("fairlead_static_ratio", std::to_string(fair0 / (1e3 * fairlead)));
  ::testing::Test::RecordProperty("anchor_static_ratio", std::to_string(anch0 / (1e3 * anchor)));
  ::testing::Test::RecordProperty("dynamic_error_metric", std::to_string(worst / (2.0 * largest)));
  EXPECT_LT(worst / (2.0 * largest), 0.15)
      << depth << " m: largest difference " << worst << " N, reference excursion " << largest << " N";
}

TEST(MoorDynPublishedCases, QuasiStaticChain50m) { quasiStaticChain("0050", 991.6, 826.2); }
TEST(MoorDynPublishedCases, QuasiStaticChain200m) { quasiStaticChain("0200", 2065.4, 1402.2); }
TEST(MoorDynPublishedCases, QuasiStaticChain600m) { quasiStaticChain("0600", 5232.6, 3244.2); }

/// MoorDyn's tests/polyester.cpp "Visco-elastic testing": visco.txt (one 1 m segment of a polyester rope,
/// EA|alphaMBL|vbeta = 1.424e8|1.586e8|0.4 N, BA|BA_d = 4e9|1.1e7 N s, started stretched 100 %) with its
/// fairlead driven along x so that the strain follows MoorDyn's reference history (x = 1 + strain; MoorDyn's
/// motion file is absent from its snapshot), the host stepping at the reference's 0.01 s. The tension against
/// the reference's stress x area within 3 % (MoorDyn's tolerance) from t = 30 s: tangle starts the rope
/// relaxed at its static solution (142.4 MN), MoorDyn part-relaxed by its initial-condition run (70.7 MN),
/// and the difference decays with the relaxation time BA / (EA_1 + EA_2) ~ 7 s (a law-level replay from
/// MoorDyn's initial state is ViscoelasticAxialLawTest: 1.7 % over the whole 60 s).
TEST(MoorDynPublishedCases, ViscoelasticRopeFollowsMoorDynsStressStrainHistory) {
  auto run = coupledRun("visco.txt");
  ASSERT_EQ(run->pointCount(), 1);
  const std::vector<std::vector<double>> ref = readTable(dataPath("visco_stress_strain.csv"));
  ASSERT_EQ(ref.size(), 6000u);  // (the header line has no numbers)
  const double area = std::numbers::pi / 4.0 * 0.1438 * 0.1438;
  std::vector<double> x = run->modelPositions(), v(3, 0.0);
  run->initialize(x, v);
  // The static solution: the rope relaxed, T = EA strain.
  EXPECT_NEAR(run->lineResults().at(0).tension.back(), 1.424e8, 1e-6 * 1.424e8);
  double worst = 0.0, worstTime = 0.0, early = 0.0;
  for (std::size_t i = 1; i < ref.size(); ++i) {
    const double dt = ref[i][0] - ref[i - 1][0];
    // As MoorDyn_Step: the position at the step's start and the velocity that reaches the target at its end.
    const double target = 1.0 + ref[i][1];
    v[0] = (target - x[0]) / dt;
    run->step(x, v, dt);
    x[0] = target;
    const double tension = std::abs(run->forces()[0]);
    const double reference = ref[i][2] * area;
    const double error = std::abs(tension - reference) / reference;
    if (ref[i][0] < 30.0) {
      early = std::max(early, error);
    } else if (error > worst) {
      worst = error;
      worstTime = ref[i][0];
    }
  }
  ::testing::Test::RecordProperty("worst_relative_error_after_30s",
                                  std::to_string(worst) + " at " + std::to_string(worstTime));
  ::testing::Test::RecordProperty("worst_relative_error_before_30s", std::to_string(early));
  EXPECT_LT(worst, 0.03) << "at t = " << worstTime << " s";
}

/// A sea-state elevation [m] at `times` [s] from a JONSWAP spectrum (MoorDyn's tests/syrope.cpp: 299
/// components at the midpoints of 300 equally spaced frequency edges, amplitudes sqrt(2 S dw), phases from a
/// Mersenne twister seeded as MoorDyn's test seeds it; its spectrum: A = 1 - 0.287 ln(gamma), sigma 0.07 /
/// 0.09).
std::vector<double> jonswapElevation(double hs, double tp, const std::vector<double>& times, unsigned seed) {
  const double gamma = 3.3, tz = tp / 1.402, wMin = 1.0 / tz, wMax = 20.0 / tz;
  constexpr int kEdges = 300;
  const double dw = (wMax - wMin) / (kEdges - 1), wp = 2.0 * std::numbers::pi / tp;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 2.0 * std::numbers::pi);
  std::vector<double> w, a, phase;
  for (int i = 0; i + 1 < kEdges; ++i) {
    const double om = wMin + (i + 0.5) * dw;
    const double sigma = om > wp ? 0.09 : 0.07, r = (om - wp) / (sigma * wp), q = std::pow(wp / om, 4.0);
    const double spectrum = (1.0 - 0.287 * std::log(gamma)) * (5.0 / 16.0) * hs * hs * (q / om) *
                            std::exp(-1.25 * q) * std::pow(gamma, std::exp(-0.5 * r * r));
    w.push_back(om);
    a.push_back(std::sqrt(2.0 * spectrum * dw));
  }
  for (std::size_t i = 0; i < w.size(); ++i) phase.push_back(uniform(rng));
  std::vector<double> eta(times.size(), 0.0);
  for (std::size_t k = 0; k < times.size(); ++k)
    for (std::size_t i = 0; i < w.size(); ++i) eta[k] += a[i] * std::cos(w[i] * times[k] + phase[i]);
  return eta;
}

/// MoorDyn's tests/syrope.cpp "Syrope tests": syrope/<form>_wc/line.txt
/// (one 1 m segment of a SYROPE polyester rope, Tmax0 1.3886 MN) with its fairlead driven along x through 18
/// h at the host's 0.2 s: a slow strain of six 3 h stages (hold, ramp up, hold, ramp down, hold, ramp up,
/// from eps0 = 0.0148657) with wave-frequency (Hs 5 m, Tp 12 s, x 4e-4 / m) and low-frequency (Hs 20 m, Tp
/// 120 s, x 0.8e-4 / m) strains on it. The rope's mean tension (MoorDyn's segment tension Te; tangle's
/// State::viscoelastic.meanTension) against the mean tension on the working curve of the largest mean tension
/// so far, at the strain of each step (the working curve of Tmax, the OWC where it reaches Tmax): relative L2
/// error below 5 % (MoorDyn's tolerance). tangle's working curves are exact where MoorDyn tabulates them, and
/// its slow strain is integrated by backward Euler where MoorDyn uses its explicit scheme. MoorDyn checks the
/// linear working curve only: its quadratic and exponential cases start from a slow strain set by Tmean0 that
/// is not the deck's strain's ("the L2 error is large"); tangle starts from the static equilibrium on the
/// working curve, and meets the same 5 % for those too.
enum class WorkingCurve { Linear, Quadratic, Exponential };
double syropeCase(const std::string& deck, WorkingCurve form, double k1, double k2, double eps0) {
  auto run = coupledRun(deck);
  EXPECT_EQ(run->pointCount(), 1);
  const double stage = 3.0 * 3600.0, dt = 0.2;
  const std::size_t steps = static_cast<std::size_t>(6.0 * stage / dt);
  std::vector<double> times(steps + 1);
  for (std::size_t i = 0; i <= steps; ++i) times[i] = 6.0 * stage * double(i) / double(steps);
  const std::vector<double> waveFrequency = jonswapElevation(5.0, 12.0, times, 12345);
  const std::vector<double> lowFrequency = jonswapElevation(20.0, 120.0, times, 54321);
  std::vector<double> strain(steps + 1);
  for (std::size_t i = 0; i <= steps; ++i) {
    const double t = times[i];
    const double slow = t < stage         ? eps0
                        : t < 2.0 * stage ? eps0 + 2.0 * eps0 * (t - stage) / stage
                        : t < 3.0 * stage ? 3.0 * eps0
                        : t < 4.0 * stage ? 3.0 * eps0 - eps0 * (t - 3.0 * stage) / stage
                        : t < 5.0 * stage ? 2.0 * eps0
                                          : 2.0 * eps0 + 1.5 * eps0 * (t - 5.0 * stage) / stage;
    strain[i] = slow + 4.0e-4 * waveFrequency[i] + 0.8e-4 * lowFrequency[i];
  }
  // The OWC as MoorDyn's test reads owc.dat (two header lines: from (0, 0)), and the working curve's mean
  // tension at a strain (its find_mean_tension: xi clamped to [0, 1]; the OWC where the curve reaches Tmax).
  const std::vector<std::vector<double>> owc = readTable(dataPath("syrope/owc.dat"));
  std::vector<double> owcStrain, owcTension;
  for (const auto& row : owc) {
    owcStrain.push_back(row[0]);
    owcTension.push_back(row[1]);
  }
  const auto interpolate = [](double x, const std::vector<double>& xs, const std::vector<double>& ys) {
    if (x <= xs.front()) return ys.front();
    if (x >= xs.back()) return ys.back();
    const std::size_t k =
        static_cast<std::size_t>(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin()) - 1;
    return ys[k] + (ys[k + 1] - ys[k]) * (x - xs[k]) / (xs[k + 1] - xs[k]);
  };
  const auto workingCurve = [&](double eps, double tmax) {
    const double epsMax = interpolate(tmax, owcTension, owcStrain);
    const double epsMin = form == WorkingCurve::Linear && k1 >= 1.0
                              ? epsMax - tmax / k1
                              : owcStrain.front() + k1 * (epsMax - owcStrain.front());
    const double xi = std::clamp((eps - epsMin) / (epsMax - epsMin), 0.0, 1.0);
    if (xi >= 1.0) return interpolate(eps, owcStrain, owcTension);
    return form == WorkingCurve::Linear      ? tmax * xi
           : form == WorkingCurve::Quadratic ? tmax * xi * (k2 * xi + 1.0 - k2)
                                             : tmax * std::expm1(k2 * xi) / std::expm1(k2);
  };
  // As MoorDyn's test: the fairlead where the deck puts it (y, z), moved along x only.
  std::vector<double> x = run->modelPositions(), v{(strain[1] - strain[0]) / dt, 0.0, 0.0};
  x[0] = 1.0 + strain[0];
  run->initialize(x, v);
  const auto& state = run->simulation().state().viscoelastic;
  if (state.meanTension.size() != 1u) {
    ADD_FAILURE() << "no SYROPE state";
    return 1.0;
  }
  double tmax = 0.16 * 885.0e3 * 9.80665;  // MoorDyn's test: 16 % of the MBL, the deck's Tmax0
  double squaredError = 0.0, squaredReference = 0.0;
  for (std::size_t i = 0; i <= steps; ++i) {
    if (i > 0) {
      x[0] = 1.0 + strain[i - 1];
      v[0] = (strain[i] - strain[i - 1]) / dt;
      run->step(x, v, dt);
    }
    const double mean = state.meanTension[0];
    tmax = std::max(tmax, mean);
    const double reference = workingCurve(strain[i], tmax);
    squaredError += (mean - reference) * (mean - reference);
    squaredReference += reference * reference;
  }
  const double l2 = std::sqrt(squaredError / squaredReference);
  ::testing::Test::RecordProperty("relative_l2", std::to_string(l2));
  // The comparison's Tmax follows the run's own: check it against the OWC independently. The slow strain
  // reaches 3 eps0 (plus the sea states' strains): Tmax must have grown along the OWC to about its tension
  // there, within the OWC's range.
  const double peakSlow = 3.0 * eps0;
  EXPECT_GT(state.maxMeanTension[0], interpolate(peakSlow, owcStrain, owcTension));
  EXPECT_LT(state.maxMeanTension[0], interpolate(peakSlow + 0.01, owcStrain, owcTension));
  return l2;
}

TEST(MoorDynPublishedCases, SyropeRopeFollowsItsLinearWorkingCurves) {
  EXPECT_LT(syropeCase("syrope/linear_wc/line.txt", WorkingCurve::Linear, 1.25e8, 0.0, 1.48657e-02), 0.05);
}

TEST(MoorDynPublishedCases, SyropeRopeFollowsItsQuadraticWorkingCurves) {
  EXPECT_LT(syropeCase("syrope/quadratic_wc/line.txt", WorkingCurve::Quadratic, 0.25, 1.0, 1.50575e-02),
            0.05);
}

TEST(MoorDynPublishedCases, SyropeRopeFollowsItsExponentialWorkingCurves) {
  EXPECT_LT(syropeCase("syrope/exp_wc/line.txt", WorkingCurve::Exponential, 0.2, 1.5, 1.24577e-02), 0.05);
}

}  // namespace
}  // namespace tangle
