// Contents of pipe lines (issue 45): each section's line type with its contents, their mass in the lumped
// node masses, and the internal pressure along the line (hydrostatic head of the contents column, summed
// element by element where sections hold different contents). Hand computations.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/ModelFactory.hpp"
#include "tangle/model/Model.hpp"

namespace tangle::model {
namespace {

constexpr double kPi = 3.141592653589793;
constexpr double kBore = 0.2;  // [m]
constexpr double kG = 9.80665;

/// A vertical line of two 50 m sections of a pipe (bore 0.2 m), end A at z = -100, end B at z = 0, 10
/// elements each.
ModelSpec verticalPipe(double lineDensity, double upperDensity, double pressure, double referenceZ) {
  ModelSpec spec;
  spec.sourceFile = "contents (test)";
  spec.environment.waterDepth = 200.0;
  section::LineType pipe = test::cableType("pipe", 0.3, 100.0, 1e9);
  pipe.internalDiameter = kBore;
  spec.lineTypes["pipe"] = pipe;
  LineSpec line = test::simpleLine("pipe", "pipe", 50.0, 10, EndKind::Pinned, Vec3(0, 0, -100.0), EndKind::Pinned,
                                   Vec3(0, 0, 0.0));
  line.sections.push_back({"pipe", 50.0, 10});
  line.sections[1].contentsDensity = upperDensity;
  line.contents.density = lineDensity;
  line.contents.pressure = pressure;
  line.contents.referenceZ = referenceZ;
  spec.lines.push_back(line);
  return spec;
}

/// The line's nodes on the vertical through the origin at their arc lengths from z = -100.
std::vector<Vec3> straightUp(const Model& m) {
  std::vector<Vec3> x;
  for (const double s : m.lines()[0].arcLength) x.emplace_back(0.0, 0.0, -100.0 + s);
  return x;
}

TEST(Contents, EachSectionWeighsAndMovesWithItsOwnContents) {
  const Model m(verticalPipe(850.0, 0.0, 0.0, std::nan("")));
  const double ai = kPi / 4.0 * kBore * kBore;
  const auto& elements = m.elements();
  // Lower section: the line's oil; upper section: empty (its own density 0), the input's line type itself.
  EXPECT_DOUBLE_EQ(elements[0].type->totalMassPerLength(), 100.0 + 850.0 * ai);
  EXPECT_DOUBLE_EQ(elements[15].type->totalMassPerLength(), 100.0);
  EXPECT_EQ(elements[15].type, &m.spec().lineTypes.at("pipe"));
  EXPECT_DOUBLE_EQ(elements[0].type->massPerLength, 100.0);  // the structure's own mass is unchanged
  // Node masses: 5 m elements, half of each on either node; node 10 sits between the two sections.
  EXPECT_NEAR(m.nodeMass()[1], 5.0 * (100.0 + 850.0 * ai), 1e-9);
  EXPECT_NEAR(m.nodeMass()[10], 2.5 * (100.0 + 850.0 * ai) + 2.5 * 100.0, 1e-9);
  EXPECT_NEAR(m.nodeMass()[15], 5.0 * 100.0, 1e-9);
  EXPECT_NEAR(m.lineMass(0), 100.0 * 100.0 + 50.0 * 850.0 * ai, 1e-6);
  // Submerged weight with contents: (m_s + rho_c A_i - rho A_e) g.
  const double water = m.environment().waterDensity;
  EXPECT_NEAR(elements[0].type->submergedWeight(water, kG),
              (100.0 + 850.0 * ai - water * kPi / 4.0 * 0.09) * kG, 1e-9);
  // No reference level given: the higher end, z = 0.
  EXPECT_DOUBLE_EQ(m.lines()[0].contentsReferenceZ, 0.0);
  EXPECT_TRUE(m.lines()[0].pipe);
}

TEST(Contents, PressureOfOneContentsColumnIsItsHeadBelowTheReference) {
  // One density: p = p_ref + rho_c g (z_ref - z) whatever the reference level, on the line (z_ref = -30)
  // or off it (z_ref = 20, above the top: the head is extended from the nearer end).
  for (const double zRef : {-30.0, 20.0, -150.0}) {
    const Model m(verticalPipe(850.0, std::nan(""), 1.0e7, zRef));
    const std::vector<Vec3> x = straightUp(m);
    std::vector<double> p;
    m.internalPressure(0, x, p);
    ASSERT_EQ(p.size(), x.size());
    for (std::size_t k = 0; k < x.size(); ++k)
      EXPECT_NEAR(p[k], 1.0e7 + 850.0 * kG * (zRef - x[k].z()), 1e-6) << "z_ref " << zRef << " node " << k;
  }
}

TEST(Contents, PressureUnderAGasCapSumsTheHeadAlongTheLine) {
  // Water (1000 kg/m^3) in the lower 50 m, gas (0) in the upper 50 m, 5 MPa at the top (z_ref = 0): the gas
  // column carries the pressure down unchanged to z = -50, the water adds its head below.
  const Model m(verticalPipe(1000.0, 0.0, 5.0e6, 0.0));
  const std::vector<Vec3> x = straightUp(m);
  std::vector<double> p;
  m.internalPressure(0, x, p);
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double z = x[k].z();
    const double expected = 5.0e6 + (z < -50.0 ? 1000.0 * kG * (-50.0 - z) : 0.0);
    EXPECT_NEAR(p[k], expected, 1e-6) << "node " << k << " at z = " << z;
  }
}

TEST(Contents, LineWithoutABoreHasNoPressure) {
  ModelSpec spec = verticalPipe(0.0, std::nan(""), 0.0, std::nan(""));
  spec.lineTypes["pipe"].internalDiameter = 0.0;
  const Model m(std::move(spec));
  EXPECT_FALSE(m.lines()[0].pipe);
  std::vector<double> p{1.0};
  m.internalPressure(0, straightUp(m), p);
  for (const double value : p) EXPECT_EQ(value, 0.0);
}

}  // namespace
}  // namespace tangle::model
