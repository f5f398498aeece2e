// Slack-to-taut snaps of grounded chain (time/CableSnapLimit.hpp).
//
// The mooring example (chain / wire / chain, fairlead moved 5 m at 10 s) in a 1 m/s current from the
// fairlead towards the anchor: the current pushes the hanging part back, the grounded chain goes slack and
// the fairlead motion snaps it taut again and again. Without the snap limit generalized-alpha (rho_inf 0.8)
// at the example's dt = 0.01 s gained energy at each snap: 4e7 N at the anchor by t = 16 s (the line's
// static tension is 1e5 N), and at dt = 0.005 s as well.
//
// Reference: the same run at dt = 1e-3 s without the limit (converged in dt to the peaks' resolution:
// 2.1e5 N anchor, 4.35e5 N fairlead over 40 s; dt = 2e-3 s gives 2.12e5 and 4.09e5). The peaks of snaps in an
// undamped chain depend on the timing of each snap to first order in dt, so the limited run at the
// nominal 0.01 s is compared at 10 %; the failure this guards against is a hundredfold blow-up.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "TestPaths.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/io/ModelReader.hpp"

namespace tangle {
namespace {

struct Peaks {
  double anchor = 0.0;    ///< largest anchor tension [N]
  double fairlead = 0.0;  ///< largest fairlead tension [N]
  int steps = 0;
};

Peaks run(double dt, double maxStrainStep) {
  model::ModelSpec spec = io::readModelFile(std::string(test::kExamplesDir) + "/mooring-dynamics/model.yaml");
  spec.environment.current = {{0.0, 1.0, 0.0}};  // towards +x: from the fairlead (x = 0) to the anchor
  spec.dynamics.duration = 25.0;
  spec.dynamics.timeStep = dt;
  spec.dynamics.outputInterval = 0.5;
  spec.dynamics.maxCableStrainStep = maxStrainStep;
  analysis::Simulation sim(std::move(spec));
  const solver::StaticResult statics = sim.solveStatics();
  EXPECT_TRUE(statics.converged) << statics.message;
  Peaks p;
  const time::DynamicResult r = sim.runDynamics(
      [](const model::State&, const VecX&) {}, false,
      [&](const model::State&, double) {
        const auto lines = sim.sectionSnapshot();
        p.anchor = std::max(p.anchor, lines[0].tension.front());
        p.fairlead = std::max(p.fairlead, lines[0].tension.back());
      });
  EXPECT_TRUE(r.completed) << r.message;
  p.steps = r.steps;
  return p;
}

TEST(CableSnap, GroundedChainSnapsWithoutGainingEnergy) {
  const Peaks limited = run(0.01, 1e-4);
  const Peaks reference = run(1e-3, 0.0);
  EXPECT_NEAR(limited.anchor, reference.anchor, 0.1 * reference.anchor);
  EXPECT_NEAR(limited.fairlead, reference.fairlead, 0.1 * reference.fairlead);
  // The limit shortens only the steps around snaps.
  EXPECT_LT(limited.steps, 3 * 2500);
}

}  // namespace
}  // namespace tangle
