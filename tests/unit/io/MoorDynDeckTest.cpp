/// @file MoorDynDeckTest.cpp
/// Tests of io::MoorDynDeck (reading a MoorDyn v2 input file) and io::MoorDynConversion (the tangle model it
/// becomes): every supported kind of entry read and converted value by value, lines joined at free points,
/// and one test per refused entry checking the file, the 1-based line and the entry's name.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "TestPaths.hpp"
#include "tangle/core/Error.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/hydro/AiryWave.hpp"
#include "tangle/hydro/CurrentGrid.hpp"
#include "tangle/hydro/HydroLoads.hpp"
#include "tangle/io/ModelReader.hpp"
#include "tangle/io/MoorDynConversion.hpp"
#include "tangle/io/MoorDynDeck.hpp"

namespace tangle::io {
namespace {

/// A deck with every supported kind of point; `points` and `lines` replace the tables, `options` the options.
std::string deck(const std::string& points, const std::string& lines, const std::string& options = "",
                 const std::string& types = "", const std::string& sections = "") {
  return "--------------------- MoorDyn Input File ------------------------------------\n"       // 1
         "Test deck\n"                                                                           // 2
         "----------------------- LINE TYPES ------------------------------------------\n"       // 3
         "TypeName   Diam    Mass/m     EA         BA/-zeta    EI   Cd    Ca    CdAx   CaAx\n"   // 4
         "(name)     (m)     (kg/m)     (N)        (N-s/-)     (-)  (-)   (-)   (-)    (-)\n"    // 5
         "chain      0.2     200        1.0e9      -0.5        0    1.2   1.0   0.4    0.5\n"    // 6
         "rope       0.15    20         2.0e8      1.0e5       10   1.4   0.9   0.1    0.0\n" +  // 7
         types +
         "---------------------- POINTS --------------------------------\n"
         "ID    Attachment  X       Y     Z      Mass   Volume  CdA    Ca\n"
         "(#)   (-)         (m)     (m)   (m)    (kg)   (mˆ3)   (m^2)  (-)\n" +
         points +
         "---------------------- LINES ----------------------------------------\n"
         "ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs\n"
         "(#)  (name)     (#)      (#)      (m)       (-)      (-)\n" +
         lines + sections +
         "---------------------- OPTIONS -----------------------------------------\n"
         "0.001         dtM           time step (s)\n"
         "100           WtrDpth       water depth (m)\n" +
         options +
         "---------------------- OUTPUTS -----------------------------------------\n"
         "FairTen1\nAnchTen1\nEND\n"
         "------------------------- need this line --------------------------------------\n";
}

const std::string kTwoPoints =
    "1     Fixed     -300   0     -100   0      0       0      0\n"
    "2     Vessel    0      0     -10    0      0       0      0\n";

/// Expects an InputError from parsing and converting `text` at deck line `line` whose message holds `words`.
std::string bodies(const std::string& rows);

void expectRefused(const std::string& text, int line, const std::string& words) {
  try {
    const MoorDynDeck d = parseMoorDynDeck(text, "deck.txt");
    convertMoorDynDeck(d);
    FAIL() << "expected an InputError mentioning '" << words << "'";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "deck.txt");
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(MoorDynDeck, ReadsEveryTableValueByValue) {
  const MoorDynDeck d = parseMoorDynDeck(deck(kTwoPoints, "1 chain 1 2 320 40 pt\n"), "deck.txt");
  EXPECT_EQ(d.title, "Test deck");
  ASSERT_EQ(d.lineTypes.size(), 2u);
  const MoorDynLineType& rope = d.lineTypes[1];
  EXPECT_EQ(rope.name, "rope");
  EXPECT_DOUBLE_EQ(rope.diameter, 0.15);
  EXPECT_DOUBLE_EQ(rope.massPerLength, 20.0);
  EXPECT_DOUBLE_EQ(rope.axialStiffness, 2.0e8);
  EXPECT_DOUBLE_EQ(rope.axialDamping, 1.0e5);
  EXPECT_DOUBLE_EQ(rope.bendingStiffness, 10.0);
  EXPECT_DOUBLE_EQ(rope.dragNormal, 1.4);
  EXPECT_DOUBLE_EQ(rope.addedMassNormal, 0.9);
  EXPECT_DOUBLE_EQ(rope.dragAxial, 0.1);
  EXPECT_DOUBLE_EQ(rope.addedMassAxial, 0.0);
  EXPECT_EQ(rope.sourceLine, 7);
  ASSERT_EQ(d.points.size(), 2u);
  EXPECT_EQ(d.points[0].kind, MoorDynPointKind::Fixed);
  EXPECT_EQ(d.points[1].kind, MoorDynPointKind::Coupled);
  EXPECT_DOUBLE_EQ(d.points[0].position.x(), -300.0);
  ASSERT_EQ(d.lines.size(), 1u);
  EXPECT_EQ(d.lines[0].pointA, 1);
  EXPECT_EQ(d.lines[0].pointB, 2);
  EXPECT_DOUBLE_EQ(d.lines[0].length, 320.0);
  EXPECT_EQ(d.lines[0].segments, 40);
  ASSERT_EQ(d.options.size(), 2u);
  EXPECT_EQ(d.options[1].name, "WtrDpth");
  ASSERT_EQ(d.outputs.size(), 2u);
  EXPECT_EQ(d.outputs[0], "FairTen1");
}

TEST(MoorDynDeck, ConvertsIntoTheModelMoorDynDescribes) {
  const MoorDynDeck d = parseMoorDynDeck(
      deck(kTwoPoints, "1 chain 1 2 320 40 -\n", "3.0e6 kBot\n2.0e5 cBot\n1000 WtrDnsty\n9.81 g\n"),
      "deck.txt");
  const MoorDynConversion c = convertMoorDynDeck(d);
  const model::ModelSpec spec = readModelString(c.yaml, "converted.yaml");
  EXPECT_DOUBLE_EQ(spec.environment.waterDepth, 100.0);
  EXPECT_DOUBLE_EQ(spec.environment.waterDensity, 1000.0);
  EXPECT_DOUBLE_EQ(spec.environment.gravity, 9.81);
  // kBot [Pa/m] and cBot [Pa s/m] over the diameter: per metre of line.
  EXPECT_DOUBLE_EQ(spec.environment.seabed.normalStiffness, 3.0e6 * 0.2);
  EXPECT_DOUBLE_EQ(spec.environment.seabed.damping, 2.0e5 * 0.2);
  ASSERT_EQ(spec.lines.size(), 1u);
  const model::LineSpec& line = spec.lines[0];
  EXPECT_EQ(line.name, "line1");
  EXPECT_EQ(line.endA.kind, model::EndKind::Anchored);  // a fixed point on the seabed
  EXPECT_EQ(line.endB.kind, model::EndKind::Pinned);    // the coupled point, held in a standalone run
  EXPECT_DOUBLE_EQ(line.endB.position.z(), -10.0);
  ASSERT_EQ(line.sections.size(), 1u);
  EXPECT_EQ(line.sections[0].elements, 40);
  EXPECT_DOUBLE_EQ(line.sections[0].length, 320.0);
  // BA = -0.5: MoorDyn's damping ratio, zeta (L/N) sqrt(EA m) N s (Line.cpp, setup).
  const section::LineType& type = spec.lineTypes.at("chain");
  EXPECT_NEAR(type.axialDamping, 0.5 * (320.0 / 40.0) * std::sqrt(1.0e9 * 200.0), 1e-6);
  EXPECT_DOUBLE_EQ(type.dragAxial, 0.4);
  EXPECT_DOUBLE_EQ(type.addedMassAxial, 0.5);
  EXPECT_DOUBLE_EQ(spec.dynamics.rampTime, 0.0);
  // The map a coupling host uses.
  ASSERT_EQ(c.points.size(), 2u);
  ASSERT_EQ(c.points[1].ends.size(), 1u);
  EXPECT_EQ(c.points[1].ends[0], (std::pair<std::string, int>{"line1", 1}));
  EXPECT_EQ(c.lines[0].tangleLine, "line1");
  EXPECT_EQ(c.lines[0].firstNode, 0);
  EXPECT_FALSE(c.lines[0].reversed);
}

/// The dynamics settings of deck `text` converted.
model::DynamicSpec convertedDynamics(const std::string& text) {
  const MoorDynConversion c = convertMoorDynDeck(parseMoorDynDeck(text, "deck.txt"));
  return readModelString(c.yaml, "converted.yaml").dynamics;
}
/// The dynamics' Newton tolerance of deck `text` converted [-].
double convertedTolerance(const std::string& text) { return convertedDynamics(text).tolerance; }

// The dynamics' Newton tolerance: 1e-5 of the lines' weight for a model of cables only (the deck's lines
// without bending; docs/moordyn.md, OPTIONS), tangle's default 1e-6 with a beam line (EI that bends over
// its segments) or a free body (a vessel).
// The converted file's comments give the deck line of an option under any of the names MoorDyn takes:
// `1000 rho` is WtrDnsty's (deck line 35), not MoorDyn's default. (Until 2026-12-06 only one name of each was
// looked up, and the comment called the deck's value the default.)
TEST(MoorDynDeck, OptionCommentsFindTheDeckLineUnderEitherName) {
  const MoorDynConversion c = convertMoorDynDeck(parseMoorDynDeck(
      deck(kTwoPoints, "1 chain 1 2 320 40 -\n", "1000 rho\n9.81 gravity\n3e6 kb\n2e5 cb\n"), "deck.txt"));
  for (const char* option : {"WtrDnsty", "g", "kBot", "cBot"}) {
    const std::size_t at = c.yaml.find(std::string("# ") + option + " ");
    ASSERT_NE(at, std::string::npos) << option << "\n" << c.yaml;
    const std::string comment = c.yaml.substr(at, c.yaml.find('\n', at) - at);
    EXPECT_NE(comment.find("deck line"), std::string::npos) << comment;
    EXPECT_EQ(comment.find("MoorDyn default"), std::string::npos) << comment;
  }
}

TEST(MoorDynDeck, CablesOnlyTakeTheCableNewtonTolerance) {
  const double defaultTolerance = model::DynamicSpec{}.tolerance;
  ASSERT_DOUBLE_EQ(defaultTolerance, 1e-6);
  // A chain, and a rope whose EI (10 N m^2) bends over 0.8 m against its 32 m segments: cables.
  EXPECT_DOUBLE_EQ(convertedTolerance(deck(kTwoPoints, "1 chain 1 2 320 40 -\n")), 1e-5);
  EXPECT_DOUBLE_EQ(convertedTolerance(deck(kTwoPoints, "1 rope 1 2 320 10 -\n")), 1e-5);
  // The same rope on 8 m segments: bending over a tenth of them, a beam line.
  EXPECT_DOUBLE_EQ(convertedTolerance(deck(kTwoPoints, "1 rope 1 2 320 40 -\n")), defaultTolerance);
  // A hose that bends over (EI / w)^(1/3) = 12 m against its 8 m segments: a beam line.
  const std::string hose =
      "hose       0.3     100        1.0e9      -1.0        5e5  1.2   1.0   0.4    0.5\n";
  EXPECT_DOUBLE_EQ(convertedTolerance(deck(kTwoPoints, "1 hose 1 2 320 40 -\n", "", hose)), defaultTolerance);
  // A free body: a vessel.
  const std::string points = kTwoPoints + "3 Body1 0 3 0 0 0 0 0\n";
  EXPECT_DOUBLE_EQ(convertedTolerance(deck(points, "1 chain 1 3 300 30 -\n2 chain 3 2 60 6 -\n", "",
                                           bodies("1 Free 0 0 -50 0 0 0 2000 0 500 3 0.4 0.5\n"))),
                   defaultTolerance);
}

// tangle's own OPTIONS entry tangleTolerance (MoorDyn warns of an unknown option and goes on) sets the
// tolerance for any deck; out of (0, 0.1] it is refused, naming the line.
TEST(MoorDynDeck, TangleToleranceOptionSetsTheNewtonTolerance) {
  EXPECT_DOUBLE_EQ(convertedTolerance(deck(kTwoPoints, "1 chain 1 2 320 40 -\n", "1e-6 tangleTolerance\n")),
                   1e-6);
  EXPECT_DOUBLE_EQ(convertedTolerance(deck(kTwoPoints, "1 rope 1 2 320 40 -\n", "3e-5 tangleTolerance\n")),
                   3e-5);
  // deck() with two points and one line: dtM on line 18, WtrDpth on 19, then this option.
  expectRefused(deck(kTwoPoints, "1 chain 1 2 320 40 -\n", "0 tangleTolerance\n"), 20,
                "tangle's Newton tolerance");
  expectRefused(deck(kTwoPoints, "1 chain 1 2 320 40 -\n", "0.5 tangleTolerance\n"), 20, "(0, 0.1]");
}

// The dynamics' implicit step: max(dtM, 0.01 s) (docs/moordyn.md, OPTIONS: dtM is an explicit scheme's
// stability limit), or the deck's own tangleTimeStep (a host coupled at 0.025 s then takes one step per call,
// not three of 0.0083 s).
TEST(MoorDynDeck, TangleTimeStepOptionSetsTheImplicitStep) {
  const auto convertedStep = [](const std::string& text) { return convertedDynamics(text).timeStep; };
  const std::string line = "1 chain 1 2 320 40 -\n";
  EXPECT_DOUBLE_EQ(convertedStep(deck(kTwoPoints, line)), 0.01);  // dtM 0.001 s
  EXPECT_DOUBLE_EQ(convertedStep(deck(kTwoPoints, line, "0.025 tangleTimeStep\n")), 0.025);
  EXPECT_DOUBLE_EQ(convertedStep(deck(kTwoPoints, line, "0.004 tangleTimeStep\n")), 0.004);
  // deck() with two points and one line: dtM on line 18, WtrDpth on 19, then this option.
  expectRefused(deck(kTwoPoints, line, "0 tangleTimeStep\n"), 20, "tangle's implicit time step");
  expectRefused(deck(kTwoPoints, line, "2 tangleTimeStep\n"), 20, "(0, 1] s");
}

TEST(MoorDynDeck, JoinsLinesInSeriesAtFreePointsWhateverTheirDirection) {
  // Anchor 1 - line 1 - buoy 3 - line 2 (drawn from the vessel to the buoy) - vessel 2.
  const std::string points = kTwoPoints + "3     Free      -150   0     -60    100    2.0     1.5    0.8\n";
  const MoorDynDeck d =
      parseMoorDynDeck(deck(points, "1 chain 1 3 200 20 -\n2 rope 2 3 160 16 -\n"), "deck.txt");
  const MoorDynConversion c = convertMoorDynDeck(d);
  const model::ModelSpec spec = readModelString(c.yaml, "converted.yaml");
  ASSERT_EQ(spec.lines.size(), 1u);
  const model::LineSpec& line = spec.lines[0];
  EXPECT_EQ(line.name, "line1-line2");
  ASSERT_EQ(line.sections.size(), 2u);
  EXPECT_DOUBLE_EQ(line.sections[0].length, 200.0);
  EXPECT_DOUBLE_EQ(line.sections[1].length, 160.0);
  EXPECT_EQ(line.endA.kind, model::EndKind::Anchored);
  EXPECT_EQ(line.endB.kind, model::EndKind::Pinned);
  ASSERT_EQ(line.attachments.size(), 1u);
  EXPECT_DOUBLE_EQ(line.attachments[0].arcLength, 200.0);
  EXPECT_DOUBLE_EQ(line.attachments[0].mass, 100.0);
  EXPECT_DOUBLE_EQ(line.attachments[0].volume, 2.0);
  EXPECT_DOUBLE_EQ(line.attachments[0].dragArea, 1.5);
  EXPECT_DOUBLE_EQ(line.attachments[0].addedMass, 0.8 * 1025.0 * 2.0);  // Ca rho V
  ASSERT_EQ(line.startShape.size(), 1u);  // the buoy's deck position starts the static solve
  EXPECT_DOUBLE_EQ(line.startShape[0].position.z(), -60.0);
  EXPECT_DOUBLE_EQ(line.startShape[0].arcLength, 200.0);
  // Deck line 2 runs from the vessel (end B of the tangle line, node 36) to the buoy (node 20).
  EXPECT_EQ(c.lines[1].firstNode, 36);
  EXPECT_TRUE(c.lines[1].reversed);
  EXPECT_EQ(c.points[2].junctionLine, "line1-line2");
  EXPECT_EQ(c.points[2].junctionNode, 20);
}

TEST(MoorDynDeck, TypeNamesYamlWouldMisreadAreQuoted) {
  // MoorDyn takes any word without a '#' (its comment mark) as a type name: "&1" would be a YAML anchor,
  // "a:b" a map, "*p" an alias.
  const std::string types =
      "&1 0.2 200 1e9 -1 0 1 1 0 0\na:b 0.2 200 1e9 -1 0 1 1 0 0\n*p\"q 0.2 200 1e9 -1 0 1 1 0 0\n";
  const std::string points = kTwoPoints + "3 Fixed 300 0 -100 0 0 0 0\n4 Fixed 0 300 -100 0 0 0 0\n";
  const MoorDynConversion c = convertMoorDynDeck(parseMoorDynDeck(
      deck(points, "1 &1 1 2 320 40 -\n2 a:b 3 2 320 40 -\n3 *p\"q 4 2 320 40 -\n", "", types), "deck.txt"));
  const model::ModelSpec spec = readModelString(c.yaml, "converted.yaml");
  EXPECT_EQ(spec.lines[0].sections[0].lineType, "&1");
  EXPECT_EQ(spec.lines[1].sections[0].lineType, "a:b");
  EXPECT_EQ(spec.lines[2].sections[0].lineType, "*p\"q");
  EXPECT_EQ(spec.lineTypes.count("*p\"q"), 1u);
}

TEST(MoorDynDeck, FreeEndPointBecomesAFreeEndWithItsMass) {
  const std::string points =
      "1     Fixed     0   0     -100   0      0       0      0\n"
      "2     Free      0   0     -40    0      3.0     0.5    1.0\n";
  const MoorDynConversion c =
      convertMoorDynDeck(parseMoorDynDeck(deck(points, "1 rope 1 2 70 10 -\n"), "deck.txt"));
  const model::ModelSpec spec = readModelString(c.yaml, "converted.yaml");
  EXPECT_EQ(spec.lines[0].endB.kind, model::EndKind::Free);
  ASSERT_EQ(spec.lines[0].attachments.size(), 1u);
  EXPECT_DOUBLE_EQ(spec.lines[0].attachments[0].arcLength, 70.0);
  EXPECT_DOUBLE_EQ(spec.lines[0].attachments[0].volume, 3.0);
  EXPECT_EQ(spec.lines[0].endA.kind, model::EndKind::Anchored);
}

TEST(MoorDynDeck, PublishedDecksConvertAndRead) {
  for (const char* name : {"lines.txt", "WD0050_Chain.txt", "lowe_langley_jumper.txt"}) {
    const std::string path = std::string(test::kTestDataDir) + "/moordyn/" + name;
    EXPECT_TRUE(isMoorDynDeck(path)) << path;
    const model::ModelSpec spec = readModelFile(path);  // the reader converts a deck itself
    EXPECT_FALSE(spec.lines.empty()) << path;
  }
  EXPECT_FALSE(isMoorDynDeck(std::string(test::kExamplesDir) + "/mooring-dynamics/model.yaml"));
}

TEST(MoorDynDeck, ASeafloorFileBecomesTheBathymetry) {
  // MoorDyn v2.7.1 tests/Mooring/seafloor.txt (its pendulum test, tests/seafloor.cpp) names
  // "Mooring/3D_seafloor/seafloor_profile_3d.txt" (relative to MoorDyn's tests folder, where its tests run):
  // found here under the deck's folder. The file's seabed is z = -30 + 0.2 x; the deck's free point (a 10 kg
  // mass at the end of a 32 m line from (0, -1, 0)) starts on it at (10, -1, -28).
  const std::string path = std::string(test::kTestDataDir) + "/moordyn/seafloor.txt";
  const model::ModelSpec spec = readModelFile(path);
  ASSERT_TRUE(spec.environment.seabedSurface);
  EXPECT_EQ(spec.environment.seabedSurface->kind(), seabed::SeabedSurface::Kind::Grid);
  EXPECT_NEAR(spec.environment.seabedSurface->height(10.0, -1.0), -28.0, 1e-9);
  EXPECT_NEAR(spec.environment.seabedSurface->height(-33.3, 0.4), -30.0 - 6.66, 1e-9);
  // Bilinear between the nodes, as MoorDyn (tangle's own grids are bicubic by default).
  EXPECT_EQ(spec.environment.seabedSurface->interpolation(), seabed::SeabedSurface::Interpolation::Bilinear);
  EXPECT_DOUBLE_EQ(spec.environment.waterDepth, 500.0);  // WtrDpth: the waves' depth
}

/// ROD TYPES and RODS sections (after the line types) with these rods.
std::string rods(const std::string& rows) {
  return "---------------------- ROD TYPES ------------------------------------\n"
         "TypeName  Diam  Mass/m  Cd   Ca   CdEnd  CaEnd\n"
         "(name)    (m)   (kg/m)  (-)  (-)  (-)    (-)\n"
         "pipe      0.25  80      1.6  1.0  1.2    0.8\n"
         "---------------------- RODS ----------------------------------------\n"
         "ID  RodType  Attachment  Xa  Ya  Za  Xb  Yb  Zb  NumSegs  RodOutputs\n"
         "(#) (name)   (#/key)     (m) (m) (m) (m) (m) (m) (-)      (-)\n" +
         rows;
}

TEST(MoorDynDeck, ReadsRodTypesAndRods) {
  const MoorDynDeck d = parseMoorDynDeck(
      deck(kTwoPoints, "1 chain 1 R1A 300 30 -\n2 rope R1B 2 100 10 -\n", "",
           rods("1 pipe Free -10 0 -80 10 0 -80 4 p\n2 pipe Pinned 0 0 -50 0 0 -40 2 -\n"
                "3 pipe Fixed 5 5 -90 5 5 -80 1 -\n4 pipe Vessel 0 0 -5 0 0 -15 2 -\n"
                "5 pipe CoupledPinned 0 0 -5 0 0 -15 2 -\n6 pipe Free 3 0 -60 3 0 -60 0 -\n")),
      "deck.txt");
  ASSERT_EQ(d.rodTypes.size(), 1u);
  const MoorDynRodType& t = d.rodTypes[0];
  EXPECT_EQ(t.name, "pipe");
  EXPECT_DOUBLE_EQ(t.diameter, 0.25);
  EXPECT_DOUBLE_EQ(t.massPerLength, 80.0);
  EXPECT_DOUBLE_EQ(t.drag, 1.6);
  EXPECT_DOUBLE_EQ(t.addedMass, 1.0);
  EXPECT_DOUBLE_EQ(t.dragEnd, 1.2);
  EXPECT_DOUBLE_EQ(t.addedMassEnd, 0.8);
  ASSERT_EQ(d.rods.size(), 6u);
  EXPECT_EQ(d.rods[0].kind, MoorDynRodKind::Free);
  EXPECT_EQ(d.rods[0].endA, Vec3(-10.0, 0.0, -80.0));
  EXPECT_EQ(d.rods[0].endB, Vec3(10.0, 0.0, -80.0));
  EXPECT_EQ(d.rods[0].segments, 4);
  EXPECT_EQ(d.rods[0].outputs, "p");
  EXPECT_EQ(d.rods[1].kind, MoorDynRodKind::Pinned);
  EXPECT_EQ(d.rods[2].kind, MoorDynRodKind::Fixed);
  EXPECT_EQ(d.rods[3].kind, MoorDynRodKind::Coupled);
  EXPECT_EQ(d.rods[4].kind, MoorDynRodKind::CoupledPinned);
  EXPECT_DOUBLE_EQ(d.rods[5].length(), 0.0);
  EXPECT_EQ(d.lines[0].rodB, 1);
  EXPECT_EQ(d.lines[0].rodEndB, 0);
  EXPECT_EQ(d.lines[1].rodA, 1);
  EXPECT_EQ(d.lines[1].rodEndA, 1);
}

TEST(MoorDynDeck, AFreeRodIsAStiffBeamWhoseEndsArePoints) {
  // A 20 m free rod hung from two lines at its ends (MoorDyn's RodHanging.txt, smaller).
  const MoorDynConversion c =
      convertMoorDynDeck(parseMoorDynDeck(deck(kTwoPoints, "1 chain 1 R1A 300 30 -\n2 rope R1B 2 100 10 -\n",
                                               "", rods("1 pipe Free -10 0 -80 10 0 -80 4 -\n")),
                                          "deck.txt"));
  const model::ModelSpec spec = readModelString(c.yaml, "converted.yaml");
  ASSERT_EQ(spec.lines.size(), 3u);
  const model::LineSpec& rod = spec.lines[0];  // first: its end nodes carry the points
  EXPECT_EQ(rod.name, "rod1");
  EXPECT_EQ(rod.endA.kind, model::EndKind::Point);
  EXPECT_EQ(rod.endA.point, "rod1a");
  EXPECT_EQ(rod.endB.point, "rod1b");
  ASSERT_EQ(rod.sections.size(), 1u);
  EXPECT_DOUBLE_EQ(rod.sections[0].length, 20.0);
  EXPECT_EQ(rod.sections[0].elements, 4);
  // End effects at each end: CdEnd pi/4 d^2 and CaEnd rho 2/3 pi (d/2)^3 (MoorDyn's Rod.cpp).
  ASSERT_EQ(rod.attachments.size(), 2u);
  EXPECT_DOUBLE_EQ(rod.attachments[1].arcLength, 20.0);
  EXPECT_NEAR(rod.attachments[0].dragArea, 1.2 * std::numbers::pi / 4.0 * 0.0625, 1e-12);
  EXPECT_NEAR(rod.attachments[0].addedMass,
              0.8 * 1025.0 * 2.0 / 3.0 * std::numbers::pi * 0.125 * 0.125 * 0.125, 1e-9);
  ASSERT_EQ(spec.points.size(), 2u);
  EXPECT_EQ(spec.points[0].position, Vec3(-10.0, 0.0, -80.0));
  EXPECT_EQ(spec.lines[1].endB.point, "rod1a");
  EXPECT_EQ(spec.lines[2].endA.point, "rod1b");
  // The rod's line type: its own diameter, mass and coefficients, no axial drag; stiff.
  const auto type = spec.lineTypes.find("rod-pipe");
  ASSERT_NE(type, spec.lineTypes.end());
  EXPECT_DOUBLE_EQ(type->second.outerDiameter, 0.25);
  EXPECT_DOUBLE_EQ(type->second.massPerLength, 80.0);
  EXPECT_DOUBLE_EQ(type->second.dragNormal, 1.6);
  EXPECT_DOUBLE_EQ(type->second.dragAxial, 0.0);
  EXPECT_GE(type->second.axialStiffness,
            1e2 * 1.0e9 / 10.0 * 5.0);  // 100 x the stiffest segment (chain, 10 m) over its 5 m elements
  EXPECT_GT(type->second.bendingStiffness, 0.0);
  // The maps: the deck's two points only; the rod is line rod1.
  EXPECT_EQ(c.points.size(), 2u);
  ASSERT_EQ(c.rods.size(), 1u);
  EXPECT_EQ(c.rods[0].tangleLine, "rod1");
}

TEST(MoorDynDeck, FixedPinnedAndZeroLengthRodsHoldTheirLines) {
  // Rod 1 fixed: the rope (EI 10) clamps to its axis at end B, the chain (EI 0) pins at end A. Rod 2 pinned:
  // a line at end A is pinned there, the rod is a beam from a pinned end. Rod 3 zero-length and free, joining
  // two lines: one tangle line through it, with both ends' drag.
  const MoorDynConversion c = convertMoorDynDeck(parseMoorDynDeck(
      deck(kTwoPoints + "3 Free -50 0 -70 0 0 0 0\n",
           "1 chain 1 R1A 200 20 -\n2 rope R1B 3 50 10 -\n3 chain R2A 2 80 8 -\n4 chain R3A 2 70 7 -\n"
           "5 chain R3B 1 330 33 -\n",
           "",
           rods("1 pipe Fixed -100 0 -90 -90 0 -90 1 -\n2 pipe Pinned 20 0 -80 20 0 -70 2 -\n"
                "3 pipe Free 0 -30 -60 0 -30 -60 0 -\n")),
      "deck.txt"));
  const model::ModelSpec spec = readModelString(c.yaml, "converted.yaml");
  const auto named = [&](const std::string& name) {
    const auto it =
        std::find_if(spec.lines.begin(), spec.lines.end(), [&](const auto& l) { return l.name == name; });
    EXPECT_NE(it, spec.lines.end()) << name;
    return *it;
  };
  EXPECT_EQ(spec.lines[0].name, "rod2");
  EXPECT_EQ(spec.lines[0].endA.kind, model::EndKind::Pinned);
  EXPECT_EQ(spec.lines[0].endB.kind, model::EndKind::Free);
  const model::LineSpec line1 = named("line1");
  EXPECT_EQ(line1.endB.kind, model::EndKind::Pinned);
  EXPECT_EQ(line1.endB.position, Vec3(-100.0, 0.0, -90.0));
  const model::LineSpec line2 = named("line2");
  EXPECT_EQ(line2.endA.kind, model::EndKind::Fixed);
  EXPECT_EQ(line2.endA.position, Vec3(-90.0, 0.0, -90.0));
  ASSERT_EQ(line2.startShape.size(), 1u);  // one element (5 m) along the rod's axis, +x
  EXPECT_EQ(line2.startShape[0].position, Vec3(-85.0, 0.0, -90.0));
  EXPECT_DOUBLE_EQ(line2.startShape[0].arcLength, 5.0);
  EXPECT_EQ(named("line3").endA.kind, model::EndKind::Pinned);
  EXPECT_EQ(named("line3").endA.position, Vec3(20.0, 0.0, -80.0));
  // Lines 4 and 5 meet at the zero-length rod: one tangle line, the rod a drag attachment inside it.
  const model::LineSpec joined = named("line5-line4");  // from point 1 along line 5, then line 4
  ASSERT_EQ(joined.attachments.size(), 1u);
  EXPECT_DOUBLE_EQ(joined.attachments[0].arcLength, 330.0);
  EXPECT_NEAR(joined.attachments[0].dragArea, 2.0 * 1.2 * std::numbers::pi / 4.0 * 0.0625, 1e-12);
}

TEST(MoorDynDeck, ADeckOfRodsOnlyIsADeck) {
  // MoorDyn's tests/Mooring/RodPinnedFloating.txt has rod types and rods and no line types: it used to be
  // read as YAML ("invalid YAML"). A YAML comment with dashes is not a deck. A free rod that no line holds
  // has no static equilibrium: the run starts from the deck's positions (statics.method: none).
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "tangle-moordyn-rods-only";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "rods.txt")
      << "--------------------- MoorDyn Input File ---------------------\nRods only\n"
         "---------------------- ROD TYPES -----------------------------\n"
         "TypeName Diam Mass/m Cd Ca CdEnd CaEnd\n(name) (m) (kg/m) (-) (-) (-) (-)\n"
         "Can 10 1000 0.6 1.0 0.6 1.0\n"
         "---------------------- RODS ----------------------------------\n"
         "ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs\n(#) (name) (#/key) (m) (m) (m) (m) (m) "
         "(m) (-) (-)\n"
         "1 Can Free 0 0 -20 0 0 -10 3 -\n"
         "---------------------- OPTIONS -------------------------------\n50 WtrDpth -\n";
  std::ofstream(dir / "model.yaml") << "# ---------------------- RODS and LINE TYPES ----------\ntitle: x\n";
  EXPECT_TRUE(isMoorDynDeck((dir / "rods.txt").string()));
  EXPECT_FALSE(isMoorDynDeck((dir / "model.yaml").string()));
  const model::ModelSpec spec = readModelFile((dir / "rods.txt").string());
  ASSERT_EQ(spec.lines.size(), 1u);
  EXPECT_EQ(spec.lines[0].endA.kind, model::EndKind::Free);
  EXPECT_EQ(spec.lines[0].endB.kind, model::EndKind::Free);
  EXPECT_TRUE(spec.statics.skip);
  std::filesystem::remove_all(dir);
}

TEST(MoorDynDeck, RefusesRodsItCannotRepresentNamingTheEntry) {
  const std::string types = rods("1 pipe Free -10 0 -80 10 0 -80 4 -\n");
  expectRefused(deck(kTwoPoints, "1 chain 1 R2A 300 30 -\n", "", types), 24, "rod 2 does not exist");
  expectRefused(deck(kTwoPoints, "1 chain 1 R1 300 30 -\n", "", types), 24, "R<number>A");
  expectRefused(deck(kTwoPoints, "1 chain 1 R1C 300 30 -\n", "", types), 24, "R<number>A");
  expectRefused(deck(kTwoPoints, "1 chain 1 2 300 30 -\n", "", rods("1 pipe Body1 0 0 0 0 0 -5 2 -\n")), 15,
                "bodies");
  expectRefused(deck(kTwoPoints, "1 chain 1 2 300 30 -\n", "", rods("1 tube Free 0 0 0 0 0 -5 2 -\n")), 15,
                "no rod type named 'tube'");
  expectRefused(deck(kTwoPoints, "1 chain 1 2 300 30 -\n", "", rods("1 pipe Free 0 0 -5 0 0 -15 0 -\n")), 15,
                "NumSegs");
  expectRefused(deck(kTwoPoints, "1 chain 1 2 300 30 -\n", "", rods("1 pipe Glued 0 0 -5 0 0 -15 2 -\n")), 15,
                "unknown rod type 'Glued'");
  expectRefused(deck(kTwoPoints, "1 chain R1A R1B 300 30 -\n", "", rods("1 pipe Free 0 0 -5 0 0 -5 0 -\n")),
                24, "same rod end");
}

/// A BODIES section (after the line types) with these rows.
std::string bodies(const std::string& rows) {
  return "---------------------------- BODIES -----------------------------------------------------\n"
         "ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca*\n"
         "(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)\n" +
         rows;
}

TEST(MoorDynDeck, AFreeBodyIsASubmergedFreeVessel) {
  // Body 1: 2 t, its CG 1 m below its reference point, I 500|600|700, 3 m^3, CdA 0.4|0.2, Ca 0.5; a 1 t point
  // on it 2 m along x (no line), a line to its point 3 m along y. Body 2 fixed at (10, 0, -40), turned 90 deg
  // in yaw: its point at x = 1 is at (10, 1, -40), a pinned end.
  const std::string points = kTwoPoints +
                             "3 Body1 2 0 0 1000 0.5 0 0\n"
                             "4 Body1 0 3 0 0 0 0 0\n"
                             "5 Body2 1 0 0 0 0 0 0\n";
  const MoorDynConversion c = convertMoorDynDeck(
      parseMoorDynDeck(deck(points, "1 chain 1 4 300 30 -\n2 rope 2 5 50 5 -\n", "",
                            bodies("1 Free 0 0 -50 0 0 0 2000 -1 500|600|700 3 0.4|0.2 0.5\n"
                                   "2 Fixed 10 0 -40 0 0 90 0 0 0 0 0 0\n")),
                       "deck.txt"));
  const model::ModelSpec spec = readModelString(c.yaml, "converted.yaml");
  ASSERT_EQ(spec.vessels.size(), 1u);
  const model::VesselSpec& v = spec.vessels[0];
  EXPECT_EQ(v.name, "body1");
  EXPECT_EQ(v.mode, model::VesselMode::Free);
  // Reference point: the centre of gravity of the body (at z -1) and the point mass (at x 2).
  const Vec3 cg = (2000.0 * Vec3(0.0, 0.0, -51.0) + 1000.0 * Vec3(2.0, 0.0, -50.0)) / 3000.0;
  EXPECT_NEAR((v.position - cg).norm(), 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(v.mass, 3000.0);
  // Inertia about it: the body's own plus both masses' parallel-axis terms.
  const Vec3 d1 = Vec3(0.0, 0.0, -51.0) - cg, d2 = Vec3(2.0, 0.0, -50.0) - cg;
  const auto parallel = [&](int k) {
    const auto arm = [&](const Vec3& d) { return d.squaredNorm() - d[k] * d[k]; };
    return 2000.0 * arm(d1) + 1000.0 * arm(d2);
  };
  EXPECT_NEAR(v.inertia.x(), 500.0 + parallel(0), 1e-6);
  EXPECT_NEAR(v.inertia.y(), 600.0 + parallel(1), 1e-6);
  EXPECT_NEAR(v.inertia.z(), 700.0 + parallel(2), 1e-6);
  // Buoyancy: the body's 3 m^3 at its CG and the point's 0.5 m^3 at its place.
  EXPECT_DOUBLE_EQ(v.displacedVolume, 3.5);
  const Vec3 cb = (3.0 * Vec3(0.0, 0.0, -51.0) + 0.5 * Vec3(2.0, 0.0, -50.0)) / 3.5 - cg;
  EXPECT_NEAR((v.centreOfBuoyancy - cb).norm(), 0.0, 1e-9);
  EXPECT_NEAR(v.addedMass[0], 0.5 * 1025.0 * 3.0, 1e-9);
  EXPECT_DOUBLE_EQ(v.addedMass[3], 0.0);
  EXPECT_NEAR(v.quadraticDamping[0], 0.5 * 1025.0 * 0.4, 1e-9);
  EXPECT_NEAR(v.quadraticDamping[4], 0.5 * 1025.0 * 0.2, 1e-9);
  // The line to point 4 ends on the vessel, 3 m along y from the deck's reference point.
  EXPECT_EQ(spec.lines[0].endB.kind, model::EndKind::Vessel);
  EXPECT_EQ(spec.lines[0].endB.vessel, "body1");
  EXPECT_NEAR((spec.lines[0].endB.position - (Vec3(0.0, 3.0, -50.0) - cg)).norm(), 0.0, 1e-9);
  // On the fixed body, turned 90 deg: a pinned end where the deck's point is.
  EXPECT_EQ(spec.lines[1].endB.kind, model::EndKind::Pinned);
  EXPECT_NEAR((spec.lines[1].endB.position - Vec3(10.0, 1.0, -40.0)).norm(), 0.0, 1e-9);
}

TEST(MoorDynDeck, RodsOnAFreeBodyEndOnItsVessel) {
  // Rod 1 fixed to body 1 (a stiff line with both ends on the vessel), rod 2 pinned to it (end A on the
  // vessel, end B where a line joins it).
  const MoorDynConversion c = convertMoorDynDeck(parseMoorDynDeck(
      deck(kTwoPoints + "3 Body1 0 0 0 0 0 0 0\n", "1 chain 1 3 300 30 -\n2 rope 2 R2B 60 6 -\n", "",
           bodies("1 Free 0 0 -50 0 0 0 5000 0 1e4 2 0 0\n") +
               rods("1 pipe Body1 0 0 0 0 0 -10 2 -\n2 pipe Body1Pinned 0 0 0 5 0 0 2 -\n")),
      "deck.txt"));
  const model::ModelSpec spec = readModelString(c.yaml, "converted.yaml");
  ASSERT_GE(spec.lines.size(), 4u);
  EXPECT_EQ(spec.lines[0].name, "rod1");
  EXPECT_EQ(spec.lines[0].endA.kind, model::EndKind::Vessel);
  EXPECT_EQ(spec.lines[0].endB.kind, model::EndKind::Vessel);
  EXPECT_NEAR((spec.lines[0].endB.position - Vec3(0.0, 0.0, -10.0)).norm(), 0.0, 1e-9);
  EXPECT_EQ(spec.lines[1].name, "rod2");
  EXPECT_EQ(spec.lines[1].endA.kind, model::EndKind::Vessel);
  EXPECT_EQ(spec.lines[1].endB.kind, model::EndKind::Point);
  EXPECT_EQ(spec.lines[1].endB.point, "rod2b");
}

TEST(MoorDynDeck, RefusesBodiesItCannotRepresentNamingTheEntry) {
  const std::string body = bodies("1 Free 0 0 -50 0 0 0 5000 0 1e4 2 0 0\n");
  expectRefused(deck(kTwoPoints, "1 chain 1 B1 300 30 -\n", "", body), 20, "point on the body");
  expectRefused(deck(kTwoPoints + "3 Body2 0 0 0 0 0 0 0\n", "1 chain 1 3 300 30 -\n", "", body), 17,
                "body 2 does not exist");
  expectRefused(
      deck(kTwoPoints, "1 chain 1 2 300 30 -\n", "", bodies("1 Free 0 0 -50 0 0 0 5000 0|1 1e4 2 0 0\n")), 11,
      "CG");
  expectRefused(
      deck(kTwoPoints, "1 chain 1 2 300 30 -\n", "", bodies("1 Free 0 0 -50 0 0 0 -5 0 1e4 2 0 0\n")), 11,
      "mass >= 0");
  expectRefused(deck(kTwoPoints, "1 chain 1 2 300 30 -\n", "", bodies("1 Free 0 0 -50 0 0 0 5\n")), 11,
                "14 columns");
}

TEST(MoorDynDeck, AnEACurveFileBecomesATensionStrainCurve) {
  // MoorDyn (MoorDyn2.hpp, read_curve): EA may name a file beside the deck, three header lines then
  // `strain tension` rows.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "tangle-moordyn-ea-curve";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "poly_ea.dat")
      << "polyester\nStrain Tension\n(-) (N)\n0.0 0.0\n0.01 1.0e5\n0.02 3.0e5  # knee\n";
  const MoorDynConversion c = convertMoorDynDeck(parseMoorDynDeck(
      deck(kTwoPoints, "1 poly 1 2 320 40 -\n", "", "poly 0.2 20 poly_ea.dat -1 0 1 1 0 0\n"),
      (dir / "deck.txt").string()));
  const model::ModelSpec spec = readModelString(c.yaml, "converted.yaml");
  const section::LineType& t = spec.lineTypes.at("poly");
  ASSERT_NE(t.tensionStrain, nullptr);
  EXPECT_EQ(t.tensionStrain->x(), (std::vector<double>{0.0, 0.01, 0.02}));
  EXPECT_EQ(t.tensionStrain->y(), (std::vector<double>{0.0, 1.0e5, 3.0e5}));
  EXPECT_DOUBLE_EQ(t.axialStiffness, 2.0e7);
  // BA = -1, a damping ratio: MoorDyn's BA = zeta (L/N) sqrt(EA w) with a curve's EA its secant to the last
  // point, 3e5 / 0.02 = 1.5e7 N (MoorDyn v2.7.1, Line.cpp, initialize), not the largest slope 2e7 N.
  EXPECT_NEAR(t.axialDamping, 1.0 * (320.0 / 40.0) * std::sqrt(1.5e7 * 20.0), 1e-6);
  // MoorDyn holds the last tension beyond the curve; tangle continues its slope: said in the notes.
  EXPECT_TRUE(std::any_of(c.notes.begin(), c.notes.end(), [](const std::string& n) {
    return n.find("MoorDyn holds the tension at") != std::string::npos;
  }));
  std::filesystem::remove_all(dir);
}

TEST(MoorDynDeck, RefusesSyropeAndBadViscoelasticRopesAndMissingCurveFiles) {
  expectRefused(deck(kTwoPoints, "1 poly 1 2 320 40 -\n", "", "poly 0.2 20 poly_ea.dat -1 0 1 1 0 0\n"), 8,
                "neither a number nor a curve file that can be opened");
  expectRefused(
      deck(kTwoPoints, "1 poly 1 2 320 40 -\n", "", "poly 0.2 20 SYROPE:s.dat|1e8|20 1e9 0 1 1 0 0\n"), 8,
      "SYROPE");
  // A damping ratio (negative BA) is no viscoelastic rope's slow dashpot; a dynamic stiffness at or below EA.
  expectRefused(deck(kTwoPoints, "1 poly 1 2 320 40 -\n", "", "poly 0.2 20 1e8|2e8 -1 0 1 1 0 0\n"), 8,
                "BA > 0");
  expectRefused(deck(kTwoPoints, "1 poly 1 2 320 40 -\n", "", "poly 0.2 20 1e8|5e7 1e9 0 1 1 0 0\n"), 8,
                "must exceed the static one");
  expectRefused(deck(kTwoPoints, "1 poly 1 2 320 40 -\n", "", "poly 0.2 20 1e8|2e8|1|2 1e9 0 1 1 0 0\n"), 8,
                "2 or 3 values");
}

// MoorDyn's viscoelastic rope (MoorDyn2.cpp readLineType): "EA|EA_d" or "EA|alphaMBL|vbeta" with "BA|BA_d"
// becomes line_types[].viscoelastic, the static EA the axial_stiffness, BA the slow dashpot (not
// axial_damping).
TEST(MoorDynDeck, ReadsViscoelasticRopes) {
  for (const char* ea : {"1e8|2e8", "1e8|1.5e8|0.4"}) {
    const MoorDynDeck d = parseMoorDynDeck(
        deck(kTwoPoints, "1 poly 1 2 320 40 -\n", "", fmt::format("poly 0.2 20 {} 4e9|1e7 0 1 1 0 0\n", ea)),
        "visco.txt");
    const MoorDynConversion c = convertMoorDynDeck(d);
    const model::ModelSpec spec = readModelString(c.yaml, "visco.txt");
    const section::LineType& t = spec.lineTypes.at("poly");
    EXPECT_DOUBLE_EQ(t.axialStiffness, 1e8);
    EXPECT_TRUE(t.viscoelastic.present());
    EXPECT_DOUBLE_EQ(t.viscoelastic.dynamicStiffness, std::string(ea) == "1e8|2e8" ? 2e8 : 1.5e8);
    EXPECT_DOUBLE_EQ(t.viscoelastic.dynamicStiffnessSlope, std::string(ea) == "1e8|2e8" ? 0.0 : 0.4);
    EXPECT_DOUBLE_EQ(t.viscoelastic.slowDamping, 4e9);
    EXPECT_DOUBLE_EQ(t.viscoelastic.dynamicDamping, 1e7);
    EXPECT_EQ(t.axialDamping, 0.0);
  }
}

TEST(MoorDynDeck, RefusesVortexInducedVibration) {
  expectRefused(deck(kTwoPoints, "1 viv 1 2 320 40 -\n", "", "viv 0.2 20 1e8 -1 0 1 1 0 0 0.8\n"), 8,
                "vortex-induced vibration");
}

TEST(MoorDynDeck, RefusesUnknownAndUnsupportedOptions) {
  expectRefused(deck(kTwoPoints, "1 chain 1 2 320 40 -\n", "1 NotAnOption\n"), 20, "NotAnOption");
  expectRefused(deck(kTwoPoints, "1 chain 1 2 320 40 -\n", "no-such-bathy.txt SeafloorFile\n"), 20,
                "the seafloor file 'no-such-bathy.txt' was not found");
  expectRefused(deck(kTwoPoints, "1 chain 1 2 320 40 -\n", "2 WaveKin\n"), 20, "WaveKin");
  expectRefused(deck(kTwoPoints, "1 chain 1 2 320 40 -\n", "2 Currents\n"), 20, "Currents");  // dynamic grid
}

/// A deck and its current_profile.txt in a fresh folder; returns the deck's path.
std::string writeDeckWithProfile(const std::string& name, const std::string& profileRows) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("tangle-moordyn-" + name);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "deck.txt") << deck(kTwoPoints, "1 chain 1 2 320 40 -\n", "1 Currents\n");
  std::ofstream(dir / "current_profile.txt") << "--- MoorDyn steady currents File ---\nTabulated\n"
                                                "z (m), ux (m/s), uy (m/s), uz (m/s)\n"
                                             << profileRows;
  return (dir / "deck.txt").string();
}

TEST(MoorDynDeck, ReadsACurrentChangingInTime) {
  // MoorDyn's Currents 2 (Waves/WaveGrid.cpp, constructDynamicCurrentGrid): current_profile_dynamic.txt, the
  // levels on line 5, from line 7 rows t, ux at each level, uy at each level (uz left out: zero). A level
  // above z = 0 is left out with a note.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "tangle-moordyn-dynamic-current";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "deck.txt") << deck(kTwoPoints, "1 chain 1 2 320 40 -\n", "2 Currents\n");
  std::ofstream(dir / "current_profile_dynamic.txt") << "--- MoorDyn dynamic currents ---\nTabulated\n2\n3\n"
                                                        "-100 0 1\n\n"
                                                        "0 0.1 0.2 0.3 0 0 0\n"
                                                        "60 0 0 0 0.5 1.0 1.5\n";
  const model::ModelSpec spec = readModelFile((dir / "deck.txt").string());
  const auto& history = spec.environment.currentHistory;
  ASSERT_EQ(history.size(), 2u);
  EXPECT_DOUBLE_EQ(history[1].time, 60.0);
  ASSERT_EQ(history[1].levels.size(), 2u);  // z = 1 left out
  EXPECT_DOUBLE_EQ(history[0].levels[1].speed, 0.2);
  EXPECT_DOUBLE_EQ(history[1].levels[1].speed, 1.0);
  EXPECT_NEAR(history[1].levels[1].azimuth, std::numbers::pi / 2.0, 1e-12);  // along +y
  EXPECT_EQ(spec.environment.current.size(), 2u);  // the first profile: the statics'
  bool noted = false;
  for (const std::string& w : spec.warnings)
    noted = noted || w.find("above the still water level") != std::string::npos;
  EXPECT_TRUE(noted);
  // Times that do not increase are refused naming the file and its row.
  std::ofstream(dir / "current_profile_dynamic.txt") << "a\nb\n2\n3\n-100 0\n\n5 0.1 0.2\n5 0.1 0.2\n";
  try {
    readModelFile((dir / "deck.txt").string());
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 8);
    EXPECT_NE(std::string(e.what()).find("times must increase"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(MoorDynDeck, ReadsACurrentOnAGridInSpaceAndTime) {
  // MoorDyn's Currents 5 (Waves/WaveGrid.cpp, construct4DCurrentGrid): current_profile_4d.txt beside the
  // deck, "nx ny nz nt", the four tick lines, then "x y z t ux uy uz" rows; tangle reads it as
  // environment.current.grid.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "tangle-moordyn-4d-current";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "deck.txt") << deck(kTwoPoints, "1 chain 1 2 320 40 -\n", "5 Currents\n");
  std::ofstream(dir / "current_profile_4d.txt") << "2 1 1 2\n-500 500\n0\n-100\n0 10\n"
                                                   "-500 0 -100 0 0.2 0 0\n-500 0 -100 10 0.4 0 0\n"
                                                   "500 0 -100 0 0.6 0 0\n500 0 -100 10 0.8 0 0\n";
  const model::ModelSpec spec = readModelFile((dir / "deck.txt").string());
  ASSERT_TRUE(spec.environment.currentGrid);
  EXPECT_NEAR(spec.environment.currentGrid->velocity(Vec3(0.0, 0.0, -50.0), 5.0).x(), 0.5, 1e-15);
  bool noted = false;
  for (const std::string& w : spec.warnings) noted = noted || w.find("Currents 5") != std::string::npos;
  EXPECT_TRUE(noted);
  // A grid row off the ticks is refused naming the deck's option and the grid file's line.
  std::ofstream(dir / "current_profile_4d.txt") << "2 1 1 1\n-500 500\n0\n-100\n0\n"
                                                   "-500 0 -100 0 0.2 0 0\n400 0 -100 0 0.6 0 0\n";
  try {
    readModelFile((dir / "deck.txt").string());
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "Currents");
    EXPECT_NE(std::string(e.what()).find("current_profile_4d.txt:7: key 'x': one of the x ticks, got 400"),
              std::string::npos)
        << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(MoorDynDeck, ReadsASteadyCurrentProfile) {
  // MoorDyn's Currents 1: (ux, uy) at each level from current_profile.txt beside the deck, linear in z.
  const std::string path = writeDeckWithProfile("profile", "-100 0.3 0.4 0\n-50 0.0 1.0\n0 1.0\n");
  const model::ModelSpec spec = readModelFile(path);
  const auto& current = spec.environment.current;
  ASSERT_EQ(current.size(), 3u);
  EXPECT_DOUBLE_EQ(current[0].z, -100.0);
  EXPECT_DOUBLE_EQ(current[0].speed, 0.5);
  EXPECT_NEAR(current[0].azimuth, std::atan2(0.4, 0.3), 1e-12);
  EXPECT_NEAR(current[1].azimuth, std::numbers::pi / 2.0, 1e-12);  // along +y
  EXPECT_DOUBLE_EQ(current[2].speed, 1.0);
  EXPECT_DOUBLE_EQ(current[2].azimuth, 0.0);
  // The direction turns with depth: noted (tangle interpolates speed and direction, MoorDyn components).
  bool noted = false;
  for (const std::string& w : spec.warnings) noted = noted || w.find("turns with depth") != std::string::npos;
  EXPECT_TRUE(noted);
}

/// A deck in its own temporary folder `name` with `file` (wave_frequencies.txt or wave_elevation.txt) beside
/// it and WaveKin `mode`; returns the converted model.
model::ModelSpec convertedWithWaveFile(const std::string& name, const std::string& file,
                                       const std::string& text, int mode,
                                       const std::string& extraOptions = "") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("tangle-moordyn-" + name);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / file) << text;
  const MoorDynConversion c = convertMoorDynDeck(parseMoorDynDeck(
      deck(kTwoPoints, "1 chain 1 2 320 32 -\n", fmt::format("{}  WaveKin  waves\n", mode) + extraOptions),
      (dir / "deck.txt").string()));
  std::filesystem::remove_all(dir);
  return readModelString(c.yaml, "converted.yaml");
}

TEST(MoorDynDeck, WaveFrequenciesBecomeWaveComponentsWithMoorDynsElevation) {
  // WaveKin 7: rows omega [rad/s], Re c, Im c [m], [beta rad]; MoorDyn (Waves/SpectrumKin.cpp) sums
  // |c| sin(omega t - k (x cos beta + y sin beta) + arg c). The converted sea gives that elevation, with k
  // from the same dispersion relation; the zero-frequency row is left out. Tolerance: round-off, 1e-12 m.
  const std::vector<std::array<double, 4>> rows{
      {0.35, 1.0, 0.0, 0.0}, {0.4, 0.0, 1.0, 1.57}, {0.9, -0.3, 0.2, -0.5}};
  std::string text = "0.0 0.0 0.0\n";
  for (const auto& r : rows) text += fmt::format("{} {} {} {}\n", r[0], r[1], r[2], r[3]);
  const model::ModelSpec spec = convertedWithWaveFile("wave-frequencies", "wave_frequencies.txt", text, 7);
  ASSERT_EQ(spec.environment.waves.kind, model::WaveKind::Components);
  ASSERT_EQ(spec.environment.waves.componentTable.size(), 3u);
  const std::unique_ptr<hydro::WaveField> sea = hydro::makeWaveField(spec.environment);
  const double depth = spec.environment.waterDepth, g = spec.environment.gravity;
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(40.0, -25.0, 0.0)})
    for (const double t : {0.0, 3.7, 21.2}) {
      double expected = 0.0;
      for (const auto& r : rows) {
        const double k = hydro::solveDispersion(r[0], depth, g);
        expected += std::hypot(r[1], r[2]) *
                    std::sin(r[0] * t - k * (p.x() * std::cos(r[3]) + p.y() * std::sin(r[3])) +
                             std::atan2(r[2], r[1]));
      }
      EXPECT_NEAR(sea->elevation(p.x(), p.y(), t), expected, 1e-12) << p.transpose() << " t " << t;
    }
}

TEST(MoorDynDeck, AWaveElevationRecordBecomesItsFourierSeries) {
  // WaveKin 3: t, eta rows resampled every dtWave and expanded in their discrete Fourier series. A record of
  // 0.8 sin(2 pi t / 12) + 0.3 cos(2 pi t / 4 + 0.4) over one 12 s period, sampled every 0.05 s and resampled
  // at dtWave = 0.1 s: two components of those periods and amplitudes, and the series through every sample at
  // x = 0 (the record is periodic and band-limited: exact to round-off, 1e-9 m).
  const auto record = [](double t) {
    return 0.8 * std::sin(2.0 * kPi * t / 12.0) + 0.3 * std::cos(2.0 * kPi * t / 4.0 + 0.4);
  };
  std::string text;
  for (int n = 0; n <= 240; ++n) text += fmt::format("{:.17g} {:.17g}\n", 0.05 * n, record(0.05 * n));
  const model::ModelSpec spec =
      convertedWithWaveFile("wave-elevation", "wave_elevation.txt", text, 3, "0.1  dtWave  step\n");
  const auto& table = spec.environment.waves.componentTable;
  ASSERT_EQ(table.size(), 2u);
  EXPECT_NEAR(table[0][0], 12.0, 1e-9);
  EXPECT_NEAR(table[0][1], 0.8, 1e-9);
  EXPECT_NEAR(table[1][0], 4.0, 1e-9);
  EXPECT_NEAR(table[1][1], 0.3, 1e-9);
  const std::unique_ptr<hydro::WaveField> sea = hydro::makeWaveField(spec.environment);
  for (const double t : {0.0, 0.05, 1.3, 7.77, 11.95, 30.0})
    EXPECT_NEAR(sea->elevation(0.0, 0.0, t), record(t), 1e-9) << t;
}

TEST(MoorDynDeck, RefusesAVerticalCurrentNamingTheProfileLine) {
  const std::string path = writeDeckWithProfile("vertical", "-100 0.3 0 0\n-50 0.2 0 0.1\n");
  try {
    readModelFile(path);
    FAIL() << "a vertical current was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(e.file().find("current_profile.txt"), std::string::npos) << e.what();
    EXPECT_EQ(e.line(), 5);
    EXPECT_EQ(e.key(), "uz");
  }
}

TEST(MoorDynDeck, AFreePointJoiningThreeLinesBecomesAPoint) {
  // Anchors 1 and 4 and vessel 2, each with a line to the free point 3 (a triplate with its own body); the
  // line from anchor 4 is drawn from the point.
  const std::string points = kTwoPoints + "3 Free -150 0 -60 500 0.4 0.6 0.5\n4 Fixed 300 0 -100 0 0 0 0\n";
  const MoorDynConversion c =
      convertMoorDynDeck(parseMoorDynDeck(deck(points,
                                               "1 chain 1 3 200 20 -\n2 rope 2 3 160 16 -\n"
                                               "3 chain 3 4 460 46 -\n"),
                                          "deck.txt"));
  const model::ModelSpec spec = readModelString(c.yaml, "converted.yaml");
  ASSERT_EQ(spec.points.size(), 1u);
  const model::PointSpec& p = spec.points[0];
  EXPECT_EQ(p.name, "point3");
  EXPECT_EQ(p.position, Vec3(-150.0, 0.0, -60.0));
  EXPECT_DOUBLE_EQ(p.body.mass, 500.0);
  EXPECT_DOUBLE_EQ(p.body.volume, 0.4);
  EXPECT_DOUBLE_EQ(p.body.dragArea, 0.6);
  EXPECT_DOUBLE_EQ(p.body.addedMass, 0.5 * 1025.0 * 0.4);  // Ca rho V
  ASSERT_EQ(spec.lines.size(), 3u);                        // no chain passes through a point of three lines
  EXPECT_EQ(spec.lines[0].endB.kind, model::EndKind::Point);
  EXPECT_EQ(spec.lines[1].endB.kind, model::EndKind::Point);
  EXPECT_EQ(spec.lines[2].endA.kind, model::EndKind::Point);
  for (const model::LineSpec& l : spec.lines)
    EXPECT_TRUE(l.attachments.empty()) << l.name;  // the body is the point's
  // The first line end at the point carries it: line 1's end B, node 20.
  EXPECT_EQ(c.points[2].junctionLine, "line1");
  EXPECT_EQ(c.points[2].junctionNode, 20);
  EXPECT_EQ(c.points[2].ends.size(), 3u);
}

/// A FAILURE section with these rows.
std::string failures(const std::string& rows) {
  return "---------------------- FAILURE ----------------------\n"
         "FailureID  Point    Line(s)   FailTime   FailTen\n"
         "()           ()       (,)      (s or 0)   (N or 0)\n" +
         rows;
}

// Anchor 1 - line 1 - buoy 3 - line 2 (drawn from the vessel) - vessel 2; anchor 4 - line 3 - vessel 5.
const std::string kFailurePoints = kTwoPoints +
                                   "3     Free      -150   0     -60    100    2.0     1.5    0.8\n"
                                   "4     Fixed     0  -300   -100   0      0       0      0\n"
                                   "5     Vessel    0  -10    -10    0      0       0      0\n";
const std::string kFailureLines = "1 chain 1 3 200 20 -\n2 rope 2 3 160 16 -\n3 chain 4 5 320 32 -\n";

TEST(MoorDynDeck, FailureRowsBecomeLineFailures) {
  // MoorDyn (docs/inputs.rst, "Failure"): the listed lines part from the point at FailTime or FailTen.
  const MoorDynConversion c = convertMoorDynDeck(
      parseMoorDynDeck(deck(kFailurePoints, kFailureLines, "", "",
                            failures("1 5 3 0 1.2e6\n2 P3 1 30 0   # the buoy's shackle\n")),
                       "deck.txt"));
  const model::ModelSpec spec = readModelString(c.yaml, "converted.yaml");
  ASSERT_EQ(spec.lines.size(), 2u);
  // Line 1 parts from the buoy inside the joined line1-line2, at arc 200 m, at 30 s.
  const model::FailureSpec& joined = spec.lines[0].failure;
  EXPECT_EQ(spec.lines[0].name, "line1-line2");
  EXPECT_TRUE(joined.enabled);
  EXPECT_DOUBLE_EQ(joined.time, 30.0);
  EXPECT_EQ(joined.tension, 0.0);
  EXPECT_EQ(joined.where, model::FailureSpec::Where::Arc);
  EXPECT_DOUBLE_EQ(joined.arcLength, 200.0);
  // Line 3 parts from its vessel point (end B) on its own end tension.
  const model::FailureSpec& single = spec.lines[1].failure;
  EXPECT_TRUE(std::isnan(single.time));
  EXPECT_DOUBLE_EQ(single.tension, 1.2e6);
  EXPECT_EQ(single.where, model::FailureSpec::Where::EndB);
}

TEST(MoorDynDeck, CommentsAfterARowsValuesAreSkipped) {
  const MoorDynDeck d = parseMoorDynDeck(deck(kTwoPoints + "", "1 chain 1 2 320 40 -   # the main leg\n", "",
                                              "poly 0.2 20 1e8 -1 0 1 1 0 0 #note\n"),
                                         "deck.txt");
  ASSERT_EQ(d.lines.size(), 1u);
  EXPECT_EQ(d.lines[0].segments, 40);
  EXPECT_DOUBLE_EQ(d.lineTypes.back().addedMassAxial, 0.0);
}

TEST(MoorDynDeck, RefusesFailuresTangleCannotHonour) {
  // Failure rows start at deck line 25 (after the types, points and lines, and the section's 3 lines).
  expectRefused(deck(kFailurePoints, kFailureLines, "", "", failures("1 R1a 1 10 0\n")), 25, "rod end");
  expectRefused(deck(kFailurePoints, kFailureLines, "", "", failures("1 5 1 10 0\n")), 25,
                "line 1 is not attached to point 5");
  expectRefused(deck(kFailurePoints, kFailureLines, "", "", failures("1 5 3 10 0\n2 4 3 20 0\n")), 26,
                "would part a second time");
  expectRefused(deck(kFailurePoints, kFailureLines, "", "", failures("1 5 3 -1 0\n")), 25, "FailTime");
}

TEST(MoorDynDeck, RefusesALoopOfLines) {
  const std::string points = "1 Free 0 0 -50 0 0 0 0\n2 Free 10 0 -50 0 0 0 0\n";
  expectRefused(deck(points, "1 chain 1 2 20 4 -\n2 chain 2 1 20 4 -\n"), 16, "loop");
}

TEST(MoorDynDeck, RefusesBadRowsNamingTheEntry) {
  expectRefused(deck(kTwoPoints, "1 nylon 1 2 320 40 -\n"), 16, "no line type named 'nylon'");
  expectRefused(deck(kTwoPoints, "1 chain 1 5 320 40 -\n"), 16, "point 5 does not exist");
  expectRefused(deck(kTwoPoints, "2 chain 1 2 320 40 -\n"), 16, "in order");
  expectRefused(deck(kTwoPoints, "1 chain 1 2 320 -\n"), 16, "7 columns");
  expectRefused(deck(kTwoPoints, "1 chain 1 2 long 40 -\n"), 16, "'long'");
  expectRefused(deck("1 Fixed 0 0 -100 0 0 0 0\n2 Tethered 0 0 -10 0 0 0 0\n", "1 chain 1 2 320 40 -\n"), 12,
                "unknown point type 'Tethered'");
  expectRefused(deck(kTwoPoints + "3 Free 0 0 -50 0 0 0 0\n", "1 chain 1 2 320 40 -\n"), 13,
                "no line is attached");
  expectRefused(deck(kTwoPoints, "1 chain 2 2 320 40 -\n"), 16, "same point");
  expectRefused(
      deck("1 Fixed 0 0 -100 0 0 0 0 1000 0 0 0 0\n2 Vessel 0 0 -10 0 0 0 0\n", "1 chain 1 2 320 40 -\n"), 11,
      "external force");
}

}  // namespace
}  // namespace tangle::io
