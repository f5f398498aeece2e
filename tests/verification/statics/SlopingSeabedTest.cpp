// Statics on a sloping seabed (issue 46) against an independent solution of the elastic catenary resting on a
// frictionless incline, written here from first principles (not tangle's catenary code):
//  - the laid part lies straight along the incline (inclination beta along the line, > 0 rising towards the
//    fairlead); without friction its tension changes only by the weight's component along it,
//    dT/ds = w sin(beta), so T_anchor = T_td - w sin(beta) L_g, and it stretches by int T / EA ds;
//  - a cable leaves a smooth seabed tangentially: at the touchdown point the catenary's inclination is beta,
//    so its vertical force there is V0 = H tan(beta) and T_td = H / cos(beta);
//  - the suspended part is the elastic catenary from (H, V0) over L_s = L - L_g (Irvine 1981, "Cable
//    Structures", eq. 2.3 generalised to a start with V0 != 0):
//      dx = H/w [asinh(V1/H) - asinh(V0/H)] + H L_s / EA,
//      dz = H/w [sqrt(1 + (V1/H)^2) - sqrt(1 + (V0/H)^2)] + (V0 L_s + w L_s^2 / 2) / EA,  V1 = V0 + w L_s;
//  - H and L_g make the fairlead's position; solved by Newton to 1e-10 m.
// The incline is the plane of the laid line's centreline: through the seated anchor, parallel to the seabed
// (the line rests one contact radius above it along the normal). The seabed's stiffness (1e7 N/m/m) makes the
// penetration about 1e-4 m, negligible against the tolerances.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "support/ModelFactory.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/seabed/SeabedSurface.hpp"
#include "tangle/solver/Assembler.hpp"
#include "tangle/solver/LineResults.hpp"
#include "tangle/solver/StaticSolver.hpp"

namespace tangle {
namespace {

/// The catenary on a frictionless incline (see the file's comment).
struct InclineCatenary {
  double horizontalTension = 0.0;  ///< H [N]
  double groundedLength = 0.0;     ///< L_g, unstretched [m]
  double fairleadTension = 0.0;    ///< [N]
  double anchorTension = 0.0;      ///< [N]
};

/// `mu`: friction fully mobilised against the laid part's slide towards the fairlead, so that its tension
/// falls towards the anchor by w (sin(beta) + mu cos(beta)) per metre (0: frictionless).
InclineCatenary solveInclineCatenary(double span, double height, double beta, double length, double w,
                                     double ea, double mu = 0.0) {
  const double gradient = w * (std::sin(beta) + mu * std::cos(beta));  // dT/ds along the laid part [N/m]
  // Residual of the fairlead's position (along the line's azimuth, up) for a trial H and L_g.
  auto residual = [&](double h, double lg) {
    const double tdp = h / std::cos(beta);
    const double anchor = tdp - gradient * lg;
    const double stretchedGround = lg + (anchor * lg + 0.5 * gradient * lg * lg) / ea;
    const double ls = length - lg;
    const double v0 = h * std::tan(beta), v1 = v0 + w * ls;
    const double dx = h / w * (std::asinh(v1 / h) - std::asinh(v0 / h)) + h * ls / ea;
    const double dz =
        h / w * (std::hypot(1.0, v1 / h) - std::hypot(1.0, v0 / h)) + (v0 * ls + 0.5 * w * ls * ls) / ea;
    return Vec2(stretchedGround * std::cos(beta) + dx - span, stretchedGround * std::sin(beta) + dz - height);
  };
  double h = 0.3 * w * length, lg = 0.3 * length;
  for (int it = 0; it < 200; ++it) {
    const Vec2 r = residual(h, lg);
    if (r.norm() < 1e-10) break;
    Eigen::Matrix2d j;
    const double dh = 1e-6 * h, dl = 1e-6 * length;
    j.col(0) = (residual(h + dh, lg) - residual(h - dh, lg)) / (2.0 * dh);
    j.col(1) = (residual(h, lg + dl) - residual(h, lg - dl)) / (2.0 * dl);
    Vec2 step = j.fullPivLu().solve(-r);
    // Damped: H stays positive and L_g within the line.
    double f = 1.0;
    while (f > 1e-6 && (h + f * step.x() <= 0.0 || lg + f * step.y() < 0.0 || lg + f * step.y() > length))
      f *= 0.5;
    h += f * step.x();
    lg += f * step.y();
  }
  EXPECT_LT(residual(h, lg).norm(), 1e-8) << "the reference did not converge";
  InclineCatenary c;
  c.horizontalTension = h;
  c.groundedLength = lg;
  const double v1 = h * std::tan(beta) + w * (length - lg);
  c.fairleadTension = std::hypot(h, v1);
  c.anchorTension = h / std::cos(beta) - gradient * lg;
  return c;
}

/// Solves the statics of `m` from its initial state; `result` gets the solver's result, and the line results
/// (end tensions, touchdown) at the state reached are returned.
std::vector<solver::LineSnapshot> solveStatics(const model::Model& m, solver::StaticResult& result) {
  solver::Assembler assembler(m);
  model::State s = m.initialState();
  result = solver::StaticSolver(assembler, m.spec().statics).solve(s);
  VecX force;
  solver::AssemblyRequest request;
  request.wantMatrix = false;
  assembler.assemble(s, request, force, nullptr);
  return solver::computeLineResults(m, assembler, s, force);
}

constexpr double kDepth = 100.0, kLength = 300.0, kDiameter = 0.1, kEa = 5.0e8;

struct SlopeCase {
  double slopeDeg;     // seabed slope [deg]
  double riseAzimuth;  // direction the seabed rises [deg]
  double lineAzimuth;  // anchor-to-fairlead direction [deg]
  double span;         // horizontal anchor-fairlead distance [m]: the laid part stays in tension
  int elements;
};

class CatenaryOnAnIncline : public ::testing::TestWithParam<SlopeCase> {};

TEST_P(CatenaryOnAnIncline, MatchesTheInclineCatenary) {
  const SlopeCase c = GetParam();
  model::ModelSpec spec;
  spec.sourceFile = "catenary on an incline (test)";
  spec.environment.waterDepth = kDepth;
  spec.environment.seabed.normalStiffness = 1.0e7;
  spec.environment.seabedSurface = std::make_shared<const seabed::SeabedSurface>(
      seabed::SeabedSurface::plane(kDepth, degToRad(c.slopeDeg), degToRad(c.riseAzimuth)));
  const section::LineType chain = test::cableType("chain", kDiameter, 100.0, kEa);
  spec.lineTypes[chain.name] = chain;
  const Vec2 dir(std::cos(degToRad(c.lineAzimuth)), std::sin(degToRad(c.lineAzimuth)));
  const Vec3 anchorGiven(0.0, 0.0, -kDepth);  // on the seabed: seated on its contact surface by the model
  const Vec3 fairlead(c.span * dir.x(), c.span * dir.y(), -10.0);
  spec.lines.push_back(test::simpleLine("chain", "chain", kLength, c.elements, model::EndKind::Anchored,
                                        anchorGiven, model::EndKind::Fixed, fairlead));
  const double w = chain.submergedWeight(spec.environment.waterDensity, spec.environment.gravity);

  model::Model m(std::move(spec));
  const Vec3 anchor = m.spec().lines[0].endA.position;
  // Seated: on the contact surface, one radius from the seabed along its normal, less the resting penetration
  // (0.6 mm: the smooth onset over the first 2 mm).
  EXPECT_NEAR(m.seabedSurface().gap(anchor, 0.5 * kDiameter), 0.0, 1e-3);
  solver::StaticResult r;
  const std::vector<solver::LineSnapshot> lines = solveStatics(m, r);
  ASSERT_TRUE(r.converged) << r.message;

  // The slope along the line: the seabed's rise per metre in the line's direction.
  const double beta =
      std::atan(std::tan(degToRad(c.slopeDeg)) * std::cos(degToRad(c.lineAzimuth - c.riseAzimuth)));
  const Vec3 chord = fairlead - anchor;
  const InclineCatenary exact =
      solveInclineCatenary(Vec2(chord.x(), chord.y()).norm(), chord.z(), beta, kLength, w, kEa);
  ASSERT_GT(exact.groundedLength, 20.0) << "the case must have a laid part";
  ASSERT_GT(exact.anchorTension, 0.0) << "the case must keep the laid part in tension";

  // Measured: fairlead and anchor tensions within 0.007 % of the reference in all four cases, touchdown
  // within 0.06-0.33 m (the touchdown estimate between 2 m elements). Issue 46's bound, 0.5 %; the polyline
  // with lumped weights differs from the continuous catenary by O((h w / H)^2) ~ 1e-5, and the tributary
  // weight at the anchor by w sin(beta) h / 2 ~ 1e-3 of T_anchor.
  EXPECT_NEAR(lines[0].endTensionB, exact.fairleadTension, 0.005 * exact.fairleadTension);
  EXPECT_NEAR(lines[0].endTensionA, exact.anchorTension, 0.005 * exact.anchorTension);
  const Vec3 fb = lines[0].endTensionForceB;
  EXPECT_NEAR(std::hypot(fb.x(), fb.y()), exact.horizontalTension, 0.005 * exact.horizontalTension);
  // Touchdown within 0.5 % of the line's length (a quarter element is 0.17 % at 150 elements).
  EXPECT_NEAR(lines[0].touchdownArcLength, exact.groundedLength, 0.005 * kLength);
  // The laid nodes rest on the incline: every node between the anchor and the touchdown within 1 mm of its
  // contact surface.
  for (std::size_t i = 1; i < lines[0].arcLength.size(); ++i) {
    if (lines[0].arcLength[i] < exact.groundedLength - 2.0 * kLength / c.elements) {
      EXPECT_NEAR(m.seabedSurface().gap(lines[0].position[i], 0.5 * kDiameter), 0.0, 1e-3) << i;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Slopes, CatenaryOnAnIncline,
    ::testing::Values(SlopeCase{5.0, 0.0, 0.0, 270.0, 150},      // rising towards the fairlead
                      SlopeCase{5.0, 180.0, 0.0, 250.0, 150},    // falling towards it
                      SlopeCase{8.0, 30.0, 30.0, 275.0, 150},    // rising, line at 30 deg
                      SlopeCase{8.0, 210.0, 30.0, 250.0, 150}),  // falling, line at 30 deg
    [](const ::testing::TestParamInfo<SlopeCase>& p) {
      return std::string(p.param.riseAzimuth == p.param.lineAzimuth ? "Rising" : "Falling") +
             std::to_string(static_cast<int>(p.param.slopeDeg)) + "DegLineAt" +
             std::to_string(static_cast<int>(p.param.lineAzimuth));
    });

}  // namespace
}  // namespace tangle

namespace tangle {
namespace {

/// A 20 m chain laid free along the fall line of a 20 degree slope (both ends free), friction `mu`.
model::ModelSpec freeChainOnSlope(double mu) {
  model::ModelSpec spec;
  spec.sourceFile = "free chain on a slope (test)";
  spec.environment.waterDepth = 100.0;
  spec.environment.seabed.normalStiffness = 1.0e6;
  spec.environment.seabed.frictionCoefficient = mu;
  const double slope = degToRad(20.0);
  spec.environment.seabedSurface =
      std::make_shared<const seabed::SeabedSurface>(seabed::SeabedSurface::plane(100.0, slope, 0.0));
  spec.lineTypes["chain"] = test::cableType("chain", 0.1, 100.0, 1.0e9);
  const Vec3 a(10.0, 0.0, -100.0 + 10.0 * std::tan(slope) + 0.05 / std::cos(slope));
  const Vec3 b = a + 20.0 * Vec3(std::cos(slope), 0.0, std::sin(slope));
  model::LineSpec line =
      test::simpleLine("chain", "chain", 20.0, 20, model::EndKind::Free, a, model::EndKind::Free, b);
  line.startShape = {model::StartPoint{a}, model::StartPoint{b}};
  spec.lines.push_back(line);
  return spec;
}

// Friction on a slope in statics (issue 46). Closed form: a laid line that nothing holds is in equilibrium on
// an incline only if mu >= tan(alpha) (Coulomb); tan(20 deg) = 0.364. Held (mu = 0.5): every node stays where
// it was laid within the friction springs' stretch along the slope, w sin(alpha) / k_t = 3e-4 m (1 mm
// allowed). Sliding (mu = 0.2): there is no equilibrium, and the solver must say so, naming the slope and the
// friction angle, never report a converged state.
TEST(FrictionOnASlope, HoldsAboveTheFrictionAngleAndHasNoEquilibriumBelowIt) {
  {
    model::Model m(freeChainOnSlope(0.5));
    solver::Assembler assembler(m);
    model::State s = m.initialState();
    const model::State start = s;
    const solver::StaticResult r = solver::StaticSolver(assembler, m.spec().statics).solve(s);
    ASSERT_TRUE(r.converged) << r.message;
    // Along the slope: the friction springs' stretch. Along the normal the nodes settle into the seabed by
    // their resting penetration (1.8 mm: the smooth onset at N = w cos(alpha), k = 1e6 N/m/m), laid without
    // it.
    const Vec3 fallLine = -Vec3(std::cos(degToRad(20.0)), 0.0, std::sin(degToRad(20.0)));
    for (std::size_t i = 0; i < s.position.size(); ++i) {
      const Vec3 d = s.position[i] - start.position[i];
      EXPECT_LT(std::abs(d.dot(fallLine)), 1e-3) << i;
      EXPECT_LT((d - d.dot(fallLine) * fallLine).norm(), 2.5e-3) << i;
    }
  }
  {
    model::Model m(freeChainOnSlope(0.2));
    solver::Assembler assembler(m);
    model::State s = m.initialState();
    const solver::StaticResult r = solver::StaticSolver(assembler, m.spec().statics).solve(s);
    EXPECT_FALSE(r.converged) << "a chain on a 20 deg slope with mu = 0.2 has no static equilibrium";
    EXPECT_NE(r.message.find("steeper than the friction angle"), std::string::npos) << r.message;
  }
}

// The catenary on an incline with friction (issue 46: "frictionless, then with friction", 0.5 %). Friction in
// statics depends on the path: here the line starts from a start shape 3 % shorter than the line (the laid
// part along the incline, then straight to the fairlead), so that reaching equilibrium stretches it: every
// laid node slides towards the fairlead, by metres against the friction spring's elastic range of
// mu w cos(beta) / k_s = 3e-5 m, and its friction is fully mobilised against that slide. The reference is
// then the incline catenary with the laid part's tension falling towards the anchor by
// w (sin(beta) + mu cos(beta)) per metre (solveInclineCatenary with mu).
TEST(CatenaryOnAnInclineWithFriction, MatchesTheInclineCatenaryWithMobilisedFriction) {
  constexpr double kMu = 0.3, kSlopeDeg = 5.0, kSpan = 280.0;
  const double slope = degToRad(kSlopeDeg);
  model::ModelSpec spec;
  spec.sourceFile = "catenary on an incline with friction (test)";
  spec.environment.waterDepth = kDepth;
  spec.environment.seabed.normalStiffness = 1.0e7;
  spec.environment.seabed.frictionCoefficient = kMu;
  spec.environment.seabedSurface =
      std::make_shared<const seabed::SeabedSurface>(seabed::SeabedSurface::plane(kDepth, slope, 0.0));
  const section::LineType chain = test::cableType("chain", kDiameter, 100.0, kEa);
  spec.lineTypes[chain.name] = chain;
  const Vec3 fairlead(kSpan, 0.0, -10.0);
  model::LineSpec line = test::simpleLine("chain", "chain", kLength, 150, model::EndKind::Anchored,
                                          Vec3(0.0, 0.0, -kDepth), model::EndKind::Fixed, fairlead);
  // The start shape: along the incline (its contact surface) to x1, then straight to the fairlead, 97 % of
  // the line's length (x1 by bisection).
  const auto onIncline = [&](double x) {
    return Vec3(x, 0.0, -kDepth + x * std::tan(slope) + 0.5 * kDiameter / std::cos(slope));
  };
  const auto polyline = [&](double x) { return x / std::cos(slope) + (fairlead - onIncline(x)).norm(); };
  double lo = 0.0, hi = kSpan - 1.0;
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    (polyline(mid) < 0.97 * kLength ? lo : hi) = mid;
  }
  line.startShape = {model::StartPoint{onIncline(0.0)}, model::StartPoint{onIncline(lo)},
                     model::StartPoint{fairlead}};
  spec.lines.push_back(line);
  const double w = chain.submergedWeight(spec.environment.waterDensity, spec.environment.gravity);

  model::Model m(std::move(spec));
  const Vec3 anchor = m.spec().lines[0].endA.position;
  solver::StaticResult r;
  const std::vector<solver::LineSnapshot> lines = solveStatics(m, r);
  ASSERT_TRUE(r.converged) << r.message;
  const Vec3 chord = fairlead - anchor;
  const InclineCatenary exact =
      solveInclineCatenary(Vec2(chord.x(), chord.y()).norm(), chord.z(), slope, kLength, w, kEa, kMu);
  const InclineCatenary frictionless =
      solveInclineCatenary(Vec2(chord.x(), chord.y()).norm(), chord.z(), slope, kLength, w, kEa);
  ASSERT_GT(exact.groundedLength, 20.0) << "the case must have a laid part";
  ASSERT_GT(exact.anchorTension, 0.0) << "the case must keep the laid part in tension";
  // The friction matters: the anchor tension differs from the frictionless one by far more than 0.5 %.
  ASSERT_GT(std::abs(exact.anchorTension - frictionless.anchorTension), 0.05 * exact.anchorTension);
  EXPECT_NEAR(lines[0].endTensionB, exact.fairleadTension, 0.005 * exact.fairleadTension);
  EXPECT_NEAR(lines[0].endTensionA, exact.anchorTension, 0.005 * exact.anchorTension);
  EXPECT_NEAR(lines[0].touchdownArcLength, exact.groundedLength, 0.005 * kLength);
}

/// A chain laid along the bottom of a V-shaped trough of a bathymetry grid (the trough's bottom is the grid
/// line x = 0, 8 m deeper than x = +-400 m), its fairlead held above the trough; `mu` seabed friction,
/// current `current` [m/s] across the trough (+x).
model::ModelSpec chainAlongATrough(seabed::SeabedSurface::Interpolation interpolation, double current) {
  model::ModelSpec spec;
  spec.sourceFile = "chain along a trough (test)";
  spec.environment.waterDepth = 183.0;
  spec.environment.seabed.normalStiffness = 1.0e6;
  spec.environment.seabed.frictionCoefficient = 0.5;
  if (current > 0.0) spec.environment.current = {{0.0, current, 0.0}, {-183.0, current, 0.0}};
  const std::vector<double> x{-400.0, 0.0, 400.0}, y{-1000.0, 0.0, 1000.0};
  std::vector<double> h;
  for (std::size_t j = 0; j < y.size(); ++j)
    for (const double xi : x) h.push_back(xi == 0.0 ? -183.0 : -175.0);
  spec.environment.seabedSurface =
      std::make_shared<const seabed::SeabedSurface>(seabed::SeabedSurface::grid(x, y, h, interpolation));
  spec.lineTypes["chain"] = test::cableType("chain", 0.1368, 114.9, 4.93e8);
  spec.lines.push_back(test::simpleLine("leg", "chain", 830.0, 166, model::EndKind::Anchored,
                                        Vec3(0.0, -780.0, -183.0), model::EndKind::Fixed,
                                        Vec3(0.0, 0.0, -15.0)));
  return spec;
}

// A line laid along a grid line of a bathymetry grid (issue 46's knife edge): on the bilinear surface the
// trough's bottom is a crease whose normal flips by 2.3 deg across it; on the bicubic one (the default of
// `bathymetry`) the surface is C1 and the grid line is the trough's smooth bottom, with slope 0 across it.
// There the line lies at the bottom, so its statics are those of the same line on a flat seabed at the
// trough's depth (183 m) in still water: fairlead and anchor tensions within 0.1 % (the trough's curvature
// across the line lifts nothing at its bottom; the seabed's penetration differs by the normal's tilt, 0).
// In a current across the trough (0.5 m/s) the line settles on the trough's flank: it must converge.
// Measured through the CLI on the same model: bicubic 4 Newton iterations in still water and 52 in the
// current; the bilinear grid does not converge in still water (1107 iterations, every fallback, load
// fraction 0.022: the knife edge) and takes 562 iterations and four load steps in the current.
TEST(BathymetryTrough, ALineAlongTheCubicTroughsBottomIsTheFlatSeabedsCatenary) {
  const auto tensions = [](model::ModelSpec spec, bool& converged) {
    const model::Model m(std::move(spec));
    solver::StaticResult r;
    const std::vector<solver::LineSnapshot> lines = solveStatics(m, r);
    converged = r.converged;
    EXPECT_TRUE(r.converged) << r.message;
    return std::array<double, 2>{lines[0].endTensionA, lines[0].endTensionB};
  };
  bool converged = false;
  model::ModelSpec flat = chainAlongATrough(seabed::SeabedSurface::Interpolation::Cubic, 0.0);
  flat.environment.seabedSurface.reset();
  const std::array<double, 2> reference = tensions(flat, converged);
  ASSERT_TRUE(converged);
  const std::array<double, 2> trough =
      tensions(chainAlongATrough(seabed::SeabedSurface::Interpolation::Cubic, 0.0), converged);
  ASSERT_TRUE(converged);
  EXPECT_NEAR(trough[0], reference[0], 1e-3 * reference[0]);
  EXPECT_NEAR(trough[1], reference[1], 1e-3 * reference[1]);
  tensions(chainAlongATrough(seabed::SeabedSurface::Interpolation::Cubic, 0.5), converged);
  EXPECT_TRUE(converged) << "a current across the trough";
}

}  // namespace
}  // namespace tangle
