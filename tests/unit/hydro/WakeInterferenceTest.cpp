/// @file WakeInterferenceTest.cpp
/// The geometry of WakeInterference (WakeInterference.hpp) at single points: where the wake starts behind
/// the upstream line and how it passes a change of the upstream line's section. The deficit formula itself
/// is hydro::wakeAt, tested against hand values in WakeModelTest; the whole static analysis against a
/// shooting solution in tests/validation/hydro/WakeInterferenceTest.cpp.
///
/// Set-up: an upstream line along z through the origin (x = y = 0), 20 m in 20 elements, of diameter 0.2 m
/// below z = -110 m and 0.6 m above (drag coefficients 1.0 and 1.5); a uniform 1 m/s current along +x; a
/// downstream line of one short element along z whose midpoint is put where the wake is probed.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "support/ModelFactory.hpp"
#include "tangle/hydro/CurrentProfile.hpp"
#include "tangle/hydro/WakeInterference.hpp"
#include "tangle/hydro/WakeModel.hpp"
#include "tangle/model/Model.hpp"

namespace tangle::hydro {
namespace {

constexpr double kJunction = -110.0;  // [m] z of the upstream line's section change (a node)

model::ModelSpec tandem() {
  model::ModelSpec spec;
  spec.sourceFile = "wake geometry (test)";
  spec.environment.waterDepth = 200.0;
  section::LineType thin = test::cableType("thin", 0.2, 50.0, 1e9),
                    thick = test::cableType("thick", 0.6, 50.0, 1e9);
  thin.dragNormal = 1.0;
  thick.dragNormal = 1.5;
  spec.lineTypes["thin"] = thin;
  spec.lineTypes["thick"] = thick;
  model::LineSpec up = test::simpleLine("up", "thin", 10.0, 10, model::EndKind::Fixed, Vec3(0, 0, -120),
                                        model::EndKind::Fixed, Vec3(0, 0, -100));
  up.sections = {{"thin", 10.0, 10}, {"thick", 10.0, 10}};
  spec.lines = {up, test::simpleLine("down", "thin", 0.02, 1, model::EndKind::Fixed, Vec3(3, 0, -110.01),
                                     model::EndKind::Fixed, Vec3(3, 0, -109.99))};
  model::WakeSpec w;
  w.upstream = "up";
  w.downstream = "down";
  spec.wakes = {w};
  return spec;
}

/// The deficit u / U [-] at the downstream element's midpoint `p`.
struct Probe {
  model::Model model{tandem()};
  model::State state{model.initialState()};
  CurrentProfile current{CurrentProfile::uniform(1.0, 0.0)};
  WakeInterference wake{model, current};
  double deficitAt(const Vec3& p) {
    const model::Line& down = model.lines()[1];
    state.position[down.firstNode] = p - Vec3(0, 0, 0.01);
    state.position[down.firstNode + 1] = p + Vec3(0, 0, 0.01);
    std::vector<ElementWake> out;
    wake.evaluate(state, 1025.0, out);
    return out[static_cast<std::size_t>(down.firstElement)].deficit;
  }
};

TEST(WakeInterference, StartsSmoothlyAtTheUpstreamCylindersRearSurface) {
  // Source: WakeInterference.hpp: behind the upstream centre the Huse deficit times the smoothstep
  // r^2 (3 - 2 r), r = 2 x / D, which is one from the rear surface x = D / 2 on; nothing level with or
  // ahead of the centre. Probed 0.05 m off the axis (y), far from the section change (z = -115 m, D = 0.2
  // m, C_d = 1). Continuity: between points 1 mm apart in x the deficit changes by less than 2 % of U
  // (its largest slope, about 0.6 U over the 0.1 m of the rise, gives 0.9 %); with the cut-off at x = 0 it
  // jumped by 0.6 U.
  Probe probe;
  const WakeCoefficients huse;  // k1 0.25, k2 1.0, k3 0.693, as WakeSpec's defaults
  double last = 0.0;
  for (int i = -50; i <= 400; ++i) {
    const double x = 1e-3 * i;
    const double deficit = probe.deficitAt(Vec3(x, 0.05, -115.0));
    const double r = std::clamp(2.0 * x / 0.2, 0.0, 1.0);
    const double expected =
        x > 0.0 ? r * r * (3.0 - 2.0 * r) * wakeAt(huse, x, 0.05, 1.0, 0.2, 0.2).deficit : 0.0;
    EXPECT_NEAR(deficit, expected, 1e-12) << "x = " << x;
    EXPECT_LT(std::abs(deficit - last), 0.02) << "x = " << x;
    last = deficit;
  }
}

TEST(WakeInterference, PassesAChangeOfTheUpstreamSectionContinuously) {
  // Source: WakeInterference.hpp: the upstream D and C_d are the means of D and C_d D over D_max = 0.6 m of
  // arc either side of the point's projection, so farther than 0.6 m from the section change the wake is
  // Huse's of the section there, and in between it passes from one to the other. Probed 3 m behind (x)
  // and on the wake's centre line, for z from 2 m below the change to 2 m above in steps of 5 mm: the
  // deficit changes by less than 1 % of U per step (the blend spreads the change from 0.229 U to 0.442 U
  // over 1.2 m: 0.09 % per step); with the element's own section it jumped by the whole 0.21 U where the
  // projection crossed the node.
  Probe probe;
  const WakeCoefficients huse;
  const double below = wakeAt(huse, 3.0, 0.0, 1.0, 0.2, 0.2).deficit;
  const double above = wakeAt(huse, 3.0, 0.0, 1.5, 0.6, 0.2).deficit;
  ASSERT_GT(above - below, 0.1);
  double last = std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i <= 800; ++i) {
    const double z = kJunction - 2.0 + 5e-3 * i;
    const double deficit = probe.deficitAt(Vec3(3.0, 0.0, z));
    if (z < kJunction - 0.6 - 1e-9) {
      EXPECT_NEAR(deficit, below, 1e-12) << "z = " << z;
    } else if (z > kJunction + 0.6 + 1e-9) {
      EXPECT_NEAR(deficit, above, 1e-12) << "z = " << z;
    }
    EXPECT_GE(deficit, std::min(below, above) - 1e-12) << "z = " << z;
    EXPECT_LE(deficit, std::max(below, above) + 1e-12) << "z = " << z;
    if (i > 0) {
      EXPECT_LT(std::abs(deficit - last), 0.01) << "z = " << z;
    }
    last = deficit;
  }
}

}  // namespace
}  // namespace tangle::hydro
