/// @file CurrentGridTest.cpp
/// A current on a grid in space and time (tangle::hydro::CurrentGrid, readCurrentGridFile) and its use
/// through CurrentProfile::withGrid.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tangle/core/Error.hpp"
#include "tangle/hydro/CurrentGrid.hpp"
#include "tangle/hydro/CurrentProfile.hpp"

namespace tangle::hydro {
namespace {

// A field linear in each coordinate and in their products (multilinear): quadrilinear interpolation
// reproduces it exactly inside the grid (source: the interpolant's definition), so the check is to round-off,
// 1e-12 m/s on values of O(10).
Vec3 multilinear(double x, double y, double z, double t) {
  return Vec3(1.0 + 0.1 * x - 0.2 * y + 0.05 * z + 0.3 * t + 0.01 * x * t, -0.5 + 0.02 * x * y + 0.1 * z * t,
              0.01 * x * y * z * t);
}

const std::array<std::vector<double>, 4> kTicks = {
    std::vector<double>{-10.0, 0.0, 25.0}, std::vector<double>{-5.0, 5.0},
    std::vector<double>{-50.0, -20.0, -5.0, 0.0}, std::vector<double>{0.0, 10.0}};

CurrentGrid sampledGrid() {
  std::vector<Vec3> v;
  for (double x : kTicks[0])
    for (double y : kTicks[1])
      for (double z : kTicks[2])
        for (double t : kTicks[3]) v.push_back(multilinear(x, y, z, t));
  return CurrentGrid(kTicks, std::move(v));
}

TEST(CurrentGrid, ReproducesAMultilinearFieldInsideTheGrid) {
  const CurrentGrid grid = sampledGrid();
  for (double x : {-10.0, -3.3, 0.0, 7.0, 25.0})
    for (double y : {-5.0, 1.7, 5.0})
      for (double z : {-50.0, -31.0, -5.0, -0.4})
        for (double t : {0.0, 2.5, 9.9})
          EXPECT_LT((grid.velocity(Vec3(x, y, z), t) - multilinear(x, y, z, t)).norm(), 1e-12)
              << x << " " << y << " " << z << " " << t;
}

// Outside the grid each coordinate is clamped to its end tick (the class's contract): beyond the last time
// the last velocities hold.
TEST(CurrentGrid, ClampsEachCoordinateOutsideTheGrid) {
  const CurrentGrid grid = sampledGrid();
  EXPECT_LT((grid.velocity(Vec3(-40.0, 9.0, 3.0), 50.0) - multilinear(-10.0, 5.0, 0.0, 10.0)).norm(), 1e-12);
  EXPECT_LT((grid.velocity(Vec3(30.0, -9.0, -80.0), -1.0) - multilinear(25.0, -5.0, -50.0, 0.0)).norm(),
            1e-12);
}

TEST(CurrentGrid, AnAxisOfOneTickIsConstantAlongIt) {
  const CurrentGrid steady({std::vector<double>{0.0, 10.0}, {0.0}, {-10.0, 0.0}, {0.0}},
                           {Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(5, 0, 0)});
  // x = 5 halfway, z = -5 halfway: the mean of the four values, at any y and t.
  EXPECT_NEAR(steady.velocity(Vec3(5.0, 123.0, -5.0), 77.0).x(), 2.75, 1e-15);
  EXPECT_FALSE(steady.isZero());
}

TEST(CurrentGrid, RefusesTicksThatDoNotIncreaseAndSizesThatDiffer) {
  EXPECT_THROW(
      CurrentGrid({std::vector<double>{0.0, 0.0}, {0.0}, {0.0}, {0.0}}, {Vec3::Zero(), Vec3::Zero()}), Error);
  EXPECT_THROW(CurrentGrid({std::vector<double>{0.0, 1.0}, {0.0}, {0.0}, {0.0}}, {Vec3::Zero()}), Error);
  EXPECT_THROW(CurrentGrid({std::vector<double>{}, {0.0}, {0.0}, {0.0}}, {}), Error);
}

TEST(CurrentGrid, AProfileWithAGridAnswersWithTheGrid) {
  const CurrentProfile current = CurrentProfile::withGrid(std::make_shared<const CurrentGrid>(sampledGrid()));
  EXPECT_LT((current.velocity(Vec3(3.0, 1.0, -7.0), 4.0) - multilinear(3.0, 1.0, -7.0, 4.0)).norm(), 1e-12);
  EXPECT_TRUE(current.changes());
  EXPECT_FALSE(current.isZero());
}

// ---- The file (MoorDyn's current_profile_4d.txt format)

class CurrentGridFile : public ::testing::Test {
 protected:
  std::string write(const std::string& text) {
    const std::string path =
        (std::filesystem::temp_directory_path() /
         ("tangle-current-grid-" +
          std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".txt"))
            .string();
    std::ofstream(path) << text;
    m_paths.push_back(path);
    return path;
  }
  void TearDown() override {
    for (const std::string& p : m_paths) std::filesystem::remove(p);
  }
  /// The message of the InputError reading `text` throws (empty if none).
  std::string errorOf(const std::string& text) {
    try {
      readCurrentGridFile(write(text));
    } catch (const InputError& e) {
      return e.what();
    }
    return {};
  }
  std::vector<std::string> m_paths;
};

// Rows in any order, each node once: the grid as given (MoorDyn's format; its first row is read too).
TEST_F(CurrentGridFile, ReadsRowsInAnyOrder) {
  const CurrentGrid grid =
      readCurrentGridFile(write("2 1 2 1\n0 10\n0\n-20 0\n0\n"
                                "10 0 0 0 4 0 0\n0 0 -20 0 1 0.5 0\n\n0 0 0 0 2 0 0\n10 0 -20 0 3 0 -0.1\n"));
  EXPECT_NEAR(grid.velocity(Vec3(0.0, 0.0, -20.0), 0.0).y(), 0.5,
              1e-15);  // the first row, which MoorDyn skips
  EXPECT_NEAR(grid.velocity(Vec3(5.0, 0.0, -10.0), 3.0).x(), 2.5, 1e-15);
  EXPECT_NEAR(grid.velocity(Vec3(10.0, 0.0, -20.0), 0.0).z(), -0.1, 1e-15);
}

TEST_F(CurrentGridFile, NamesTheLineAndWhatWasExpected) {
  const std::string head = "2 1 1 1\n0 10\n0\n0\n0\n";
  EXPECT_NE(errorOf("1e84 1 1 1\n0\n0\n0\n0\n0 0 0 0 1 0 0\n").find("nx"), std::string::npos);
  EXPECT_NE(errorOf("1e84 1 1 1\n0\n0\n0\n0\n0 0 0 0 1 0 0\n").find("whole number"), std::string::npos);
  EXPECT_NE(errorOf(head + "0 0 0 0 1 0 0\n").find("one row per grid node: 2 rows, got 1"),
            std::string::npos);
  EXPECT_NE(errorOf(head + "0 0 0 0 1 0 0\n5 0 0 0 1 0 0\n").find(":7: key 'x': one of the x ticks, got 5"),
            std::string::npos)
      << errorOf(head + "0 0 0 0 1 0 0\n5 0 0 0 1 0 0\n");
  EXPECT_NE(errorOf(head + "0 0 0 0 1 0 0\n0 0 0 0 1 0 0\n").find("this node was given before"),
            std::string::npos);
  EXPECT_NE(errorOf(head + "0 0 0 0 1 0 0\n10 0 0 0 1 nan 0\n").find("a finite number, got 'nan'"),
            std::string::npos);
  EXPECT_NE(errorOf("2 1 1 1\n10 0\n0\n0\n0\n0 0 0 0 1 0 0\n10 0 0 0 1 0 0\n").find("increasing ticks"),
            std::string::npos);
  EXPECT_NE(errorOf(head + "0 0 0 0 1 0\n10 0 0 0 1 0 0\n").find("7 numbers, got 6"), std::string::npos);
  EXPECT_THROW(readCurrentGridFile("/no/such/current_profile_4d.txt"), InputError);
}

}  // namespace
}  // namespace tangle::hydro
