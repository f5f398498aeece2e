/// @file SyropeAxialLawTest.cpp
/// The SYROPE rope law (tangle::element::SyropeAxialLaw): its working curves (closed-form inverses against
/// MoorDyn's forward formulas), their continuity with the original working curve at Tmax, the slow and fast
/// limits of a step, and the memory of the largest mean tension.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "tangle/core/Error.hpp"
#include "tangle/element/SyropeAxialLaw.hpp"

namespace tangle::element {
namespace {

// MoorDyn's tests/Mooring/syrope/owc.dat, every third point (a concave fibre-rope curve, N against strain).
std::shared_ptr<const core::PiecewiseLinear> owc() {
  return std::make_shared<const core::PiecewiseLinear>(
      std::vector<double>{0.0, 6.20690e-03, 1.24138e-02, 1.86207e-02, 2.48276e-02, 3.10345e-02, 3.72414e-02},
      std::vector<double>{0.0, 4.78788e+05, 8.66556e+05, 1.19666e+06, 1.50245e+06, 1.81728e+06, 2.17500e+06});
}

SyropeConstants constants(WorkingCurveForm form, double k1, double k2) {
  return {owc(), form, k1, k2, 1.53e8, 23.12, 5.0e10, 1.0e5};
}

// Source: MoorDyn's setWorkingCurve (Line.cpp) forward formulas, T(xi) for xi = (eps - eps_min) / (eps_max -
// eps_min): the law's closed-form inverse X(T) must return eps for T(eps) (1e-12 of the span), and at T =
// Tmax the working curve meets the OWC (eps_max = X_owc(Tmax)).
TEST(SyropeAxialLaw, WorkingCurvesInvertMoorDynsFormulasAndMeetTheOriginalCurveAtTmax) {
  const double tmax = 1.3886e6;
  struct Case {
    WorkingCurveForm form;
    double k1, k2;
  };
  for (const Case c :
       {Case{WorkingCurveForm::Linear, 1.25e8, 0.0}, Case{WorkingCurveForm::Quadratic, 0.25, 1.0},
        Case{WorkingCurveForm::Quadratic, 0.25, -0.5}, Case{WorkingCurveForm::Exponential, 0.2, 1.5}}) {
    const SyropeAxialLaw law(constants(c.form, c.k1, c.k2));
    // eps_max = X_owc(Tmax): the OWC's points interpolated by hand (Tmax lies between its 4th and 5th).
    const double epsMax =
        1.86207e-02 + (2.48276e-02 - 1.86207e-02) * (tmax - 1.19666e+06) / (1.50245e+06 - 1.19666e+06);
    const double epsMin = law.slackStrain(tmax);
    EXPECT_NEAR(law.curveStrain(tmax, tmax).strain, epsMax, 1e-9 * epsMax);
    for (double xi : {0.1, 0.37, 0.8, 1.0}) {
      const double forward = c.form == WorkingCurveForm::Linear ? xi
                             : c.form == WorkingCurveForm::Quadratic
                                 ? xi * (c.k2 * xi + 1.0 - c.k2)
                                 : (1.0 - std::exp(c.k2 * xi)) / (1.0 - std::exp(c.k2));
      const double eps = epsMin + xi * (epsMax - epsMin);
      EXPECT_NEAR(law.curveStrain(tmax * forward, tmax).strain, eps, 1e-12 * (epsMax - epsMin)) << xi;
      EXPECT_NEAR(law.staticTension(eps, tmax), tmax * forward, 1e-9 * tmax) << xi;
    }
    EXPECT_EQ(law.staticTension(0.5 * epsMin, tmax), 0.0);  // slack below the working curve
  }
}

// A step much longer than the relaxation time lands on the static curve (N = T = X^-1(eps)); a very short one
// from the relaxed state responds with the dynamic stiffness alpha + beta T (times BA / (BA + BA_d)).
TEST(SyropeAxialLaw, SlowAndFastLimitsOfAStep) {
  const double tmax = 1.3886e6;
  const SyropeAxialLaw law(constants(WorkingCurveForm::Linear, 1.25e8, 0.0));
  const double eps = 0.0185;
  const double t = law.staticTension(eps, tmax);
  const SyropeAxialLaw::Step slow = law.step(eps, 0.0, 0.0, tmax, 1e12);
  EXPECT_NEAR(slow.meanTension, t, 1e-6 * t);
  EXPECT_NEAR(slow.tension, t, 1e-6 * t);
  const double x0 = law.slowStrain(t, tmax);
  const SyropeAxialLaw::Step fast = law.step(eps, 0.0, x0, tmax, 1e-6);
  EXPECT_NEAR(fast.tension, t, 1e-6 * t);
  const double dynamic = (1.53e8 + 23.12 * t) * 5.0e10 / (5.0e10 + 1.0e5);
  EXPECT_NEAR(fast.dTensionDStrain, dynamic, 1e-3 * dynamic);
}

// Loaded beyond Tmax the rope follows the OWC; the commit raises Tmax; unloaded, it follows the new working
// curve, which starts at a larger strain (the rope has taken a permanent stretch): at the same strain its
// tension is below the OWC's and below the old working curve's.
TEST(SyropeAxialLaw, RemembersTheLargestMeanTension) {
  const SyropeAxialLaw law(constants(WorkingCurveForm::Linear, 1.25e8, 0.0));
  const double tmax0 = 1.0e6;
  const double eps = 0.025;  // beyond X_owc(1 MN) = 0.0155
  const SyropeAxialLaw::Step loaded = law.step(eps, 0.0, 0.0, tmax0, 1e12);
  EXPECT_NEAR(loaded.meanTension, owc()->at(eps).value, 1e-6 * loaded.meanTension);  // on the OWC
  const double tmax1 = loaded.meanTension;
  const double back = 0.014;  // below X_owc(1 MN) = 0.0149: on both working curves
  EXPECT_LT(law.staticTension(back, tmax1), owc()->at(back).value - 1e4);
  // Linear working curves of slope k1: k1 (back - eps_min) with eps_min = X_owc(Tmax) - Tmax / k1.
  EXPECT_NEAR(law.staticTension(back, tmax0), 1.25e8 * (back - law.slackStrain(tmax0)), 1e-6 * tmax0);
  EXPECT_LT(law.staticTension(back, tmax1), 0.5 * law.staticTension(back, tmax0));
}

TEST(SyropeAxialLaw, RefusesCurvesAndParametersOutOfRange) {
  auto bad = constants(WorkingCurveForm::Quadratic, 1.5, 0.5);  // k1 >= 1 for a quadratic curve
  EXPECT_THROW(SyropeAxialLaw{bad}, Error);
  bad = constants(WorkingCurveForm::Exponential, 0.2, 0.0);  // k2 = 0: no exponential
  EXPECT_THROW(SyropeAxialLaw{bad}, Error);
  bad = constants(WorkingCurveForm::Linear, 1.25e8, 0.0);
  bad.dynamicStiffness = 1e6;  // softer than the curve: the slow strain would fall along it
  EXPECT_THROW(SyropeAxialLaw{bad}, Error);
}

}  // namespace
}  // namespace tangle::element
