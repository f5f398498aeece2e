// Unit tests of the seabed's shape (SeabedSurface: flat, plane, bathymetry grid, MoorDyn's SeafloorFile) and
// of the seabed reaction on a slope (Seabed with a plane). References: plane geometry (the distance of a
// point to a plane, the plane's normal), bilinear interpolation by hand, the reaction's own force
// differentiated by central differences (its tangent must be consistent: Newton's quadratic convergence on a
// slope depends on it), and the flat seabed's numbers (a plane of zero slope is flat, bit for bit).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "TestPaths.hpp"
#include "tangle/core/Error.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/seabed/Seabed.hpp"
#include "tangle/seabed/SeabedSurface.hpp"

namespace tangle {
namespace {

using seabed::SeabedSurface;

TEST(SeabedSurface, PlaneRisesTowardsItsUpslopeAzimuth) {
  // 100 m deep at the origin, rising 10 degrees towards azimuth 30 degrees.
  const double slope = degToRad(10.0), azimuth = degToRad(30.0);
  const SeabedSurface s = SeabedSurface::plane(100.0, slope, azimuth);
  const Vec2 up(std::cos(azimuth), std::sin(azimuth));
  EXPECT_DOUBLE_EQ(s.height(0.0, 0.0), -100.0);
  EXPECT_NEAR(s.height(50.0 * up.x(), 50.0 * up.y()), -100.0 + 50.0 * std::tan(slope), 1e-12);
  // Across the slope the height does not change.
  EXPECT_NEAR(s.height(-80.0 * up.y(), 80.0 * up.x()), -100.0, 1e-12);
  const Vec3 n = s.at(3.0, 4.0).normal;
  EXPECT_NEAR(n.norm(), 1.0, 1e-15);
  EXPECT_NEAR(n.z(), std::cos(slope), 1e-15);
  // The normal leans down-slope (away from the rise).
  EXPECT_NEAR(n.x(), -std::sin(slope) * up.x(), 1e-15);
  EXPECT_NEAR(n.y(), -std::sin(slope) * up.y(), 1e-15);
}

TEST(SeabedSurface, GapOnAPlaneIsThePerpendicularDistanceLessTheRadius) {
  const SeabedSurface s = SeabedSurface::plane(50.0, degToRad(20.0), degToRad(-60.0));
  const Vec3 n = s.at(0.0, 0.0).normal;
  const Vec3 onPlane(12.0, -7.0, s.height(12.0, -7.0));
  for (const double distance : {-0.3, 0.0, 0.05, 2.0}) {
    const Vec3 p = onPlane + distance * n;
    EXPECT_NEAR(s.gap(p, 0.1), distance - 0.1, 1e-12) << distance;
    // The footprint is the foot of the normal: back on the plane.
    const Vec2 f = s.footprint(p);
    EXPECT_NEAR(f.x(), onPlane.x(), 1e-12);
    EXPECT_NEAR(f.y(), onPlane.y(), 1e-12);
  }
  // restingZ puts a sphere's centre at (radius - penetration) from the plane along the normal.
  const double z = s.restingZ(3.0, 4.0, 0.2, 0.01);
  EXPECT_NEAR(s.gap(Vec3(3.0, 4.0, z), 0.2), -0.01, 1e-12);
}

TEST(SeabedSurface, FlatAndZeroSlopeAreTheFlatArithmetic) {
  const SeabedSurface flat = SeabedSurface::flat(75.0);
  const SeabedSurface plane = SeabedSurface::plane(75.0, 0.0, 1.0);
  EXPECT_TRUE(plane.isFlat());
  const Vec3 p(1.0, 2.0, -74.93);
  EXPECT_EQ(flat.gap(p, 0.05), (p.z() - 0.05) + 75.0);
  EXPECT_EQ(flat.restingZ(1.0, 2.0, 0.05, 0.001), -75.0 + 0.05 - 0.001);
  EXPECT_EQ(flat.footprint(p), Vec2(1.0, 2.0));
}

TEST(SeabedSurface, GridInterpolatesBilinearlyAndHoldsTheEdgeValueBeyond) {
  // Heights at x = {0, 10, 30}, y = {0, 20}, y-major.
  const SeabedSurface s = SeabedSurface::grid({0.0, 10.0, 30.0}, {0.0, 20.0},
                                              {-100.0, -90.0, -60.0,    // y = 0
                                               -110.0, -96.0, -70.0});  // y = 20
  EXPECT_DOUBLE_EQ(s.height(10.0, 20.0), -96.0);                        // a node
  // Middle of the second cell: the mean of its four corners.
  EXPECT_NEAR(s.height(20.0, 10.0), 0.25 * (-90.0 - 60.0 - 96.0 - 70.0), 1e-12);
  // By hand at (4, 5): fx = 0.4, fy = 0.25.
  const double h = 0.6 * 0.75 * -100.0 + 0.4 * 0.75 * -90.0 + 0.6 * 0.25 * -110.0 + 0.4 * 0.25 * -96.0;
  EXPECT_NEAR(s.height(4.0, 5.0), h, 1e-12);
  // Gradient there: dh/dx = ((1 - fy)(h10 - h00) + fy (h11 - h01)) / 10, dh/dy likewise.
  const double gx = (0.75 * 10.0 + 0.25 * 14.0) / 10.0, gy = (0.6 * -10.0 + 0.4 * -6.0) / 20.0;
  const Vec3 n = s.at(4.0, 5.0).normal;
  EXPECT_NEAR(n.x() / n.z(), -gx, 1e-12);
  EXPECT_NEAR(n.y() / n.z(), -gy, 1e-12);
  // Beyond the grid: held at the edge value (MoorDyn's interp_factor), flat across.
  EXPECT_DOUBLE_EQ(s.height(-50.0, 0.0), -100.0);
  EXPECT_DOUBLE_EQ(s.height(99.0, 99.0), -70.0);
  EXPECT_NEAR(s.at(-50.0, -40.0).normal.z(), 1.0, 1e-15);
  EXPECT_DOUBLE_EQ(s.referenceDepth(), 110.0);
  EXPECT_THROW(SeabedSurface::grid({0.0, 0.0}, {0.0}, {-1.0, -1.0}), std::invalid_argument);
  EXPECT_THROW(SeabedSurface::grid({0.0, 1.0}, {0.0}, {-1.0}), std::invalid_argument);
}

TEST(SeabedSurface, CubicGridGoesThroughItsNodesAndReproducesAPlane) {
  // Uneven ticks; a plane z = -100 + 0.1 x - 0.05 y is reproduced exactly (the three-point and one-sided
  // differences are exact for it, and the bicubic Hermite patch reproduces bilinear functions).
  const std::vector<double> x{0.0, 10.0, 30.0, 35.0}, y{-20.0, 0.0, 25.0};
  std::vector<double> h;
  for (const double yj : y)
    for (const double xi : x) h.push_back(-100.0 + 0.1 * xi - 0.05 * yj);
  const SeabedSurface s = SeabedSurface::grid(x, y, h, SeabedSurface::Interpolation::Cubic);
  EXPECT_EQ(s.interpolation(), SeabedSurface::Interpolation::Cubic);
  for (const double px : {0.0, 3.0, 10.0, 21.0, 33.0})
    for (const double py : {-20.0, -7.0, 0.0, 12.5, 25.0}) {
      EXPECT_NEAR(s.height(px, py), -100.0 + 0.1 * px - 0.05 * py, 1e-12) << px << ", " << py;
      const Vec3 n = s.at(px + 0.3, 0.9 * py).normal;  // inside the grid (px + 0.3 <= 33.3 < 35)
      EXPECT_NEAR(n.x() / n.z(), -0.1, 1e-12);
      EXPECT_NEAR(n.y() / n.z(), 0.05, 1e-12);
    }
}

TEST(SeabedSurface, CubicGridsNormalIsContinuousAcrossCellEdgesWhereTheBilinearTurns) {
  // A trough along x = 0: the bilinear surface has a crease there (its slope jumps from -0.2 to +0.2), the
  // bicubic one turns smoothly through it.
  const std::vector<double> x{-40.0, -20.0, 0.0, 20.0, 40.0}, y{-10.0, 10.0};
  std::vector<double> h;
  for (int j = 0; j < 2; ++j)
    for (const double xi : x) h.push_back(-100.0 + 0.01 * xi * xi);
  const SeabedSurface cubic = SeabedSurface::grid(x, y, h, SeabedSurface::Interpolation::Cubic);
  const SeabedSurface bilinear = cubic.interpolated(SeabedSurface::Interpolation::Bilinear);
  const double e = 1e-9;
  for (const double edge : {-20.0, 0.0, 20.0}) {
    const Vec3 left = cubic.at(edge - e, 0.0).normal, right = cubic.at(edge + e, 0.0).normal;
    EXPECT_LT((left - right).norm(), 1e-8) << "cubic at x = " << edge;
    EXPECT_NEAR(cubic.height(edge, 0.0), -100.0 + 0.01 * edge * edge, 1e-12);
  }
  EXPECT_GT((bilinear.at(-e, 0.0).normal - bilinear.at(e, 0.0).normal).norm(), 0.3) << "the bilinear crease";
  // The normal is the height's gradient (central differences) inside the cells.
  for (const double px : {-33.0, -5.0, 7.0, 29.0}) {
    const double d = 1e-5;
    const double gx = (cubic.height(px + d, 3.0) - cubic.height(px - d, 3.0)) / (2.0 * d);
    const Vec3 n = cubic.at(px, 3.0).normal;
    EXPECT_NEAR(-n.x() / n.z(), gx, 1e-7) << px;
  }
  // Interior nodes' slopes are the parabola's: exact for this quadratic (0.02 x).
  const Vec3 n = cubic.at(-20.0 + 1e-12, 0.0).normal;
  EXPECT_NEAR(-n.x() / n.z(), -0.4, 1e-9);
}

TEST(SeabedSurface, ReadsMoorDynsSeafloorFile) {
  // MoorDyn v2.7.1 tests/Mooring/3D_seafloor/seafloor_profile_3d.txt: 100 x 5 nodes of z = -30 + 0.2 x (the
  // file's rows, from -40 m at x = -50 m to -20 m at x = 50 m; its make_3d_seafloor.py writes 0.1 x, the file
  // committed beside it was made with 0.2 x). Bilinear interpolation of planar data is exact.
  const SeabedSurface s = seabed::readSeafloorFile(std::string(test::kTestDataDir) +
                                                   "/moordyn/Mooring/3D_seafloor/seafloor_profile_3d.txt");
  ASSERT_EQ(s.kind(), SeabedSurface::Kind::Grid);
  EXPECT_EQ(s.gridX().size(), 100u);
  EXPECT_EQ(s.gridY().size(), 5u);
  for (const double x : {-50.0, -12.34, 0.0, 27.5, 49.9})
    EXPECT_NEAR(s.height(x, 0.7), -30.0 + 0.2 * x, 1e-9) << x;
  EXPECT_NEAR(s.at(5.0, 0.0).normal.x() / s.at(5.0, 0.0).normal.z(), -0.2, 1e-9);
}

TEST(SeabedSurface, SeafloorFileErrorsNameTheFileAndLine) {
  const std::string path = ::testing::TempDir() + "bad_seafloor.txt";
  auto expectError = [&](const std::string& text, const std::string& fragment) {
    {
      std::ofstream out(path);
      out << text;
    }
    try {
      seabed::readSeafloorFile(path);
      ADD_FAILURE() << "no error for:\n" << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  };
  expectError("2 2\n0 1\n0 1\n0 0 -10\n0 1 -10\n1 0 -10\n", "a row for every grid node");
  expectError("2 2\n0 1\n0\n0 0 -10\n", "2 ticks");
  expectError("1e84 2\n0 1\n0 1\n0 0 -10\n", "whole number");
  expectError("2 1\n1 0\n0\n0 0 -10\n1 0 -10\n", "increasing");
  expectError("1 1\n0\n0\n0 0 abc\n", "a finite number");
  expectError("1 1\n0\n0\n0 0 5\n", "z <= 0");
  std::remove(path.c_str());
  EXPECT_THROW(seabed::readSeafloorFile(path), InputError);
}

seabed::SeabedSpec slopeSpec(bool elastic) {
  seabed::SeabedSpec s;
  s.normalStiffness = 2.0e5;
  s.damping = 3.0e3;
  s.frictionCoefficient = 0.4;
  s.frictionVelocity = 0.02;
  s.elasticFriction = elastic;
  return s;
}

TEST(SeabedOnASlope, ReactionIsNormalToThePlaneAndFrictionInIt) {
  auto surface =
      std::make_shared<const SeabedSurface>(SeabedSurface::plane(100.0, degToRad(15.0), degToRad(45.0)));
  const seabed::Seabed bed(slopeSpec(false), surface);
  const Vec3 n = surface->at(0.0, 0.0).normal;
  const Vec3 p = Vec3(5.0, -3.0, surface->height(5.0, -3.0)) + (0.05 - 0.01) * n;  // 1 cm in, radius 5 cm
  // At rest: the force is along the normal, k L (delta - d_s / 2) (the linear branch).
  const seabed::SeabedNodeReaction rest = bed.reaction(p, Vec3::Zero(), 2.0, 0.05, true);
  EXPECT_NEAR(rest.penetration, 0.01, 1e-12);
  const double expected = 2.0e5 * 2.0 * (0.01 - 0.5 * seabed::Seabed::kSmoothPenetration);
  EXPECT_NEAR(rest.force.dot(n), expected, 1e-9 * expected);
  EXPECT_NEAR((rest.force - rest.force.dot(n) * n).norm(), 0.0, 1e-9 * expected);
  // Sliding fast along the slope: friction mu N opposite to the tangential velocity; a normal velocity
  // component changes only the dashpot.
  const Vec3 along = n.unitOrthogonal();
  const Vec3 v = 0.5 * along - 0.001 * n;
  const seabed::SeabedNodeReaction r = bed.reaction(p, v, 2.0, 0.05, true);
  const double normal = expected + 3.0e3 * 2.0 * 0.001;
  EXPECT_NEAR(r.normalForce, normal, 1e-9 * normal);
  EXPECT_NEAR(r.force.dot(n), normal, 1e-9 * normal);
  EXPECT_NEAR(r.force.dot(along), -0.4 * normal, 1e-9 * normal);
  EXPECT_EQ(bed.reactionForce(p, v, 2.0, 0.05, true), r.force);
}

/// -d(force)/d(position) of a reaction by central differences.
template <class Force>
Mat3 numericalStiffness(const Force& force, const Vec3& p, double h) {
  Mat3 k;
  for (int j = 0; j < 3; ++j) {
    Vec3 dp = Vec3::Zero();
    dp(j) = h;
    k.col(j) = -(force(p + dp) - force(p - dp)) / (2.0 * h);
  }
  return k;
}

TEST(SeabedOnASlope, TangentsAreTheDerivativesOfTheForces) {
  auto surface =
      std::make_shared<const SeabedSurface>(SeabedSurface::plane(100.0, degToRad(12.0), degToRad(-110.0)));
  const Vec3 n = surface->at(0.0, 0.0).normal;
  const Vec3 p = Vec3(-4.0, 9.0, surface->height(-4.0, 9.0)) + (0.1 - 0.02) * n;  // 2 cm in, radius 10 cm
  const Vec3 t = n.unitOrthogonal();
  // Viscous friction, sliding and in the linear branch.
  const seabed::Seabed viscous(slopeSpec(false), surface);
  for (const double speed : {0.3, 0.005}) {
    const Vec3 v = speed * t;
    const auto force = [&](const Vec3& x) { return viscous.reaction(x, v, 1.5, 0.1, true).force; };
    const Mat3 k = viscous.reaction(p, v, 1.5, 0.1, true).stiffness;
    EXPECT_LT((k - numericalStiffness(force, p, 1e-7)).norm(), 1e-5 * k.norm()) << speed;
  }
  // Elastic friction (statics): stick and slip, the anchor 1 mm and 10 cm away along the slope.
  const seabed::Seabed elastic(slopeSpec(true), surface);
  for (const double offset : {0.001, 0.1}) {
    const Vec3 anchorPoint = p - (0.1 - 0.02) * n - offset * t;
    const Vec2 anchor(anchorPoint.x(), anchorPoint.y());
    const auto total = [&](const Vec3& x) {
      const seabed::SeabedNodeReaction r = elastic.reaction(x, Vec3::Zero(), 1.5, 0.1, false);
      return Vec3(r.force + elastic
                                .staticFriction(x, anchor, r.normalForce, r.normalStiffness, 1.5,
                                                Vec3::Zero(), 0.0, r.normal)
                                .force);
    };
    const seabed::SeabedNodeReaction r = elastic.reaction(p, Vec3::Zero(), 1.5, 0.1, false);
    const seabed::StaticFrictionResult f =
        elastic.staticFriction(p, anchor, r.normalForce, r.normalStiffness, 1.5, Vec3::Zero(), 0.0, r.normal);
    EXPECT_EQ(f.sliding, offset > 0.01);
    // The friction lies in the tangent plane, against the slip.
    EXPECT_NEAR(f.force.dot(n), 0.0, 1e-9 * f.force.norm());
    EXPECT_LT(f.force.dot(t), 0.0);
    const Mat3 k = r.stiffness + f.stiffness;
    EXPECT_LT((k - numericalStiffness(total, p, 1e-8)).norm(), 1e-5 * k.norm()) << offset;
    if (f.sliding) {
      // The anchor is dragged to cap / kt behind the node, on the seabed.
      const Vec3 a(f.anchor.x(), f.anchor.y(), surface->height(f.anchor.x(), f.anchor.y()));
      EXPECT_NEAR((a - (p - (0.1 - 0.02) * n)).norm(), 0.4 * r.normalForce / (2.0e5 * 1.5), 1e-9);
    }
  }
}

// The elastic friction in dynamics (docs/theory.md 5.4): the stick spring with its dashpot c beside it, the
// trial force -kt s - c v_t capped at mu N. Its stiffness and damping must be -dF/dx and -dF/dv (central
// differences; the cap's N held for dv, as the tangent documents) in stick and in slip, with the velocity
// across the slip so that the dashpot turns the force: in slip the dashpot's share was left out of both until
// 2026-12-07 (a sliding laid node then converged linearly, about 0.66 per Newton iteration). Tolerance 1e-5
// of the tangent's norm: central differences of a smooth function at steps of 1e-7 m and 1e-7 m/s.
TEST(SeabedOnASlope, ElasticFrictionInDynamicsHasTheDerivativesOfItsForce) {
  auto surface =
      std::make_shared<const SeabedSurface>(SeabedSurface::plane(100.0, degToRad(12.0), degToRad(-110.0)));
  const Vec3 n = surface->at(0.0, 0.0).normal;
  const Vec3 p = Vec3(-4.0, 9.0, surface->height(-4.0, 9.0)) + (0.1 - 0.02) * n;  // 2 cm in, radius 10 cm
  const Vec3 t = n.unitOrthogonal(), across = n.cross(t);
  const seabed::Seabed elastic(slopeSpec(true), surface);
  const double tributary = 1.5, dashpot = 4.0e4;
  const Vec3 anchorPoint = p - (0.1 - 0.02) * n;
  for (const double offset : {0.001, 0.1}) {
    for (const double speed : {0.0, 0.01, 0.3}) {
      const Vec2 anchor = Vec2((anchorPoint - offset * t).x(), (anchorPoint - offset * t).y());
      const Vec3 v = speed * across;
      const seabed::SeabedNodeReaction r = elastic.reaction(p, v, tributary, 0.1, true);
      const auto friction = [&](const Vec3& x, const Vec3& u, double normal, double normalStiffness) {
        return elastic.staticFriction(x, anchor, normal, normalStiffness, tributary, u, dashpot, r.normal);
      };
      const seabed::StaticFrictionResult f = friction(p, v, r.normalForce, r.normalStiffness);
      const auto total = [&](const Vec3& x) {
        const seabed::SeabedNodeReaction rx = elastic.reaction(x, v, tributary, 0.1, true);
        return Vec3(rx.force + friction(x, v, rx.normalForce, rx.normalStiffness).force);
      };
      const auto ofVelocity = [&](const Vec3& u) {
        return friction(p, u, r.normalForce, r.normalStiffness).force;
      };
      const Mat3 k = r.stiffness + f.stiffness;
      EXPECT_LT((k - numericalStiffness(total, p, 1e-7)).norm(), 1e-5 * k.norm())
          << "offset " << offset << " speed " << speed << (f.sliding ? " sliding" : " stuck");
      EXPECT_LT((f.damping - numericalStiffness(ofVelocity, v, 1e-7)).norm(), 1e-5 * f.damping.norm())
          << "offset " << offset << " speed " << speed << (f.sliding ? " sliding" : " stuck");
    }
  }
}

}  // namespace
}  // namespace tangle
