// Unit tests of the MoorDyn-compatible C API (include/tangle-moordyn/), through the exported C functions
// alone (this executable links libtangle_moordyn, not tangle_lib): the error codes of NULL and closed
// handles, out-of-range ids and functions tangle does not implement; the answers about the coupled_chain
// deck (one 410 m chain from a fixed anchor at (400, 0, -50) to a coupled fairlead at the origin, 41
// segments) before and after MoorDyn_Init; the old single-system API.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include "MoorDyn.h"
#include "MoorDyn2.h"
#include "TestPaths.hpp"

namespace {

std::string deckPath() { return std::string(tangle::test::kTestDataDir) + "/moordyn/coupled_chain.txt"; }

double norm(const double v[3]) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

/// The text of the deck at `path`.
std::string readDeck(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// MoorDyn_Create on `deck` written to the temporary file `name`, removed after: NULL when refused.
MoorDyn createFromText(const std::string& deck, const std::string& name) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::ofstream(path) << deck;
  MoorDyn system = MoorDyn_Create(path.c_str());
  std::filesystem::remove(path);
  return system;
}

TEST(MoorDynApi, CreateReturnsNullForAMissingFile) {
  EXPECT_EQ(MoorDyn_Create("/nonexistent/tangle/deck.txt"), nullptr);
}

TEST(MoorDynApi, NullHandlesAreInvalidValues) {
  unsigned int n = 7;
  int id = 0;
  double x[3] = {0, 0, 0}, f[3], t = 0.0, dt = 0.1;
  float h = 0, v = 0, ah = 0, av = 0;
  const int one = 1;
  EXPECT_EQ(MoorDyn_NCoupledDOF(nullptr, &n), MOORDYN_INVALID_VALUE);
  EXPECT_EQ(n, 7u);  // untouched
  EXPECT_EQ(MoorDyn_Init(nullptr, x, x), MOORDYN_INVALID_VALUE);
  EXPECT_EQ(MoorDyn_Step(nullptr, x, x, f, &t, &dt), MOORDYN_INVALID_VALUE);
  EXPECT_EQ(MoorDyn_GetFASTtens(nullptr, &one, &h, &v, &ah, &av), MOORDYN_INVALID_VALUE);
  EXPECT_EQ(MoorDyn_Close(nullptr), MOORDYN_INVALID_VALUE);
  EXPECT_EQ(MoorDyn_GetLine(nullptr, 1), nullptr);
  EXPECT_EQ(MoorDyn_GetPoint(nullptr, 1), nullptr);
  EXPECT_EQ(MoorDyn_GetLineID(nullptr, &id), MOORDYN_INVALID_VALUE);
  EXPECT_EQ(MoorDyn_GetLineFairTen(nullptr, &t), MOORDYN_INVALID_VALUE);
  EXPECT_EQ(MoorDyn_GetPointType(nullptr, &id), MOORDYN_INVALID_VALUE);
  EXPECT_EQ(MoorDyn_GetPointPos(nullptr, x), MOORDYN_INVALID_VALUE);
  EXPECT_EQ(MoorDyn_SaveState(nullptr, "state.txt"), MOORDYN_INVALID_VALUE);
}

TEST(MoorDynApi, DescribesTheDeckBeforeInit) {
  MoorDyn system = MoorDyn_Create(deckPath().c_str());
  ASSERT_NE(system, nullptr);
  unsigned int n = 0;
  EXPECT_EQ(MoorDyn_NCoupledDOF(system, &n), MOORDYN_SUCCESS);
  EXPECT_EQ(n, 3u);
  EXPECT_EQ(MoorDyn_GetNumberLines(system, &n), MOORDYN_SUCCESS);
  EXPECT_EQ(n, 1u);
  EXPECT_EQ(MoorDyn_GetNumberPoints(system, &n), MOORDYN_SUCCESS);
  EXPECT_EQ(n, 2u);
  EXPECT_EQ(MoorDyn_GetNumberBodies(system, &n), MOORDYN_SUCCESS);
  EXPECT_EQ(n, 0u);
  EXPECT_EQ(MoorDyn_GetNumberRods(system, &n), MOORDYN_SUCCESS);
  EXPECT_EQ(n, 0u);
  EXPECT_EQ(MoorDyn_GetLine(system, 0), nullptr);  // ids start at 1
  EXPECT_EQ(MoorDyn_GetLine(system, 2), nullptr);
  EXPECT_EQ(MoorDyn_GetPoint(system, 0), nullptr);
  EXPECT_EQ(MoorDyn_GetPoint(system, 3), nullptr);
  EXPECT_EQ(MoorDyn_GetBody(system, 1), nullptr);
  EXPECT_EQ(MoorDyn_GetRod(system, 1), nullptr);  // the deck has no rod

  MoorDynLine line = MoorDyn_GetLine(system, 1);
  ASSERT_NE(line, nullptr);
  int id = 0;
  EXPECT_EQ(MoorDyn_GetLineID(line, &id), MOORDYN_SUCCESS);
  EXPECT_EQ(id, 1);
  EXPECT_EQ(MoorDyn_GetLineN(line, &n), MOORDYN_SUCCESS);
  EXPECT_EQ(n, 41u);
  EXPECT_EQ(MoorDyn_GetLineNumberNodes(line, &n), MOORDYN_SUCCESS);
  EXPECT_EQ(n, 42u);
  double value = 0.0;
  EXPECT_EQ(MoorDyn_GetLineUnstretchedLength(line, &value), MOORDYN_SUCCESS);
  EXPECT_DOUBLE_EQ(value, 410.0);
  EXPECT_EQ(MoorDyn_GetLineConstantEA(line, &value), MOORDYN_SUCCESS);
  EXPECT_DOUBLE_EQ(value, 1.674e9);
  EXPECT_EQ(MoorDyn_GetDt(system, &value), MOORDYN_SUCCESS);
  EXPECT_DOUBLE_EQ(value, 0.01);

  MoorDynPoint anchor = MoorDyn_GetPoint(system, 1);
  MoorDynPoint fairlead = MoorDyn_GetPoint(system, 2);
  ASSERT_NE(anchor, nullptr);
  ASSERT_NE(fairlead, nullptr);
  int type = 0;
  EXPECT_EQ(MoorDyn_GetPointType(anchor, &type), MOORDYN_SUCCESS);
  EXPECT_EQ(type, 1);  // MoorDyn's FIXED
  EXPECT_EQ(MoorDyn_GetPointType(fairlead, &type), MOORDYN_SUCCESS);
  EXPECT_EQ(type, -1);  // MoorDyn's COUPLED
  double pos[3] = {1, 1, 1};
  EXPECT_EQ(MoorDyn_GetPointPos(fairlead, pos), MOORDYN_SUCCESS);
  EXPECT_EQ(norm(pos), 0.0);
  EXPECT_EQ(MoorDyn_GetPointPos(anchor, pos), MOORDYN_SUCCESS);
  EXPECT_DOUBLE_EQ(pos[0], 400.0);
  EXPECT_DOUBLE_EQ(pos[2], -50.0);
  EXPECT_EQ(MoorDyn_GetPointNAttached(fairlead, &n), MOORDYN_SUCCESS);
  EXPECT_EQ(n, 1u);
  MoorDynLine attached = nullptr;
  int end = -1;
  EXPECT_EQ(MoorDyn_GetPointAttached(fairlead, 0, &attached, &end), MOORDYN_SUCCESS);
  EXPECT_EQ(attached, line);
  EXPECT_EQ(end, 1);  // end B
  EXPECT_EQ(MoorDyn_GetPointAttached(fairlead, 1, &attached, &end), MOORDYN_INVALID_VALUE);

  // No results before MoorDyn_Init.
  double x[3] = {0, 0, 0}, f[3], t = 0.0, dt = 0.1;
  EXPECT_EQ(MoorDyn_GetLineNodePos(line, 0, pos), MOORDYN_INVALID_VALUE);
  EXPECT_EQ(MoorDyn_GetLineFairTen(line, &value), MOORDYN_INVALID_VALUE);
  EXPECT_EQ(MoorDyn_GetPointForce(fairlead, pos), MOORDYN_INVALID_VALUE);
  EXPECT_EQ(MoorDyn_Step(system, x, x, f, &t, &dt), MOORDYN_INVALID_VALUE);
  EXPECT_EQ(MoorDyn_SetDt(system, -1.0), MOORDYN_INVALID_VALUE);

  EXPECT_EQ(MoorDyn_Close(system), MOORDYN_SUCCESS);
  EXPECT_EQ(MoorDyn_Close(system), MOORDYN_INVALID_VALUE);  // closed handles are recognised
}

TEST(MoorDynApi, AnswersAfterInitAndStep) {
  MoorDyn system = MoorDyn_Create(deckPath().c_str());
  ASSERT_NE(system, nullptr);
  MoorDynLine line = MoorDyn_GetLine(system, 1);
  MoorDynPoint anchor = MoorDyn_GetPoint(system, 1);
  MoorDynPoint fairlead = MoorDyn_GetPoint(system, 2);
  double x[3] = {0, 0, 0}, xd[3] = {0, 0, 0};
  ASSERT_EQ(MoorDyn_Init(system, x, xd), MOORDYN_SUCCESS);
  EXPECT_EQ(MoorDyn_Init(system, x, xd), MOORDYN_INVALID_VALUE);  // once only
  EXPECT_EQ(MoorDyn_SetDt(system, 0.005), MOORDYN_NON_IMPLEMENTED);

  // The fairlead end: node 41 at the coupled point. MoorDyn's tension there (Line::getNodeTen, and
  // MoorDyn_GetLineFairTen its norm) is the top segment's, EA (l / l0 - 1) from its stretch, along the
  // segment; its largest tension (MoorDyn_GetLineMaxTen) is over nodes 0 to N - 1, the top node left out.
  double pos[3], below[3], ten[3], fairTen = 0.0, maxTen = 0.0, ea = 0.0;
  ASSERT_EQ(MoorDyn_GetLineNodePos(line, 41, pos), MOORDYN_SUCCESS);
  EXPECT_NEAR(norm(pos), 0.0, 1e-9);
  EXPECT_EQ(MoorDyn_GetLineNodePos(line, 42, pos), MOORDYN_INVALID_VALUE);
  ASSERT_EQ(MoorDyn_GetLineNodePos(line, 40, below), MOORDYN_SUCCESS);
  ASSERT_EQ(MoorDyn_GetLineConstantEA(line, &ea), MOORDYN_SUCCESS);
  const double segment[3] = {pos[0] - below[0], pos[1] - below[1], pos[2] - below[2]};
  ASSERT_EQ(MoorDyn_GetLineFairTen(line, &fairTen), MOORDYN_SUCCESS);
  EXPECT_GT(fairTen, 1e5);
  EXPECT_NEAR(fairTen, ea * (norm(segment) / 10.0 - 1.0), 1e-9 * fairTen);
  ASSERT_EQ(MoorDyn_GetLineNodeTen(line, 41, ten), MOORDYN_SUCCESS);
  EXPECT_NEAR(norm(ten), fairTen, 1e-9 * fairTen);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(ten[k], fairTen * segment[k] / norm(segment), 1e-9 * fairTen);
  EXPECT_LT(ten[0], 0.0);  // pointing from end A (anchor, x = 400) towards end B (x = 0)
  ASSERT_EQ(MoorDyn_GetLineMaxTen(line, &maxTen), MOORDYN_SUCCESS);
  double ten40[3];
  ASSERT_EQ(MoorDyn_GetLineNodeTen(line, 40, ten40), MOORDYN_SUCCESS);
  EXPECT_NEAR(maxTen, norm(ten40), 1e-9 * maxTen);  // the chain's tension grows towards the fairlead
  EXPECT_LT(maxTen, fairTen);
  ASSERT_EQ(MoorDyn_GetLineNodePos(line, 0, pos), MOORDYN_SUCCESS);
  EXPECT_NEAR(pos[0], 400.0, 1e-6);

  // The force on the fairlead (MoorDyn_GetLineNodeForce at the top, MoorDyn's Fnet there) is the top
  // segment's pull and the top node's own load: half a segment's submerged weight, (390 - rho pi / 4 d^2)
  // g l0 / 2, in statics (no current).
  double topForce[3];
  ASSERT_EQ(MoorDyn_GetLineNodeForce(line, 41, topForce), MOORDYN_SUCCESS);
  const double halfSegment = (390.0 - 1025.0 * 3.141592653589793 / 4.0 * 0.252 * 0.252) * 9.81 * 10.0 / 2.0;
  EXPECT_NEAR(topForce[0], -ten[0], 1e-6 * fairTen);
  EXPECT_NEAR(topForce[1], -ten[1], 1e-6 * fairTen);
  EXPECT_NEAR(topForce[2], -ten[2] - halfSegment, 1e-3 * halfSegment);

  // FAST's customary tensions: the line pulls the fairlead down and towards the anchor; the anchor's
  // horizontal force is the fairlead's (no current, no friction, a grounded length at the anchor).
  const int count = 1;
  float fairH = 0, fairV = 0, anchH = 0, anchV = 0;
  ASSERT_EQ(MoorDyn_GetFASTtens(system, &count, &fairH, &fairV, &anchH, &anchV), MOORDYN_SUCCESS);
  EXPECT_GT(fairH, 0.0f);
  EXPECT_LT(fairV, 0.0f);
  EXPECT_NEAR(anchH, fairH, 1e-3 * fairH);
  EXPECT_NEAR(fairH, std::hypot(topForce[0], topForce[1]), 1e-5 * fairTen);  // float precision
  EXPECT_NEAR(fairV, topForce[2], 1e-5 * fairTen);
  const int tooMany = 2;
  EXPECT_EQ(MoorDyn_GetFASTtens(system, &tooMany, &fairH, &fairV, &anchH, &anchV), MOORDYN_INVALID_VALUE);

  // MoorDyn_Step with dt = 0 only returns the forces: the coupled point's force.
  double f[3], pointForce[3], t = -1.0, dt = 0.0;
  ASSERT_EQ(MoorDyn_Step(system, x, xd, f, &t, &dt), MOORDYN_SUCCESS);
  EXPECT_EQ(t, 0.0);
  ASSERT_EQ(MoorDyn_GetPointForce(fairlead, pointForce), MOORDYN_SUCCESS);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(pointForce[i], f[i]);
  EXPECT_GT(f[0], 0.0);  // towards the anchor
  ASSERT_EQ(MoorDyn_GetPointForce(anchor, pointForce), MOORDYN_SUCCESS);
  EXPECT_LT(pointForce[0], 0.0);  // the anchor is pulled towards the fairlead

  // Hold the fairlead for 0.5 s in host steps of 0.1 s (ten model steps each).
  for (int k = 0; k < 5; ++k) {
    dt = 0.1;
    ASSERT_EQ(MoorDyn_Step(system, x, xd, f, &t, &dt), MOORDYN_SUCCESS);
  }
  EXPECT_NEAR(t, 0.5, 1e-9);
  double vel[3] = {1, 1, 1};
  ASSERT_EQ(MoorDyn_GetPointVel(fairlead, vel), MOORDYN_SUCCESS);
  EXPECT_EQ(norm(vel), 0.0);
  double nan[3] = {std::nan(""), 0, 0};
  dt = 0.1;
  EXPECT_EQ(MoorDyn_Step(system, nan, xd, f, &t, &dt), MOORDYN_INVALID_VALUE);

  // What tangle does not have.
  double node[3];
  EXPECT_EQ(MoorDyn_GetLineNodeDrag(line, 3, node), MOORDYN_NON_IMPLEMENTED);
  EXPECT_EQ(MoorDyn_SaveState(system, "state.txt"), MOORDYN_NON_IMPLEMENTED);
  EXPECT_EQ(MoorDyn_BreakLine(system, fairlead, line), MOORDYN_NON_IMPLEMENTED);
  // The deck has no WaveKin 1: no points for external wave kinematics, and setting them is refused (MoorDyn's
  // answers).
  unsigned int n = 7;
  EXPECT_EQ(MoorDyn_ExternalWaveKinInit(system, &n), MOORDYN_SUCCESS);
  EXPECT_EQ(n, 0u);
  const double zeros[3] = {0.0, 0.0, 0.0};
  EXPECT_EQ(MoorDyn_ExternalWaveKinSet(system, zeros, zeros, 0.0), MOORDYN_INVALID_VALUE);
  EXPECT_EQ(MoorDyn_GetWaves(system), nullptr);
  EXPECT_EQ(MoorDyn_GetSeafloor(system), nullptr);
  size_t length = 0;
  ASSERT_EQ(MoorDyn_GetTimeScheme(system, nullptr, &length), MOORDYN_SUCCESS);
  std::string scheme(length, '\0');
  ASSERT_EQ(MoorDyn_GetTimeScheme(system, scheme.data(), nullptr), MOORDYN_SUCCESS);
  EXPECT_EQ(std::string(scheme.c_str()), "generalized_alpha");

  EXPECT_EQ(MoorDyn_Close(system), MOORDYN_SUCCESS);
}

// A line of one segment (coupled_chain.txt's chain, 64 m from an anchor at (40, 0, -50) to the fairlead at
// the origin: taut, 0.05 % stretched): the force on the fairlead (MoorDyn_GetLineNodeForce at the top,
// MoorDyn's Fnet there) is the segment's pull and half its submerged weight, (390 - rho pi / 4 0.252^2) 9.81
// x 64 / 2 = 108 kN, after MoorDyn_Init (the statics' exact end force) and after steps holding the fairlead
// alike (1e-3 of that weight: the dynamics' end force is extrapolated, here with the element's own weight as
// the slope). Until 2026-12-06 the steps dropped the weight (858 N against the statics' 116 kN on the
// reviewer's deck).
TEST(MoorDynApi, OneSegmentLineKeepsItsEndForceFromInitToStep) {
  std::string deck = readDeck(deckPath());
  const std::string anchorRow = "1     Fixed       400.0   0.0     -50.0";
  const std::string lineRow = "1    chain      1        2        410.0     41";
  ASSERT_NE(deck.find(anchorRow), std::string::npos);
  ASSERT_NE(deck.find(lineRow), std::string::npos);
  deck.replace(deck.find(anchorRow), anchorRow.size(), "1     Fixed       40.0    0.0     -50.0");
  deck.replace(deck.find(lineRow), lineRow.size(), "1    chain      1        2        64.0      1 ");
  MoorDyn system = createFromText(deck, "tangle-one-segment.txt");
  ASSERT_NE(system, nullptr);
  double x[3] = {0, 0, 0}, xd[3] = {0, 0, 0}, f[3], t = 0.0, dt = 0.05;
  ASSERT_EQ(MoorDyn_Init(system, x, xd), MOORDYN_SUCCESS);
  MoorDynLine line = MoorDyn_GetLine(system, 1);
  const double halfWeight = (390.0 - 1025.0 * 3.141592653589793 / 4.0 * 0.252 * 0.252) * 9.81 * 64.0 / 2.0;
  for (int step = 0; step <= 5; ++step) {
    if (step > 0) {
      ASSERT_EQ(MoorDyn_Step(system, x, xd, f, &t, &dt), MOORDYN_SUCCESS);
    }
    double ten[3], force[3];
    ASSERT_EQ(MoorDyn_GetLineNodeTen(line, 1, ten), MOORDYN_SUCCESS);
    ASSERT_EQ(MoorDyn_GetLineNodeForce(line, 1, force), MOORDYN_SUCCESS);
    EXPECT_GT(norm(ten), 1e5) << "step " << step;
    EXPECT_NEAR(force[0], -ten[0], 1e-3 * halfWeight) << "step " << step;
    EXPECT_NEAR(force[2], -ten[2] - halfWeight, 1e-3 * halfWeight) << "step " << step;
  }
  EXPECT_EQ(MoorDyn_Close(system), MOORDYN_SUCCESS);
}

// The jumper deck has WaveKin 1: the host gives the fluid kinematics at every line node (0 to 68), at the
// two points and at MoorDyn's ground body, in MoorDyn's order (Waves::kinematicsForAllNodes: lines, rods,
// points, bodies); a current across the line raises the top tension over still water.
TEST(MoorDynApi, ExternalWaveKinematicsReachTheLine) {
  const std::string jumper = std::string(tangle::test::kTestDataDir) + "/moordyn/lowe_langley_jumper.txt";
  MoorDyn system = MoorDyn_Create(jumper.c_str());
  ASSERT_NE(system, nullptr);
  MoorDynPoint top = MoorDyn_GetPoint(system, 2);
  double x[3], xd[3] = {0.0, 0.0, 0.0}, f[3], t = 0.0, dt = 0.01;
  ASSERT_EQ(MoorDyn_GetPointPos(top, x), MOORDYN_SUCCESS);
  ASSERT_EQ(MoorDyn_Init(system, x, xd), MOORDYN_SUCCESS);
  unsigned int n = 0;
  ASSERT_EQ(MoorDyn_ExternalWaveKinInit(system, &n), MOORDYN_SUCCESS);
  ASSERT_EQ(n, 69u + 2u + 1u);
  std::vector<double> r(3 * n);
  ASSERT_EQ(MoorDyn_ExternalWaveKinGetCoordinates(system, r.data()), MOORDYN_SUCCESS);
  MoorDynLine line = MoorDyn_GetLine(system, 1);
  double node[3];
  ASSERT_EQ(MoorDyn_GetLineNodePos(line, 30, node), MOORDYN_SUCCESS);
  for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(r[3 * 30 + k], node[k]);
  for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(r[3 * 70 + k], x[k]);  // the last point: the top
  for (int k = 0; k < 3; ++k) EXPECT_EQ(r[3 * 71 + k], 0.0);          // the ground body
  std::vector<double> u(3 * n, 0.0), a(3 * n, 0.0);
  // Still water given by the host: the jumper stays in its plane (no force across it on the top).
  ASSERT_EQ(MoorDyn_ExternalWaveKinSet(system, u.data(), a.data(), 0.0), MOORDYN_SUCCESS);
  for (int s = 0; s < 50; ++s) ASSERT_EQ(MoorDyn_Step(system, x, xd, f, &t, &dt), MOORDYN_SUCCESS);
  EXPECT_LT(std::abs(f[1]), 1.0);
  // 1 m/s across the jumper's plane (drag about 0.2 kN/m): the flow pushes the line along +y, and the line
  // pulls the top with it.
  for (unsigned int i = 0; i < n; ++i) u[3 * i + 1] = 1.0;
  ASSERT_EQ(MoorDyn_ExternalWaveKinSet(system, u.data(), a.data(), 0.0), MOORDYN_SUCCESS);
  for (int s = 0; s < 200; ++s) ASSERT_EQ(MoorDyn_Step(system, x, xd, f, &t, &dt), MOORDYN_SUCCESS);
  EXPECT_GT(f[1], 1e3);
  std::vector<double> notNumbers(3 * n, std::nan(""));
  EXPECT_EQ(MoorDyn_ExternalWaveKinSet(system, notNumbers.data(), a.data(), 0.0), MOORDYN_INVALID_VALUE);
  EXPECT_EQ(MoorDyn_Close(system), MOORDYN_SUCCESS);
}

// A buoy joining two deck lines (buoy_and_clump.txt: point 2, 1000 kg, 12 m^3, between a chain and a
// polyester rope) sits inside one tangle line: the lines' forces on it are each line's own end segment, so
// they hold the buoy's net lift down less the half segments of line lumped on its node (statics).
TEST(MoorDynApi, FreePointJoiningTwoLinesIsBalanced) {
  const std::string deck = std::string(tangle::test::kTestDataDir) + "/moordyn/buoy_and_clump.txt";
  MoorDyn system = MoorDyn_Create(deck.c_str());
  ASSERT_NE(system, nullptr);
  double x[3], xd[3] = {0.0, 0.0, 0.0};
  ASSERT_EQ(MoorDyn_GetPointPos(MoorDyn_GetPoint(system, 3), x), MOORDYN_SUCCESS);
  ASSERT_EQ(MoorDyn_Init(system, x, xd), MOORDYN_SUCCESS);
  double f[3];
  ASSERT_EQ(MoorDyn_GetPointForce(MoorDyn_GetPoint(system, 2), f), MOORDYN_SUCCESS);
  const double g = 9.80665, rho = 1025.0, pi = 3.141592653589793;
  const double lift = (12.0 * rho - 1000.0) * g;
  const double halfSegments =
      5.0 * g * ((140.0 - rho * pi / 4.0 * 0.15 * 0.15) + (20.0 - rho * pi / 4.0 * 0.16 * 0.16));
  EXPECT_NEAR(f[0], 0.0, 1.0);
  EXPECT_NEAR(f[2], -(lift - halfSegments), 10.0);
  // The chain below the buoy carries far more than the rope above it, each at its own end.
  double chain = 0.0, rope = 0.0;
  ASSERT_EQ(MoorDyn_GetLineFairTen(MoorDyn_GetLine(system, 1), &chain), MOORDYN_SUCCESS);
  ASSERT_EQ(MoorDyn_GetLineFairTen(MoorDyn_GetLine(system, 2), &rope), MOORDYN_SUCCESS);
  EXPECT_GT(chain, 20.0 * rope);
  EXPECT_EQ(MoorDyn_Close(system), MOORDYN_SUCCESS);
}

TEST(MoorDynApi, TripodRunsAsInMoorDynsOwnTest) {
  // MoorDyn's tests/tripod.cpp: Init without coupled points, then 3 s in steps of 0.1 s. Free point 3 joins
  // four deck lines (a float's tether and three bridles); every one of their ends stays at it and the lines'
  // pulls on it balance (it has no body of its own).
  const std::string deck = std::string(tangle::test::kTestDataDir) + "/moordyn/tripod.txt";
  MoorDyn system = MoorDyn_Create(deck.c_str());
  ASSERT_NE(system, nullptr);
  ASSERT_EQ(MoorDyn_Init(system, nullptr, nullptr), MOORDYN_SUCCESS);
  double t = 0.0;
  for (int i = 0; i < 30; ++i) {
    double dt = 0.1;
    ASSERT_EQ(MoorDyn_Step(system, nullptr, nullptr, nullptr, &t, &dt), MOORDYN_SUCCESS) << "step " << i;
  }
  EXPECT_NEAR(t, 3.0, 1e-9);
  double point[3], end[3], force[3];
  ASSERT_EQ(MoorDyn_GetPointPos(MoorDyn_GetPoint(system, 3), point), MOORDYN_SUCCESS);
  double largest = 0.0;
  for (const int id : {2, 3, 6, 9}) {  // each starts (node 0) at point 3
    MoorDynLine line = MoorDyn_GetLine(system, static_cast<unsigned int>(id));
    ASSERT_EQ(MoorDyn_GetLineNodePos(line, 0, end), MOORDYN_SUCCESS);
    const double gap[3] = {end[0] - point[0], end[1] - point[1], end[2] - point[2]};
    EXPECT_LT(norm(gap), 1e-4) << "line " << id;  // the ties stretch by micrometres under ~100 N
    double tension = 0.0;
    ASSERT_EQ(MoorDyn_GetLineNodeTen(line, 0, end), MOORDYN_SUCCESS);
    tension = norm(end);
    largest = std::max(largest, tension);
  }
  EXPECT_GT(largest, 10.0);
  ASSERT_EQ(MoorDyn_GetPointForce(MoorDyn_GetPoint(system, 3), force), MOORDYN_SUCCESS);
  EXPECT_LT(norm(force), 0.02 * largest);
  // The float (free point 2 at the top of line 1) floats: it reaches above the still water level.
  ASSERT_EQ(MoorDyn_GetPointPos(MoorDyn_GetPoint(system, 2), point), MOORDYN_SUCCESS);
  EXPECT_GT(point[2], 0.0);
  EXPECT_EQ(MoorDyn_Close(system), MOORDYN_SUCCESS);
}

TEST(MoorDynApi, OldApiHoldsOneSystem) {
  double x[3] = {0, 0, 0}, xd[3] = {0, 0, 0}, f[3], t = 0.0, dt = 0.1;
  EXPECT_EQ(MoorDynStep(x, xd, f, &t, &dt), MOORDYN_INVALID_VALUE);  // no system yet
  EXPECT_EQ(GetFairTen(1), -1.0);
  ASSERT_EQ(MoorDynInit(x, xd, deckPath().c_str()), MOORDYN_SUCCESS);
  EXPECT_GT(GetFairTen(1), 1e5);
  EXPECT_EQ(GetFairTen(2), -1.0);
  ASSERT_EQ(MoorDynStep(x, xd, f, &t, &dt), MOORDYN_SUCCESS);
  EXPECT_NEAR(t, 0.1, 1e-12);
  double pos[3];
  ASSERT_EQ(GetNodePos(1, 41, pos), MOORDYN_SUCCESS);
  EXPECT_NEAR(norm(pos), 0.0, 1e-9);
  EXPECT_EQ(MoorDynClose(), MOORDYN_SUCCESS);
  EXPECT_EQ(MoorDynClose(), MOORDYN_INVALID_VALUE);
  EXPECT_EQ(MoorDynInit(x, xd, "/nonexistent/tangle/deck.txt"), MOORDYN_UNHANDLED_ERROR);
}

// MoorDyn's tests/rods.cpp through the C API: the rod of RodHanging.txt stays level and centred, and the
// buoyant free rod of rod_tests/AddedMass.txt (no line) rises from rest at a = (rho V - M) g / (M + Ca rho
// V), checked as MoorDyn's test does at its 0.1 s steps until z > -1 (MoorDyn allows 1e-8 relative; tangle
// 1e-6 m, its Newton tolerance: MoorDynRodsTest).
TEST(MoorDynApi, RodsAnswerAsMoorDynsRodTests) {
  const std::string dir = std::string(tangle::test::kTestDataDir) + "/moordyn/";
  MoorDyn hanging = MoorDyn_Create((dir + "RodHanging.txt").c_str());
  ASSERT_NE(hanging, nullptr);
  unsigned int n = 0;
  EXPECT_EQ(MoorDyn_GetNumberRods(hanging, &n), MOORDYN_SUCCESS);
  EXPECT_EQ(n, 1u);
  EXPECT_EQ(MoorDyn_GetRod(hanging, 2), nullptr);
  MoorDynRod rod = MoorDyn_GetRod(hanging, 1);
  ASSERT_NE(rod, nullptr);
  int id = 0, type = 7;
  EXPECT_EQ(MoorDyn_GetRodID(rod, &id), MOORDYN_SUCCESS);
  EXPECT_EQ(id, 1);
  EXPECT_EQ(MoorDyn_GetRodType(rod, &type), MOORDYN_SUCCESS);
  EXPECT_EQ(type, 0);  // free
  EXPECT_EQ(MoorDyn_GetRodN(rod, &n), MOORDYN_SUCCESS);
  EXPECT_EQ(n, 1u);
  EXPECT_EQ(MoorDyn_GetRodNumberNodes(rod, &n), MOORDYN_SUCCESS);
  EXPECT_EQ(n, 2u);
  double a[3], b[3];
  EXPECT_EQ(MoorDyn_GetRodNodePos(rod, 2, a), MOORDYN_INVALID_VALUE);
  ASSERT_EQ(MoorDyn_Init(hanging, nullptr, nullptr), MOORDYN_SUCCESS);
  ASSERT_EQ(MoorDyn_GetRodNodePos(rod, 0, a), MOORDYN_SUCCESS);
  ASSERT_EQ(MoorDyn_GetRodNodePos(rod, 1, b), MOORDYN_SUCCESS);
  EXPECT_NEAR(a[0], -10.0, 1e-3);
  EXPECT_NEAR(b[0], 10.0, 1e-3);
  EXPECT_NEAR(a[2], b[2], 1e-6);
  EXPECT_LT(a[2], -75.0);  // it hangs lower than the deck puts it
  double force[6];
  EXPECT_EQ(MoorDyn_GetRodForce(rod, force), MOORDYN_NON_IMPLEMENTED);
  EXPECT_EQ(MoorDyn_Close(hanging), MOORDYN_SUCCESS);

  MoorDyn rising = MoorDyn_Create((dir + "rod_AddedMass.txt").c_str());
  ASSERT_NE(rising, nullptr);
  ASSERT_EQ(MoorDyn_Init(rising, nullptr, nullptr), MOORDYN_SUCCESS);
  rod = MoorDyn_GetRod(rising, 1);
  ASSERT_NE(rod, nullptr);
  const double rho = 1025.0, area = 3.141592653589793 / 4.0 * 0.5 * 0.5, mass = 100.0, g = 9.80665;
  const double acceleration = (rho * area - mass) * g / (mass + rho * area);
  double t = 0.0, dt = 0.1;
  int steps = 0;
  while (t < 2.5) {
    ASSERT_EQ(MoorDyn_Step(rising, nullptr, nullptr, nullptr, &t, &dt), MOORDYN_SUCCESS);
    ++steps;
    const double expected = -10.0 + 0.5 * acceleration * t * t;
    ASSERT_EQ(MoorDyn_GetRodN(rod, &n), MOORDYN_SUCCESS);
    for (unsigned int i = 0; i <= n; ++i) {
      ASSERT_EQ(MoorDyn_GetRodNodePos(rod, i, a), MOORDYN_SUCCESS);
      EXPECT_NEAR(a[2], expected, 1e-6) << "node " << i << " at t = " << t;
    }
    if (expected > -1.0) break;
  }
  EXPECT_GE(steps, 20);
  EXPECT_EQ(MoorDyn_Close(rising), MOORDYN_SUCCESS);
}

// MoorDyn's riser.txt (tests/test_complex_ic.py runs it 10 s): a free body (29.5 kg, 0.014 m^3) with a clamp
// rod, two zero-length connector rods and a coupled top. Held at rest, the dynamics stays at the static
// equilibrium: the top force after 10 s of 0.05 s host steps equals MoorDyn_Init's to 1e-4 relative (it
// stopped at 1.08 s before the links' round-off was in the tolerance at the body, docs/theory.md 8.2).
TEST(MoorDynApi, ABodyDeckStaysAtRestInItsDynamics) {
  MoorDyn system = MoorDyn_Create((std::string(tangle::test::kTestDataDir) + "/moordyn/riser.txt").c_str());
  ASSERT_NE(system, nullptr);
  unsigned int n = 0;
  EXPECT_EQ(MoorDyn_GetNumberBodies(system, &n), MOORDYN_SUCCESS);
  EXPECT_EQ(n, 1u);
  EXPECT_EQ(MoorDyn_GetNumberRods(system, &n), MOORDYN_SUCCESS);
  EXPECT_EQ(n, 3u);
  ASSERT_EQ(MoorDyn_NCoupledDOF(system, &n), MOORDYN_SUCCESS);
  ASSERT_EQ(n, 3u);
  double x[3] = {0.0, 0.0, -63.6}, v[3] = {0.0, 0.0, 0.0}, f0[3], f[3];
  ASSERT_EQ(MoorDyn_Init(system, x, v), MOORDYN_SUCCESS);
  double t = 0.0, dt = 0.05;
  ASSERT_EQ(MoorDyn_Step(system, x, v, f0, &t, &dt), MOORDYN_SUCCESS);
  while (t < 10.0 - 1e-9) ASSERT_EQ(MoorDyn_Step(system, x, v, f, &t, &dt), MOORDYN_SUCCESS) << "t = " << t;
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(f[k], f0[k], 1e-4 * norm(f0)) << "component " << k;
  EXPECT_GT(norm(f0), 1e4);  // the riser's weight on its top
  EXPECT_EQ(MoorDyn_Close(system), MOORDYN_SUCCESS);
}

// Bodies (Body.h): riser.txt's free body 1 (29.5 kg, at (452, 0, -313)) is a free vessel of the converted
// model whose reference point is the centre of gravity of the body and its points. The body's own reference
// point, which the functions report, must coincide with point 3 (on Body1 at offset 0) and carry the clamp
// rod's end A at body offset (0.1, 0, 0) through the reported attitude: three routes (the point map, the
// rod's line end, the body state) to the same place. The point and the rod's end are line end nodes tied to
// the vessel by links of 100 x their end element's EA / h (the vessel end's stiffness), which stretch by
// tension / stiffness (2 um here): 1e-5 m.
TEST(MoorDynApi, BodiesAnswerWithTheirReferencePointAndAttitude) {
  MoorDyn system = MoorDyn_Create((std::string(tangle::test::kTestDataDir) + "/moordyn/riser.txt").c_str());
  ASSERT_NE(system, nullptr);
  MoorDynBody body = MoorDyn_GetBody(system, 1);
  ASSERT_NE(body, nullptr);
  EXPECT_EQ(MoorDyn_GetBody(system, 2), nullptr);
  int id = 0, type = 5;
  EXPECT_EQ(MoorDyn_GetBodyID(body, &id), MOORDYN_SUCCESS);
  EXPECT_EQ(id, 1);
  EXPECT_EQ(MoorDyn_GetBodyType(body, &type), MOORDYN_SUCCESS);
  EXPECT_EQ(type, 0);  // free
  double r[6], rd[6];
  ASSERT_EQ(MoorDyn_GetBodyState(body, r, rd), MOORDYN_SUCCESS);  // before MoorDyn_Init: the input file's
  EXPECT_DOUBLE_EQ(r[0], 452.0);
  EXPECT_DOUBLE_EQ(r[2], -313.0);
  double x[3] = {0.0, 0.0, -63.6}, v[3] = {0.0, 0.0, 0.0}, f[3];
  ASSERT_EQ(MoorDyn_Init(system, x, v), MOORDYN_SUCCESS);
  double t = 0.0, dt = 0.05;
  for (int step = 0; step <= 20; ++step) {
    if (step > 0) {
      x[0] = 0.5 * std::sin(0.5 * t);  // the top swayed, so that the body moves and turns
      v[0] = 0.25 * std::cos(0.5 * t);
      ASSERT_EQ(MoorDyn_Step(system, x, v, f, &t, &dt), MOORDYN_SUCCESS);
    }
    ASSERT_EQ(MoorDyn_GetBodyState(body, r, rd), MOORDYN_SUCCESS);
    double pos[3], ang[3], point[3], rodEnd[3];
    ASSERT_EQ(MoorDyn_GetBodyPos(body, pos), MOORDYN_SUCCESS);
    ASSERT_EQ(MoorDyn_GetBodyAngle(body, ang), MOORDYN_SUCCESS);
    ASSERT_EQ(MoorDyn_GetPointPos(MoorDyn_GetPoint(system, 3), point), MOORDYN_SUCCESS);
    ASSERT_EQ(MoorDyn_GetRodNodePos(MoorDyn_GetRod(system, 1), 0, rodEnd), MOORDYN_SUCCESS);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(pos[k], r[k]);
      EXPECT_EQ(ang[k], r[3 + k]);
      EXPECT_NEAR(pos[k], point[k], 1e-5) << "step " << step << " component " << k;
    }
    // R = Rx(a) Ry(b) Rz(c); its first column R e_x = (cb cc, ca sc + sa sb cc, sa sc - ca sb cc).
    const double ca = std::cos(r[3]), sa = std::sin(r[3]), cb = std::cos(r[4]), sb = std::sin(r[4]),
                 cc = std::cos(r[5]), sc = std::sin(r[5]);
    const double ex[3] = {cb * cc, ca * sc + sa * sb * cc, sa * sc - ca * sb * cc};
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(rodEnd[k], pos[k] + 0.1 * ex[k], 1e-5) << "step " << step << " component " << k;
  }
  EXPECT_GT(std::abs(r[0] - 452.0), 1e-3);  // it did move
  EXPECT_GT(std::abs(r[4]), 0.1);  // pitched (0.36 rad): the rod-end check of the attitude is not vacuous
  double f6[6];
  EXPECT_EQ(MoorDyn_GetBodyForce(body, f6), MOORDYN_NON_IMPLEMENTED);
  EXPECT_EQ(MoorDyn_Close(system), MOORDYN_SUCCESS);
}

// A coupled body (Body.h): the host's 6 DOFs move its two fairleads rigidly. The same fairleads as two
// coupled points, moved by the host to where the body puts them, are the reference: the lines see the same
// motion, so the body's force is the sum of the points' forces and its moment their moments about its
// reference point, and its points are where the reference's are (1e-9 m). The two runs' inputs differ at
// round-off (the rotation evaluated two ways), so each step's Newton iteration, converged to the dynamics'
// tolerance, may end a few ulps of the input apart: 1e-6 of the force allowed (5e-9 seen). The motion: a
// surge of 0.5 m and a yaw of 0.05 rad at 10 s, with a small roll, so that every component of the rotation
// counts.
TEST(MoorDynApi, CoupledBodyMovesItsPointsAndReturnsTheirForceAndMoment) {
  const std::string dir = std::string(tangle::test::kTestDataDir) + "/moordyn/";
  MoorDyn body = MoorDyn_Create((dir + "coupled_body.txt").c_str());
  MoorDyn points = MoorDyn_Create((dir + "coupled_body_points.txt").c_str());
  ASSERT_NE(body, nullptr);
  ASSERT_NE(points, nullptr);
  unsigned int n = 0;
  ASSERT_EQ(MoorDyn_NCoupledDOF(body, &n), MOORDYN_SUCCESS);
  ASSERT_EQ(n, 6u);
  int type = 5;
  ASSERT_EQ(MoorDyn_GetBodyType(MoorDyn_GetBody(body, 1), &type), MOORDYN_SUCCESS);
  EXPECT_EQ(type, -1);  // coupled
  const double omega = 2.0 * std::numbers::pi / 10.0;
  const auto motion = [&](double t, double r[6], double rd[6]) {
    r[0] = 0.5 * std::sin(omega * t), rd[0] = 0.5 * omega * std::cos(omega * t);
    r[1] = 0.0, rd[1] = 0.0;
    r[2] = -5.0, rd[2] = 0.0;
    r[3] = 0.01 * std::sin(omega * t), rd[3] = 0.01 * omega * std::cos(omega * t);
    r[4] = 0.0, rd[4] = 0.0;
    r[5] = 0.05 * std::sin(omega * t), rd[5] = 0.05 * omega * std::cos(omega * t);
  };
  // The fairleads where the body puts them: X + Rx(a) Rz(c) (0, +-10, 0) (no pitch), and their velocities
  // Xd + w x arm, w = (ad, 0, cd) (the angle rates as the angular velocity, as MoorDyn).
  const auto fairleads = [&](const double r[6], const double rd[6], double x[6], double xd[6]) {
    for (int k = 0; k < 2; ++k) {
      const double y = k == 0 ? 10.0 : -10.0;
      const double ca = std::cos(r[3]), sa = std::sin(r[3]), cc = std::cos(r[5]), sc = std::sin(r[5]);
      const double arm[3] = {-sc * y, ca * cc * y, sa * cc * y};  // Rx(a) Rz(c) (0, y, 0)
      const double w[3] = {rd[3], rd[4], rd[5]};
      const double wxa[3] = {w[1] * arm[2] - w[2] * arm[1], w[2] * arm[0] - w[0] * arm[2],
                             w[0] * arm[1] - w[1] * arm[0]};
      for (int i = 0; i < 3; ++i) {
        x[3 * k + i] = r[i] + arm[i];
        xd[3 * k + i] = rd[i] + wxa[i];
      }
    }
  };
  double r[6], rd[6], x[6], xd[6], fb[6], fp[6];
  motion(0.0, r, rd);
  fairleads(r, rd, x, xd);
  ASSERT_EQ(MoorDyn_Init(body, r, rd), MOORDYN_SUCCESS);
  ASSERT_EQ(MoorDyn_Init(points, x, xd), MOORDYN_SUCCESS);
  double tb = 0.0, tp = 0.0, dt = 0.05;
  double largestMoment = 0.0;
  for (int step = 0; step < 100; ++step) {
    motion(tb, r, rd);
    fairleads(r, rd, x, xd);
    // Over a step the body's points move along the chord to where its pose puts them at the step's end.
    double r1[6], x1[6], unused[6];
    for (int i = 0; i < 6; ++i) r1[i] = r[i] + rd[i] * dt;
    fairleads(r1, rd, x1, unused);
    for (int i = 0; i < 6; ++i) xd[i] = (x1[i] - x[i]) / dt;
    ASSERT_EQ(MoorDyn_Step(body, r, rd, fb, &tb, &dt), MOORDYN_SUCCESS);
    ASSERT_EQ(MoorDyn_Step(points, x, xd, fp, &tp, &dt), MOORDYN_SUCCESS);
    double p3[3], p4[3], q3[3], q4[3];
    ASSERT_EQ(MoorDyn_GetPointPos(MoorDyn_GetPoint(points, 3), p3), MOORDYN_SUCCESS);
    ASSERT_EQ(MoorDyn_GetPointPos(MoorDyn_GetPoint(points, 4), p4), MOORDYN_SUCCESS);
    ASSERT_EQ(MoorDyn_GetPointPos(MoorDyn_GetPoint(body, 3), q3), MOORDYN_SUCCESS);
    ASSERT_EQ(MoorDyn_GetPointPos(MoorDyn_GetPoint(body, 4), q4), MOORDYN_SUCCESS);
    double reference[3];  // the body's reference point at the end of the step (its motion is linear over it)
    for (int i = 0; i < 3; ++i) reference[i] = r[i] + rd[i] * dt;
    const double scale = std::max(norm(fp), norm(fp + 3));
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(q3[i], x1[i], 1e-9) << "step " << step;  // on the body at the step's end
      EXPECT_NEAR(q3[i], p3[i], 1e-9) << "step " << step;
      EXPECT_NEAR(q4[i], p4[i], 1e-9) << "step " << step;
      EXPECT_NEAR(fb[i], fp[i] + fp[3 + i], 1e-6 * scale) << "step " << step << " force " << i;
    }
    const double a3[3] = {p3[0] - reference[0], p3[1] - reference[1], p3[2] - reference[2]};
    const double a4[3] = {p4[0] - reference[0], p4[1] - reference[1], p4[2] - reference[2]};
    const double moment[3] = {a3[1] * fp[2] - a3[2] * fp[1] + a4[1] * fp[5] - a4[2] * fp[4],
                              a3[2] * fp[0] - a3[0] * fp[2] + a4[2] * fp[3] - a4[0] * fp[5],
                              a3[0] * fp[1] - a3[1] * fp[0] + a4[0] * fp[4] - a4[1] * fp[3]};
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(fb[3 + i], moment[i], 1e-6 * 10.0 * scale) << "step " << step << " moment " << i;
    largestMoment = std::max(largestMoment, std::abs(fb[5]));
  }
  EXPECT_GT(largestMoment, 1e4);  // the yaw loads it: the moment check is not vacuous
  double state[6], rates[6];
  ASSERT_EQ(MoorDyn_GetBodyState(MoorDyn_GetBody(body, 1), state, rates), MOORDYN_SUCCESS);
  EXPECT_NEAR(state[5], r[5] + rd[5] * dt, 1e-12);  // the host's yaw at the end of the last step
  EXPECT_EQ(MoorDyn_Close(body), MOORDYN_SUCCESS);
  EXPECT_EQ(MoorDyn_Close(points), MOORDYN_SUCCESS);
  // A body whose host gives only its translation (CoupledPinned: its rotation solved) carries its mass at the
  // pin: one whose mass is off its reference point is refused by name.
  std::string deck = readDeck(dir + "coupled_body.txt");
  const std::string row = "1    Coupled     0.0    0.0    -5.0   0      0      0      0      0";
  ASSERT_NE(deck.find(row), std::string::npos);
  deck.replace(deck.find(row), row.size(),
               "1    CoupledPinned     0.0    0.0    -5.0   0      0      0      1000      1");
  EXPECT_EQ(createFromText(deck, "tangle-coupled-pinned-body.txt"), nullptr);
}

// The points on a Coupled body load it with their own mass, volume and drag, as MoorDyn's Body::doRHS sums
// its points' Point::getNetForceAndMass (MoorDyn v2.7.1): coupled_body.txt with its point 3 (a line's end)
// given 5000 kg, 2 m^3, CdA 1.5 m^2, Ca 1 and a point 5 at (5, 0, -2) on the body with no line (2000 kg, 0.5
// m^3, CdA 1, Ca 0.5), against the deck as it is, both moved alike by the host. The lines see the same
// motion, so the difference of the forces returned is the points' loads alone: (rho V - m) g upward, drag
// 1/2 rho CdA |v| v against each point's velocity v = v_ref + w x r in still water, and -(m + rho V Ca) a
// with a = a_ref + alpha x r + w x (w x r), the accelerations the change of the host's velocities over its
// step (MoorDyn's MoorDyn::Step); the moment their arms' (MoorDyn leaves out the centripetal term's moment,
// tangle does not). 1e-9 relative: the same sums. Until 2026-12-06 the points' loads were dropped, the
// points' velocities read 0 and MoorDyn_GetBodyForce read 0 after MoorDyn_Init.
TEST(MoorDynApi, PointsOnACoupledBodyAddTheirWeightDragAndInertia) {
  const std::string dir = std::string(tangle::test::kTestDataDir) + "/moordyn/";
  std::string deck = readDeck(dir + "coupled_body.txt");
  const std::string row3 = "3     Body1       0.0     10.0     0.0     0      0       0      0";
  const std::string row4 = "4     Body1       0.0    -10.0     0.0     0      0       0      0";
  ASSERT_NE(deck.find(row3), std::string::npos);
  ASSERT_NE(deck.find(row4), std::string::npos);
  deck.replace(deck.find(row3), row3.size(),
               "3     Body1       0.0     10.0     0.0     5000   2       1.5    1");
  deck.insert(deck.find(row4) + row4.size(),
              "\n5     Body1       5.0     0.0      -2.0    2000   0.5     1.0    0.5");
  MoorDyn plain = MoorDyn_Create((dir + "coupled_body.txt").c_str());
  MoorDyn heavy = createFromText(deck, "tangle-coupled-body-masses.txt");
  ASSERT_NE(plain, nullptr);
  ASSERT_NE(heavy, nullptr);
  using V = std::array<double, 3>;
  const auto cross = [](const V& a, const V& b) {
    return V{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  const auto plus = [](V a, const V& b, double k = 1.0) {
    for (int i = 0; i < 3; ++i) a[i] += k * b[i];
    return a;
  };
  const double rho = 1025.0, g = 9.81;
  struct Lump {
    V offset;
    double mass, volume, cda, ca;
  };
  const Lump lumps[2] = {{{0.0, 10.0, 0.0}, 5000.0, 2.0, 1.5, 1.0},
                         {{5.0, 0.0, -2.0}, 2000.0, 0.5, 1.0, 0.5}};
  // The arm R offset of a lump on a body at MoorDyn's XYZ Euler angles: R = Rx(a) Ry(b) Rz(c).
  const auto turned = [](const V& angles, const V& offset) {
    const double ca = std::cos(angles[0]), sa = std::sin(angles[0]), cb = std::cos(angles[1]);
    const double sb = std::sin(angles[1]), cc = std::cos(angles[2]), sc = std::sin(angles[2]);
    const double rot[3][3] = {{cb * cc, -cb * sc, sb},
                              {sa * sb * cc + ca * sc, -sa * sb * sc + ca * cc, -sa * cb},
                              {-ca * sb * cc + sa * sc, ca * sb * sc + sa * cc, ca * cb}};
    V arm{};
    for (int i = 0; i < 3; ++i)
      arm[i] = rot[i][0] * offset[0] + rot[i][1] * offset[1] + rot[i][2] * offset[2];
    return arm;
  };
  // The loads about the reference point of the lumps on a body at `angles` with velocity v, angular velocity
  // w (the angles' rates, as MoorDyn), acceleration a and angular acceleration alpha.
  const auto loads = [&](const V& angles, const V& v, const V& w, const V& a, const V& alpha) {
    std::array<double, 6> out{};
    for (const Lump& l : lumps) {
      const V arm = turned(angles, l.offset);
      const V velocity = plus(v, cross(w, arm));
      const V acceleration = plus(plus(a, cross(alpha, arm)), cross(w, cross(w, arm)));
      const double speed = norm(velocity.data());
      V force{0.0, 0.0, (rho * l.volume - l.mass) * g};
      force = plus(force, velocity, -0.5 * rho * l.cda * speed);
      force = plus(force, acceleration, -(l.mass + rho * l.volume * l.ca));
      const V moment = cross(arm, force);
      for (int i = 0; i < 3; ++i) out[i] += force[i], out[3 + i] += moment[i];
    }
    return out;
  };
  double r[6] = {0.0, 0.0, -5.0, 0.0, 0.0, 0.0}, rd[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  ASSERT_EQ(MoorDyn_Init(plain, r, rd), MOORDYN_SUCCESS);
  ASSERT_EQ(MoorDyn_Init(heavy, r, rd), MOORDYN_SUCCESS);
  // After MoorDyn_Init, at rest: the lines' forces and the lumps' weight and buoyancy.
  double fPlain[6], fHeavy[6];
  ASSERT_EQ(MoorDyn_GetBodyForce(MoorDyn_GetBody(plain, 1), fPlain), MOORDYN_SUCCESS);
  ASSERT_EQ(MoorDyn_GetBodyForce(MoorDyn_GetBody(heavy, 1), fHeavy), MOORDYN_SUCCESS);
  EXPECT_GT(norm(fPlain), 1e5);  // the chains' pull, not 0
  const V zero{0.0, 0.0, 0.0};
  std::array<double, 6> expected = loads(zero, zero, zero, zero, zero);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(fHeavy[i] - fPlain[i], expected[i], 1e-9 * norm(fPlain)) << i;
  // Two host steps of 0.1 s from rest, every DOF moving (roll and pitch rates too, so that the centripetal
  // term is not along the arm).
  double t = 0.0, dt = 0.1, tHeavy = 0.0;
  const double rates[2][6] = {{1.0, 0.0, 0.2, 0.05, -0.03, 0.1}, {1.5, -0.4, 0.1, 0.12, 0.08, 0.3}};
  double previous[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  for (int step = 0; step < 2; ++step) {
    for (int i = 0; i < 6; ++i) rd[i] = rates[step][i];
    ASSERT_EQ(MoorDyn_Step(plain, r, rd, fPlain, &t, &dt), MOORDYN_SUCCESS);
    ASSERT_EQ(MoorDyn_Step(heavy, r, rd, fHeavy, &tHeavy, &dt), MOORDYN_SUCCESS);
    // The host's pose at the step's end (linear over it), its velocities and their change over the step.
    const V angles{r[3] + rd[3] * dt, r[4] + rd[4] * dt, r[5] + rd[5] * dt};
    const V v{rd[0], rd[1], rd[2]}, w{rd[3], rd[4], rd[5]};
    const V a{(rd[0] - previous[0]) / dt, (rd[1] - previous[1]) / dt, (rd[2] - previous[2]) / dt};
    const V alpha{(rd[3] - previous[3]) / dt, (rd[4] - previous[4]) / dt, (rd[5] - previous[5]) / dt};
    expected = loads(angles, v, w, a, alpha);
    for (int i = 0; i < 6; ++i)
      EXPECT_NEAR(fHeavy[i] - fPlain[i], expected[i], 1e-9 * norm(fPlain)) << "step " << step << " " << i;
    double reported[6];
    ASSERT_EQ(MoorDyn_GetBodyForce(MoorDyn_GetBody(heavy, 1), reported), MOORDYN_SUCCESS);
    for (int i = 0; i < 6; ++i) EXPECT_EQ(reported[i], fHeavy[i]);
    // The points' velocities: v + w x r, the line's point and the free lump alike (MoorDyn's
    // Body::setDependentStates).
    for (int p : {3, 5}) {
      const V arm = turned(angles, lumps[p == 3 ? 0 : 1].offset);
      const V velocity = plus(v, cross(w, arm));
      double pv[3], x[3];
      ASSERT_EQ(MoorDyn_GetPointVel(MoorDyn_GetPoint(heavy, static_cast<unsigned int>(p)), pv),
                MOORDYN_SUCCESS);
      ASSERT_EQ(MoorDyn_GetPointPos(MoorDyn_GetPoint(heavy, static_cast<unsigned int>(p)), x),
                MOORDYN_SUCCESS);
      for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(pv[i], velocity[i], 1e-12) << "point " << p << " step " << step;
        EXPECT_NEAR(x[i], r[i] + rd[i] * dt + arm[i], 1e-12) << "point " << p << " step " << step;
      }
    }
    for (int i = 0; i < 6; ++i) previous[i] = rd[i];
    for (int i = 0; i < 6; ++i) r[i] += rd[i] * dt;
  }
  EXPECT_EQ(MoorDyn_Close(plain), MOORDYN_SUCCESS);
  EXPECT_EQ(MoorDyn_Close(heavy), MOORDYN_SUCCESS);
}

// A point on a free body that no line holds is where the body puts it: MoorDyn's Body::setDependentStates,
// reference point + R r with R = Rx Ry Rz of MoorDyn_GetBodyState's angles, velocity v + w x (R r).
// BodiesAndRods.dat (a free body held by three nylon lines) with a point 11 at (5, 3, -2) on the body and no
// line, at t = 0 and after 1 s of dynamics. Until 2026-12-06 its body-frame offset was returned as its
// position.
TEST(MoorDynApi, APointOnAFreeBodyWithoutALineMovesWithTheBody) {
  std::string deck = readDeck(std::string(tangle::test::kTestDataDir) + "/moordyn/BodiesAndRods.dat");
  const std::string row = "10        Body1       0      0        0         0        0         0     0";
  ASSERT_NE(deck.find(row), std::string::npos);
  deck.insert(deck.find(row) + row.size(),
              "\n11        Body1       5.0    3.0     -2.0       0        0         0     0");
  MoorDyn system = createFromText(deck, "tangle-free-body-point.dat");
  ASSERT_NE(system, nullptr);
  ASSERT_EQ(MoorDyn_Init(system, nullptr, nullptr), MOORDYN_SUCCESS);
  double t = 0.0, dt = 0.05;
  for (int step = 0; step <= 20; ++step) {
    if (step > 0) {
      ASSERT_EQ(MoorDyn_Step(system, nullptr, nullptr, nullptr, &t, &dt), MOORDYN_SUCCESS);
    }
    if (step != 0 && step != 20) continue;
    double r[6], v[6], x[3], xd[3];
    ASSERT_EQ(MoorDyn_GetBodyState(MoorDyn_GetBody(system, 1), r, v), MOORDYN_SUCCESS);
    ASSERT_EQ(MoorDyn_GetPointPos(MoorDyn_GetPoint(system, 11), x), MOORDYN_SUCCESS);
    ASSERT_EQ(MoorDyn_GetPointVel(MoorDyn_GetPoint(system, 11), xd), MOORDYN_SUCCESS);
    const double ca = std::cos(r[3]), sa = std::sin(r[3]), cb = std::cos(r[4]), sb = std::sin(r[4]);
    const double cc = std::cos(r[5]), sc = std::sin(r[5]);
    // Rx(a) Ry(b) Rz(c), row by row.
    const double rot[3][3] = {{cb * cc, -cb * sc, sb},
                              {sa * sb * cc + ca * sc, -sa * sb * sc + ca * cc, -sa * cb},
                              {-ca * sb * cc + sa * sc, ca * sb * sc + sa * cc, ca * cb}};
    const double offset[3] = {5.0, 3.0, -2.0};
    double arm[3];
    for (int i = 0; i < 3; ++i)
      arm[i] = rot[i][0] * offset[0] + rot[i][1] * offset[1] + rot[i][2] * offset[2];
    const double wxa[3] = {v[4] * arm[2] - v[5] * arm[1], v[5] * arm[0] - v[3] * arm[2],
                           v[3] * arm[1] - v[4] * arm[0]};
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(x[i], r[i] + arm[i], 1e-9) << "t " << t << " " << i;
      EXPECT_NEAR(xd[i], v[i] + wxa[i], 1e-9) << "t " << t << " " << i;
    }
  }
  EXPECT_EQ(MoorDyn_Close(system), MOORDYN_SUCCESS);
}

// A rod fixed to a fixed body is where the body puts it: BodiesAndRods.dat with its body made Fixed at
// (10, 5, 0) rolled 30 deg: rod 1's end B, (0, 0, 15) in the body's axes, is at (10, 5, 0) + Rx(30 deg) (0,
// 0, 15) = (10, -2.5, 12.990) before and after MoorDyn_Init (1e-9 m). Until 2026-12-06 its body-frame
// coordinates were returned, and given to a WaveKin 1 host as its kinematics points.
TEST(MoorDynApi, ARodOnAFixedBodyIsWhereTheBodyPutsIt) {
  std::string deck = readDeck(std::string(tangle::test::kTestDataDir) + "/moordyn/BodiesAndRods.dat");
  const std::string row = "1       free      0     0      0     0       0      0";
  ASSERT_NE(deck.find(row), std::string::npos);
  deck.replace(deck.find(row), row.size(), "1       fixed     10    5      0     30      0      0");
  MoorDyn system = createFromText(deck, "tangle-fixed-body-rod.dat");
  ASSERT_NE(system, nullptr);
  const double roll = 30.0 * std::numbers::pi / 180.0;
  const double expected[3] = {10.0, 5.0 - 15.0 * std::sin(roll), 15.0 * std::cos(roll)};
  MoorDynRod rod = MoorDyn_GetRod(system, 1);
  double b[3];
  ASSERT_EQ(MoorDyn_GetRodNodePos(rod, 3, b), MOORDYN_SUCCESS);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(b[k], expected[k], 1e-9) << "before Init, " << k;
  ASSERT_EQ(MoorDyn_Init(system, nullptr, nullptr), MOORDYN_SUCCESS);
  ASSERT_EQ(MoorDyn_GetRodNodePos(rod, 3, b), MOORDYN_SUCCESS);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(b[k], expected[k], 1e-9) << "after Init, " << k;
  EXPECT_EQ(MoorDyn_Close(system), MOORDYN_SUCCESS);
}

// WaveKin 1 with a rod: MoorDyn's points for the host's kinematics are the lines' nodes, then the rods'
// nodes, then the points, then the bodies with the ground body first (Waves::kinematicsForAllNodes):
// RodHanging.txt (two 45-segment ropes holding a one-segment free rod) has 2 x 46 + 2 + 2 + 1 = 97. A flow
// given across the rod at its two nodes alone reaches the rod (a tangle line): it swings with it. The old
// API's functions are the same (MoorDyn.cpp forwards them). Until 2026-12-06 the rod's nodes were left out
// (94 points) and the old API's functions did nothing.
TEST(MoorDynApi, ExternalWaveKinematicsReachTheRods) {
  std::string deck = readDeck(std::string(tangle::test::kTestDataDir) + "/moordyn/RodHanging.txt");
  const std::string options = "---------------------- OPTIONS";
  ASSERT_NE(deck.find(options), std::string::npos);
  const std::size_t next = deck.find('\n', deck.find(options));
  deck.insert(next + 1, "1             WaveKin              external wave kinematics\n");
  const std::string path = (std::filesystem::temp_directory_path() / "tangle-rod-wavekin.txt").string();
  std::ofstream(path) << deck;
  MoorDyn system = MoorDyn_Create(path.c_str());
  ASSERT_NE(system, nullptr);
  ASSERT_EQ(MoorDyn_Init(system, nullptr, nullptr), MOORDYN_SUCCESS);
  unsigned int n = 0;
  ASSERT_EQ(MoorDyn_ExternalWaveKinInit(system, &n), MOORDYN_SUCCESS);
  ASSERT_EQ(n, 97u);
  std::vector<double> r(3 * n);
  ASSERT_EQ(MoorDyn_ExternalWaveKinGetCoordinates(system, r.data()), MOORDYN_SUCCESS);
  MoorDynRod rod = MoorDyn_GetRod(system, 1);
  double a[3], b[3];
  ASSERT_EQ(MoorDyn_GetRodNodePos(rod, 0, a), MOORDYN_SUCCESS);
  ASSERT_EQ(MoorDyn_GetRodNodePos(rod, 1, b), MOORDYN_SUCCESS);
  for (int k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(r[3 * 92 + k], a[k]);
    EXPECT_DOUBLE_EQ(r[3 * 93 + k], b[k]);
    EXPECT_EQ(r[3 * 96 + k], 0.0);  // the ground body
  }
  std::vector<double> u(3 * n, 0.0), ud(3 * n, 0.0);
  u[3 * 92 + 1] = u[3 * 93 + 1] = 2.0;  // 2 m/s across the rod (along y) at its nodes only
  ASSERT_EQ(MoorDyn_ExternalWaveKinSet(system, u.data(), ud.data(), 0.0), MOORDYN_SUCCESS);
  double t = 0.0, dt = 0.05;
  for (int s = 0; s < 20; ++s)
    ASSERT_EQ(MoorDyn_Step(system, nullptr, nullptr, nullptr, &t, &dt), MOORDYN_SUCCESS);
  double moved[3];
  ASSERT_EQ(MoorDyn_GetRodNodePos(rod, 0, moved), MOORDYN_SUCCESS);
  EXPECT_GT(moved[1] - a[1], 0.1) << "the rod does not drift with the flow at its nodes";  // 0.46 m
  EXPECT_EQ(MoorDyn_Close(system), MOORDYN_SUCCESS);

  // The old API on the same deck.
  ASSERT_EQ(MoorDynInit(nullptr, nullptr, path.c_str()), MOORDYN_SUCCESS);
  std::filesystem::remove(path);
  ASSERT_EQ(externalWaveKinInit(), 97);
  std::vector<double> old(3 * 97, -1.0);
  getWaveKinCoordinates(old.data());
  for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(old[3 * 92 + k], r[3 * 92 + k]);
  setWaveKin(u.data(), ud.data(), 0.0);
  double f[1];
  t = 0.0;
  for (int s = 0; s < 20; ++s) ASSERT_EQ(MoorDynStep(nullptr, nullptr, f, &t, &dt), MOORDYN_SUCCESS);
  EXPECT_EQ(MoorDynClose(), MOORDYN_SUCCESS);
}

// A Coupled rod (6 DOFs: its end A and XYZ Euler angles turning the deck's axis, MoorDyn's Rod::COUPLED):
// MoorDyn's RodHanging.txt with its free rod made Coupled, the host swinging it in surge and yaw, against
// the same deck with two Coupled points in place of the rod's ends, moved along the same chords. The rod's
// ends and the line ends there end each step where the host's pose puts them (1e-9 m); the force is the
// points' sum and the moment theirs about end A (1e-6 relative: sums of the same numbers, as the coupled
// body's); MoorDyn_GetRodForce returns what MoorDyn_Step did.
TEST(MoorDynApi, CoupledRodMovesItsLinesEndsRigidlyAndReturnsTheirForceAndMoment) {
  const std::string dir = std::string(tangle::test::kTestDataDir) + "/moordyn/";
  const std::string original = readDeck(dir + "RodHanging.txt");
  const auto edited = [&](const std::vector<std::pair<std::string, std::string>>& edits, const char* name) {
    std::string deck = original;
    for (const auto& [from, to] : edits) {
      EXPECT_NE(deck.find(from), std::string::npos) << from;
      if (deck.find(from) != std::string::npos) deck.replace(deck.find(from), from.size(), to);
    }
    return createFromText(deck, name);
  };
  MoorDyn system = edited({{"1    rod       Free        -10", "1    rod       Coupled     -10"}},
                          "tangle-coupled-rod.txt");
  MoorDyn points = edited({{"1    rod       Free        -10   0     -75   10    0     -75  1       -", ""},
                           {"2     Fixed      450    0       0       0      0       0      0",
                            "2     Fixed      450    0       0       0      0       0      0\n"
                            "3     Coupled   -10     0     -75      0      0       0      0\n"
                            "4     Coupled    10     0     -75      0      0       0      0"},
                           {"R1A", "3  "},
                           {"R1B", "4  "}},
                          "tangle-coupled-rod-points.txt");
  ASSERT_NE(system, nullptr);
  ASSERT_NE(points, nullptr);
  unsigned int n = 0;
  ASSERT_EQ(MoorDyn_NCoupledDOF(system, &n), MOORDYN_SUCCESS);
  ASSERT_EQ(n, 6u);
  MoorDynRod rod = MoorDyn_GetRod(system, 1);
  ASSERT_NE(rod, nullptr);
  int type = 5;
  ASSERT_EQ(MoorDyn_GetRodType(rod, &type), MOORDYN_SUCCESS);
  EXPECT_EQ(type, -2);  // coupled
  const double omega = 2.0 * std::numbers::pi / 10.0;
  const auto motion = [&](double t, double r[6], double rd[6]) {
    for (int i = 0; i < 6; ++i) r[i] = rd[i] = 0.0;
    r[0] = -10.0 + 2.0 * std::sin(omega * t), rd[0] = 2.0 * omega * std::cos(omega * t);
    r[2] = -75.0;
    r[5] = 0.1 * std::sin(omega * t), rd[5] = 0.1 * omega * std::cos(omega * t);
  };
  // The rod's ends for pose r: A at r, B at r + Rz(yaw) (20, 0, 0).
  const auto ends = [](const double r[6], double x[6]) {
    for (int i = 0; i < 3; ++i) x[i] = r[i];
    x[3] = r[0] + 20.0 * std::cos(r[5]), x[4] = r[1] + 20.0 * std::sin(r[5]), x[5] = r[2];
  };
  double r[6], rd[6], x[6], xd[6], f[6], fp[6], g[6];
  motion(0.0, r, rd);
  ends(r, x);
  for (int i = 0; i < 3; ++i) xd[i] = rd[i];
  xd[3] = rd[0] - 20.0 * std::sin(r[5]) * rd[5], xd[4] = rd[1] + 20.0 * std::cos(r[5]) * rd[5], xd[5] = rd[2];
  ASSERT_EQ(MoorDyn_Init(system, r, rd), MOORDYN_SUCCESS);
  ASSERT_EQ(MoorDyn_Init(points, x, xd), MOORDYN_SUCCESS);
  MoorDynLine line2 = MoorDyn_GetLine(system, 2);
  double t = 0.0, tp = 0.0, dt = 0.05, largestMoment = 0.0;
  for (int step = 0; step < 100; ++step) {
    motion(t, r, rd);
    double r1[6], x1[6];
    for (int i = 0; i < 6; ++i) r1[i] = r[i] + rd[i] * dt;  // the host's pose at the step's end
    ends(r, x);
    ends(r1, x1);
    for (int i = 0; i < 6; ++i) xd[i] = (x1[i] - x[i]) / dt;
    ASSERT_EQ(MoorDyn_Step(system, r, rd, f, &t, &dt), MOORDYN_SUCCESS);
    ASSERT_EQ(MoorDyn_Step(points, x, xd, fp, &tp, &dt), MOORDYN_SUCCESS);
    double a0[3], b0[3], lb[3];
    ASSERT_EQ(MoorDyn_GetRodNodePos(rod, 0, a0), MOORDYN_SUCCESS);
    ASSERT_EQ(MoorDyn_GetRodNodePos(rod, 1, b0), MOORDYN_SUCCESS);
    ASSERT_EQ(MoorDyn_GetLineNodePos(line2, 45, lb), MOORDYN_SUCCESS);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(a0[i], x1[i], 1e-9) << "step " << step;
      EXPECT_NEAR(b0[i], x1[3 + i], 1e-9) << "step " << step;
      EXPECT_NEAR(lb[i], x1[3 + i], 1e-9) << "step " << step;
    }
    const double scale = std::max(norm(fp), norm(fp + 3));
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(f[i], fp[i] + fp[3 + i], 1e-6 * scale) << "step " << step << " force " << i;
    const double arm[3] = {x1[3] - x1[0], x1[4] - x1[1], x1[5] - x1[2]};
    const double* fb = fp + 3;
    const double moment[3] = {arm[1] * fb[2] - arm[2] * fb[1], arm[2] * fb[0] - arm[0] * fb[2],
                              arm[0] * fb[1] - arm[1] * fb[0]};
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(f[3 + i], moment[i], 1e-6 * 20.0 * scale) << "step " << step << " moment " << i;
    largestMoment = std::max(largestMoment, std::abs(f[4]));
  }
  EXPECT_GT(largestMoment, 1e4);  // the line's weight at end B: the moment check is not vacuous
  ASSERT_EQ(MoorDyn_GetRodForce(rod, g), MOORDYN_SUCCESS);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(g[i], f[i]);
  EXPECT_EQ(MoorDyn_Close(system), MOORDYN_SUCCESS);
  EXPECT_EQ(MoorDyn_Close(points), MOORDYN_SUCCESS);
}

/// Runs a host that moves a coupled-pinned object (3 DOFs at the front of the coupled vector; `counted` what
/// MoorDyn_NCoupledDOF says) from (0, 0, -5) with a constant acceleration `accel` along y from rest, at
/// the host's 0.01 s step, until two full swings (MoorDyn's tests/bodies.cpp, "Pinned body": the fourth
/// extremum of the swing angle after the first 30 steps). Returns the mean swing angle about x [rad]
/// (`angle` reads it after each step) and the mean force the host got [N].
struct SwingResult {
  double meanAngle = 0.0;
  double meanForce[3] = {0.0, 0.0, 0.0};
  int steps = 0;
};
template <typename Angle>
SwingResult swingUnderAcceleration(MoorDyn system, unsigned int counted, double accel, Angle&& angle) {
  SwingResult out;
  unsigned int n = 0;
  EXPECT_EQ(MoorDyn_NCoupledDOF(system, &n), MOORDYN_SUCCESS);
  EXPECT_EQ(n, counted);
  std::vector<double> x(n, 0.0), xd(n, 0.0), f(n, 0.0);
  x[2] = -5.0;
  EXPECT_EQ(MoorDyn_Init(system, x.data(), xd.data()), MOORDYN_SUCCESS);
  std::vector<double> roll;
  double t = 0.0, dt = 0.01;
  int extrema = 0;
  for (int i = 0; t < 50.0; ++i) {
    x[1] = 0.5 * accel * t * t;
    xd[1] = accel * t;
    if (MoorDyn_Step(system, x.data(), xd.data(), f.data(), &t, &dt) != MOORDYN_SUCCESS) {
      ADD_FAILURE() << "step " << i << " failed";
      return out;
    }
    roll.push_back(angle());
    for (int k = 0; k < 3; ++k) out.meanForce[k] += f[static_cast<std::size_t>(k)];
    const std::size_t j = roll.size() - 1;
    if (j >= 30 && (roll[j] - roll[j - 1]) * (roll[j - 1] - roll[j - 2]) < 0.0) ++extrema;
    if (extrema > 3) break;
  }
  out.steps = static_cast<int>(roll.size());
  for (double r : roll) out.meanAngle += r / static_cast<double>(roll.size());
  for (double& v : out.meanForce) v /= static_cast<double>(roll.size());
  return out;
}

// MoorDyn's own "Pinned body" test (tests/bodies.cpp, its deck tests/Mooring/body_tests/pinnedBody.txt): a
// massless CoupledPinned body holding a fixed 10 m rod of 50 t, in vacuum, its pin accelerated at 0.5 m/s^2:
// a pendulum on an accelerating cart, whose angle swings between 0 and 2 theta about theta = atan(-a / g).
// MoorDyn's tolerance on the mean roll: 0.001 rad. The mean force on the host over whole swings (from rest
// to an extremum, where the rod is at rest relative to the pin): momentum, -m (0, a, g), to 1 % (the window
// ends at the sample nearest the extremum, 0.01 s: the rod's relative momentum there is below 0.1 % of m a
// T).
TEST(MoorDynApi, PinnedBodySwingsAboutAtanOfItsAccelerationOverGravity) {
  const std::string dir = std::string(tangle::test::kTestDataDir) + "/moordyn/";
  MoorDyn system = MoorDyn_Create((dir + "pinnedBody.txt").c_str());
  ASSERT_NE(system, nullptr);
  MoorDynBody body = MoorDyn_GetBody(system, 1);
  ASSERT_NE(body, nullptr);
  int type = 5;
  ASSERT_EQ(MoorDyn_GetBodyType(body, &type), MOORDYN_SUCCESS);
  EXPECT_EQ(type, 2);  // coupled pinned
  const double accel = 0.5, g = 9.80665, mass = 5e3 * 10.0;
  const SwingResult r = swingUnderAcceleration(system, 6, accel, [&] {
    double q[6], qd[6];
    EXPECT_EQ(MoorDyn_GetBodyState(body, q, qd), MOORDYN_SUCCESS);
    return q[3];
  });
  const double theta = std::atan(-accel / g);
  EXPECT_GT(r.steps, 500);  // two swings of a 10 m rod 5 m below its pin: about 2 x 5.6 s
  EXPECT_NEAR(r.meanAngle, theta, 0.001);
  EXPECT_NEAR(r.meanForce[0], 0.0, 0.01 * mass * g);
  EXPECT_NEAR(r.meanForce[1], -mass * accel, 0.01 * mass * accel);
  EXPECT_NEAR(r.meanForce[2], -mass * g, 0.01 * mass * g);
  double f[6];
  ASSERT_EQ(MoorDyn_GetBodyForce(body, f), MOORDYN_SUCCESS);
  EXPECT_EQ(f[3], 0.0);  // a pinned body returns no moment
  // Its mass about the pin (the rod fixed to it, lumped on its 4 nodes as the deck's `mass: lumped`): the
  // total mass and its first moment exact (the rod's centre 10 m below the pin, along its current axis);
  // the moment of inertia within 2 % of the continuous rod's m (L^2 / 12 + d^2) + m D^2 / 16 (3 lumped
  // elements: +1.7 %).
  double m[6][6], q[6], qd[6];
  ASSERT_EQ(MoorDyn_GetBodyM(body, m), MOORDYN_SUCCESS);
  ASSERT_EQ(MoorDyn_GetBodyState(body, q, qd), MOORDYN_SUCCESS);
  const double vessel = 1e-3;  // the massless body's floor (a conversion note)
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(m[i][i], mass + vessel, 1e-9 * mass);
  // m[1][3]: the y force of a unit roll acceleration, -m z_c with z_c = -10 cos(roll) about the pin.
  EXPECT_NEAR(m[1][3], mass * 10.0 * std::cos(q[3]), 1e-6 * mass * 10.0);
  EXPECT_NEAR(m[3][1], m[1][3], 1e-9 * std::abs(m[1][3]));
  const double rollInertia = mass * (100.0 / 12.0 + 100.0) + mass * 4.0 / 16.0;
  EXPECT_NEAR(m[3][3], rollInertia, 0.02 * rollInertia);
  EXPECT_EQ(MoorDyn_Close(system), MOORDYN_SUCCESS);
}

// The same pendulum as a CoupledPinned rod (3 DOFs: its end A) from (0, 0, -5) to (0, 0, -15), no body:
// the same mean angle (MoorDyn's tolerance) and force; the angle from the rod's end nodes.
TEST(MoorDynApi, PinnedRodSwingsAboutAtanOfItsAccelerationOverGravity) {
  const std::string dir = std::string(tangle::test::kTestDataDir) + "/moordyn/";
  std::string deck = readDeck(dir + "pinnedBody.txt");
  const std::string bodyRow = "1     CoupledPinned    0.00    0.00  -5.00";
  const std::string rodRow = "1      Can     Body1         0     0     -5     0     0     -15     3";
  ASSERT_NE(deck.find(bodyRow), std::string::npos);
  ASSERT_NE(deck.find(rodRow), std::string::npos);
  deck.erase(deck.find(bodyRow), deck.find('\n', deck.find(bodyRow)) + 1 - deck.find(bodyRow));
  deck.replace(deck.find(rodRow), rodRow.size(),
               "1      Can     CoupledPinned 0     0     -5     0     0     -15     3");
  MoorDyn system = createFromText(deck, "tangle-pinned-rod.txt");
  ASSERT_NE(system, nullptr);
  MoorDynRod rod = MoorDyn_GetRod(system, 1);
  ASSERT_NE(rod, nullptr);
  int type = 5;
  ASSERT_EQ(MoorDyn_GetRodType(rod, &type), MOORDYN_SUCCESS);
  EXPECT_EQ(type, -1);  // coupled pinned
  const double accel = 0.5, g = 9.80665, mass = 5e3 * 10.0;
  const SwingResult r = swingUnderAcceleration(system, 3, accel, [&] {
    double a[3], b[3];
    EXPECT_EQ(MoorDyn_GetRodNodePos(rod, 0, a), MOORDYN_SUCCESS);
    EXPECT_EQ(MoorDyn_GetRodNodePos(rod, 3, b), MOORDYN_SUCCESS);
    return std::atan2(b[1] - a[1], a[2] - b[2]);  // Rx(phi) (0, 0, -1) = (0, sin phi, -cos phi)
  });
  EXPECT_GT(r.steps, 400);
  EXPECT_NEAR(r.meanAngle, std::atan(-accel / g), 0.001);
  EXPECT_NEAR(r.meanForce[1], -mass * accel, 0.01 * mass * accel);
  EXPECT_NEAR(r.meanForce[2], -mass * g, 0.01 * mass * g);
  double f[6];
  ASSERT_EQ(MoorDyn_GetRodForce(rod, f), MOORDYN_SUCCESS);
  EXPECT_LT(f[2], 0.0);
  // Its mass about end A: total and first moment exact (centre 5 m along the rod), inertia within 6 % of
  // m L^2 / 3 + m D^2 / 16 (3 lumped elements: +5.6 %).
  double m[6][6];
  ASSERT_EQ(MoorDyn_GetRodM(rod, m), MOORDYN_SUCCESS);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(m[i][i], mass, 1e-9 * mass);
  double a[3], b[3];
  ASSERT_EQ(MoorDyn_GetRodNodePos(rod, 0, a), MOORDYN_SUCCESS);
  ASSERT_EQ(MoorDyn_GetRodNodePos(rod, 3, b), MOORDYN_SUCCESS);
  EXPECT_NEAR(m[1][3], -mass * 0.5 * (b[2] - a[2]), 1e-6 * mass * 5.0);  // -m z_c, z_c from end A
  const double inertia = mass * 100.0 / 3.0 + mass * 4.0 / 16.0;
  EXPECT_NEAR(m[3][3], inertia, 0.06 * inertia);
  EXPECT_EQ(MoorDyn_Close(system), MOORDYN_SUCCESS);
}

}  // namespace
