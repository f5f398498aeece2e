/// @file MoorDynObjectsApi.cpp
/// The line, point, rod and body functions of the MoorDyn v2 C API (include/tangle-moordyn/Line.h, Point.h,
/// Rod.h, Body.h)
/// on capi::MoorDynSystem. Every function catches every exception (CApiBoundary.hpp) and returns a MOORDYN_*
/// code.

#include <string>

#include "MoorDyn2.h"
#include "tangle/capi/CApiBoundary.hpp"
#include "tangle/capi/MoorDynSystem.hpp"

namespace capi = tangle::capi;

namespace {

void put(const tangle::Vec3& v, double* out) {
  out[0] = v.x();
  out[1] = v.y();
  out[2] = v.z();
}

void put(const tangle::Vec6& v, double* out) {
  for (int k = 0; k < 6; ++k) out[k] = v[k];
}

void put(const tangle::Mat6& m, double out[6][6]) {
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) out[r][c] = m(r, c);
}

/// The guard of a per-node vector result: writes get(system, line, node) into out[3].
template <class Get>
int nodeVector(const char* function, MoorDynLine l, unsigned int i, double* out, Get get) {
  return capi::withLine(function, l, [&](capi::MoorDynSystem& s, int line) {
    capi::output(out, "the output array");
    put(get(s, line, i), out);
  });
}

/// The guard of a function tangle does not implement, for a line.
int lineNotImplemented(const char* function, MoorDynLine l, const char* why) {
  return capi::withLine(function, l, [&](capi::MoorDynSystem&, int) { capi::throwNotImplemented(why); });
}

int pointNotImplemented(const char* function, MoorDynPoint p, const char* why) {
  return capi::withPoint(function, p, [&](capi::MoorDynSystem&, int) { capi::throwNotImplemented(why); });
}

constexpr const char* kNoSplit =
    "tangle does not split the node forces by source (MoorDyn_GetLineNodeForce and MoorDyn_GetLineNodeTen "
    "are "
    "available)";

}  // namespace

extern "C" {

// Lines (Line.h).

int MoorDyn_GetLineID(MoorDynLine l, int* id) {
  return capi::withLine("MoorDyn_GetLineID", l, [&](capi::MoorDynSystem& s, int line) {
    capi::output(id, "id") = s.deckLine(line).id;
  });
}

int MoorDyn_GetLineN(MoorDynLine l, unsigned int* n) {
  return capi::withLine("MoorDyn_GetLineN", l, [&](capi::MoorDynSystem& s, int line) {
    capi::output(n, "n") = static_cast<unsigned int>(s.deckLine(line).segments);
  });
}

int MoorDyn_GetLineNumberNodes(MoorDynLine l, unsigned int* n) {
  return capi::withLine("MoorDyn_GetLineNumberNodes", l, [&](capi::MoorDynSystem& s, int line) {
    capi::output(n, "n") = static_cast<unsigned int>(s.deckLine(line).segments) + 1;
  });
}

int MoorDyn_GetLineUnstretchedLength(MoorDynLine l, double* ul) {
  return capi::withLine("MoorDyn_GetLineUnstretchedLength", l, [&](capi::MoorDynSystem& s, int line) {
    capi::output(ul, "ul") = s.deckLine(line).length;
  });
}

int MoorDyn_SetLineUnstretchedLength(MoorDynLine l, double /*ul*/) {
  return lineNotImplemented("MoorDyn_SetLineUnstretchedLength", l,
                            "tangle does not change a line's length during a run (no winches)");
}

int MoorDyn_SetLineUnstretchedLengthVel(MoorDynLine l, double /*v*/) {
  return lineNotImplemented("MoorDyn_SetLineUnstretchedLengthVel", l,
                            "tangle does not change a line's length during a run (no winches)");
}

int MoorDyn_IsLineConstantEA(MoorDynLine l, int* b) {
  return capi::withLine("MoorDyn_IsLineConstantEA", l,
                        [&](capi::MoorDynSystem&, int) { capi::output(b, "b") = 1; });
}

int MoorDyn_GetLineConstantEA(MoorDynLine l, double* EA) {
  return capi::withLine("MoorDyn_GetLineConstantEA", l, [&](capi::MoorDynSystem& s, int line) {
    capi::output(EA, "EA") = s.lineAxialStiffness(line);
  });
}

int MoorDyn_SetLineConstantEA(MoorDynLine l, double /*EA*/) {
  return lineNotImplemented("MoorDyn_SetLineConstantEA", l,
                            "the line types are fixed when the system is created (edit the input file)");
}

int MoorDyn_IsLinePressBend(MoorDynLine l, int* b) {
  return capi::withLine("MoorDyn_IsLinePressBend", l,
                        [&](capi::MoorDynSystem&, int) { capi::output(b, "b") = 0; });
}

int MoorDyn_SetLinePressBend(MoorDynLine l, int /*b*/) {
  return lineNotImplemented("MoorDyn_SetLinePressBend", l, "tangle has no internal pressure bending");
}

int MoorDyn_SetLinePressInt(MoorDynLine l, const double* /*p*/) {
  return lineNotImplemented("MoorDyn_SetLinePressInt", l, "tangle has no internal pressure");
}

int MoorDyn_GetLineNodePos(MoorDynLine l, unsigned int i, double pos[3]) {
  return nodeVector(
      "MoorDyn_GetLineNodePos", l, i, pos,
      [](capi::MoorDynSystem& s, int line, unsigned int node) { return s.nodePosition(line, node); });
}

int MoorDyn_GetLineNodeVel(MoorDynLine l, unsigned int i, double vel[3]) {
  return nodeVector(
      "MoorDyn_GetLineNodeVel", l, i, vel,
      [](capi::MoorDynSystem& s, int line, unsigned int node) { return s.nodeVelocity(line, node); });
}

int MoorDyn_GetLineNodeForce(MoorDynLine l, unsigned int i, double f[3]) {
  return nodeVector(
      "MoorDyn_GetLineNodeForce", l, i, f,
      [](capi::MoorDynSystem& s, int line, unsigned int node) { return s.nodeForce(line, node); });
}

int MoorDyn_GetLineNodeTen(MoorDynLine l, unsigned int i, double t[3]) {
  return nodeVector(
      "MoorDyn_GetLineNodeTen", l, i, t,
      [](capi::MoorDynSystem& s, int line, unsigned int node) { return s.nodeTension(line, node); });
}

int MoorDyn_GetLineNodeBendStiff(MoorDynLine l, unsigned int /*i*/, double /*f*/[3]) {
  return lineNotImplemented("MoorDyn_GetLineNodeBendStiff", l, kNoSplit);
}

int MoorDyn_GetLineNodeWeight(MoorDynLine l, unsigned int /*i*/, double /*f*/[3]) {
  return lineNotImplemented("MoorDyn_GetLineNodeWeight", l, kNoSplit);
}

int MoorDyn_GetLineNodeDrag(MoorDynLine l, unsigned int /*i*/, double /*f*/[3]) {
  return lineNotImplemented("MoorDyn_GetLineNodeDrag", l, kNoSplit);
}

int MoorDyn_GetLineNodeFroudeKrilov(MoorDynLine l, unsigned int /*i*/, double /*f*/[3]) {
  return lineNotImplemented("MoorDyn_GetLineNodeFroudeKrilov", l, kNoSplit);
}

int MoorDyn_GetLineNodeSeabedForce(MoorDynLine l, unsigned int /*i*/, double /*f*/[3]) {
  return lineNotImplemented("MoorDyn_GetLineNodeSeabedForce", l, kNoSplit);
}

int MoorDyn_GetLineNodeCurv(MoorDynLine l, unsigned int i, double* c) {
  return capi::withLine("MoorDyn_GetLineNodeCurv", l, [&](capi::MoorDynSystem& s, int line) {
    capi::output(c, "c") = s.nodeCurvature(line, i);
  });
}

int MoorDyn_GetLineNodeM(MoorDynLine l, unsigned int /*i*/, double /*m*/[3][3]) {
  return lineNotImplemented("MoorDyn_GetLineNodeM", l, "tangle does not export the node mass matrices");
}

int MoorDyn_GetLineFairTen(MoorDynLine l, double* t) {
  return capi::withLine("MoorDyn_GetLineFairTen", l, [&](capi::MoorDynSystem& s, int line) {
    capi::output(t, "t") = s.endTension(line, 1);
  });
}

int MoorDyn_GetLineMaxTen(MoorDynLine l, double* t) {
  return capi::withLine("MoorDyn_GetLineMaxTen", l,
                        [&](capi::MoorDynSystem& s, int line) { capi::output(t, "t") = s.maxTension(line); });
}

int MoorDyn_SaveLineVTK(MoorDynLine l, const char* /*filename*/) {
  return lineNotImplemented("MoorDyn_SaveLineVTK", l,
                            "`tangle run` writes ParaView files (vtk/lines.pvd) for a model run on its own");
}

// Points (Point.h).

int MoorDyn_GetPointID(MoorDynPoint point, int* id) {
  return capi::withPoint("MoorDyn_GetPointID", point, [&](capi::MoorDynSystem& s, int p) {
    capi::output(id, "id") = s.pointMap(p).deckId;
  });
}

int MoorDyn_GetPointType(MoorDynPoint point, int* t) {
  return capi::withPoint("MoorDyn_GetPointType", point,
                         [&](capi::MoorDynSystem& s, int p) { capi::output(t, "t") = s.pointType(p); });
}

int MoorDyn_GetPointPos(MoorDynPoint point, double pos[3]) {
  return capi::withPoint("MoorDyn_GetPointPos", point, [&](capi::MoorDynSystem& s, int p) {
    capi::output(pos, "pos");
    put(s.pointPosition(p), pos);
  });
}

int MoorDyn_GetPointVel(MoorDynPoint point, double v[3]) {
  return capi::withPoint("MoorDyn_GetPointVel", point, [&](capi::MoorDynSystem& s, int p) {
    capi::output(v, "v");
    put(s.pointVelocity(p), v);
  });
}

int MoorDyn_GetPointForce(MoorDynPoint point, double f[3]) {
  return capi::withPoint("MoorDyn_GetPointForce", point, [&](capi::MoorDynSystem& s, int p) {
    capi::output(f, "f");
    put(s.pointForce(p), f);
  });
}

int MoorDyn_GetPointM(MoorDynPoint point, double /*m*/[3][3]) {
  return pointNotImplemented("MoorDyn_GetPointM", point, "tangle does not export the point mass matrices");
}

int MoorDyn_GetPointNAttached(MoorDynPoint point, unsigned int* n) {
  return capi::withPoint("MoorDyn_GetPointNAttached", point, [&](capi::MoorDynSystem& s, int p) {
    capi::output(n, "n") = static_cast<unsigned int>(s.pointMap(p).attachedLines.size());
  });
}

int MoorDyn_GetPointAttached(MoorDynPoint point, unsigned int i, MoorDynLine* l, int* e) {
  return capi::withPoint("MoorDyn_GetPointAttached", point, [&](capi::MoorDynSystem& s, int p) {
    const auto& attached = s.pointMap(p).attachedLines;
    if (i >= attached.size())
      throw capi::InvalidValue("point " + std::to_string(s.pointMap(p).deckId) + " has " +
                               std::to_string(attached.size()) + " attached lines, so no line " +
                               std::to_string(i));
    capi::output(l, "l");
    capi::output(e, "e");
    const auto& [deckId, end] = attached[i];
    capi::LineHandle* line = s.line(static_cast<unsigned int>(deckId));
    if (line == nullptr)
      throw capi::InvalidValue("the attached line " + std::to_string(deckId) + " does not exist");
    *l = capi::toHandle(line);
    *e = end;
  });
}

int MoorDyn_SavePointVTK(MoorDynPoint point, const char* /*filename*/) {
  return pointNotImplemented("MoorDyn_SavePointVTK", point,
                             "`tangle run` writes ParaView files (vtk/lines.pvd) for a model run on its own");
}

int MoorDyn_GetRodID(MoorDynRod rod, int* id) {
  return capi::withRod("MoorDyn_GetRodID", rod,
                       [&](capi::MoorDynSystem& s, int r) { capi::output(id, "id") = s.deckRod(r).id; });
}

int MoorDyn_GetRodType(MoorDynRod rod, int* t) {
  return capi::withRod("MoorDyn_GetRodType", rod,
                       [&](capi::MoorDynSystem& s, int r) { capi::output(t, "t") = s.rodType(r); });
}

int MoorDyn_GetRodForce(MoorDynRod rod, double f[6]) {
  return capi::withRod("MoorDyn_GetRodForce", rod, [&](capi::MoorDynSystem& s, int r) {
    capi::output(f, "f");
    put(s.rodForce(r), f);
  });
}

int MoorDyn_GetRodM(MoorDynRod rod, double m[6][6]) {
  return capi::withRod("MoorDyn_GetRodM", rod, [&](capi::MoorDynSystem& s, int r) {
    capi::output(m, "m");
    put(s.rodMass(r), m);
  });
}

int MoorDyn_GetRodN(MoorDynRod rod, unsigned int* n) {
  return capi::withRod("MoorDyn_GetRodN", rod, [&](capi::MoorDynSystem& s, int r) {
    capi::output(n, "n") = static_cast<unsigned int>(s.deckRod(r).segments);
  });
}

int MoorDyn_GetRodNumberNodes(MoorDynRod rod, unsigned int* n) {
  return capi::withRod("MoorDyn_GetRodNumberNodes", rod, [&](capi::MoorDynSystem& s, int r) {
    capi::output(n, "n") = static_cast<unsigned int>(s.deckRod(r).segments) + 1;
  });
}

int MoorDyn_GetRodNodePos(MoorDynRod rod, unsigned int i, double pos[3]) {
  return capi::withRod("MoorDyn_GetRodNodePos", rod, [&](capi::MoorDynSystem& s, int r) {
    capi::output(pos, "pos");
    put(s.rodNodePosition(r, i), pos);
  });
}

int MoorDyn_GetRodNodeVel(MoorDynRod rod, unsigned int i, double vel[3]) {
  return capi::withRod("MoorDyn_GetRodNodeVel", rod, [&](capi::MoorDynSystem& s, int r) {
    capi::output(vel, "vel");
    put(s.rodNodeVelocity(r, i), vel);
  });
}

int MoorDyn_SaveRodVTK(MoorDynRod rod, const char* /*filename*/) {
  return capi::withRod("MoorDyn_SaveRodVTK", rod, [&](capi::MoorDynSystem&, int) {
    capi::throwNotImplemented(
        "`tangle run` writes ParaView files (vtk/lines.pvd) for a model run on its own");
  });
}

}  // extern "C"

// ---- Bodies (Body.h)

int MoorDyn_GetBodyID(MoorDynBody b, int* id) {
  return capi::withBody("MoorDyn_GetBodyID", b,
                        [&](capi::MoorDynSystem& s, int i) { capi::output(id, "id") = s.deckBody(i).id; });
}

int MoorDyn_GetBodyType(MoorDynBody b, int* t) {
  return capi::withBody("MoorDyn_GetBodyType", b,
                        [&](capi::MoorDynSystem& s, int i) { capi::output(t, "t") = s.bodyType(i); });
}

int MoorDyn_GetBodyState(MoorDynBody b, double r[6], double rd[6]) {
  return capi::withBody("MoorDyn_GetBodyState", b, [&](capi::MoorDynSystem& s, int i) {
    capi::output(r, "r");
    capi::output(rd, "rd");
    tangle::Vec6 position, velocity;
    s.bodyState(i, position, velocity);
    put(position, r);
    put(velocity, rd);
  });
}

namespace {
/// One half of the body's state (position or velocity, first or last three) into `out` [3].
template <bool Velocity, int First>
int bodyPart(const char* function, MoorDynBody b, double* out) {
  return capi::withBody(function, b, [&](capi::MoorDynSystem& s, int i) {
    capi::output(out, "the output array");
    tangle::Vec6 position, velocity;
    s.bodyState(i, position, velocity);
    const tangle::Vec6& v = Velocity ? velocity : position;
    for (int k = 0; k < 3; ++k) out[k] = v[First + k];
  });
}
}  // namespace

int MoorDyn_GetBodyPos(MoorDynBody b, double r[3]) { return bodyPart<false, 0>("MoorDyn_GetBodyPos", b, r); }
int MoorDyn_GetBodyAngle(MoorDynBody b, double r[3]) {
  return bodyPart<false, 3>("MoorDyn_GetBodyAngle", b, r);
}
int MoorDyn_GetBodyVel(MoorDynBody b, double rd[3]) { return bodyPart<true, 0>("MoorDyn_GetBodyVel", b, rd); }
int MoorDyn_GetBodyAngVel(MoorDynBody b, double rd[3]) {
  return bodyPart<true, 3>("MoorDyn_GetBodyAngVel", b, rd);
}

int MoorDyn_GetBodyForce(MoorDynBody b, double f[6]) {
  return capi::withBody("MoorDyn_GetBodyForce", b, [&](capi::MoorDynSystem& s, int i) {
    capi::output(f, "f");
    put(s.bodyForce(i), f);
  });
}

int MoorDyn_GetBodyM(MoorDynBody b, double m[6][6]) {
  return capi::withBody("MoorDyn_GetBodyM", b, [&](capi::MoorDynSystem& s, int i) {
    capi::output(m, "m");
    put(s.bodyMass(i), m);
  });
}

int MoorDyn_SaveBodyVTK(MoorDynBody b, const char* /*filename*/) {
  return capi::withBody("MoorDyn_SaveBodyVTK", b, [&](capi::MoorDynSystem&, int) {
    capi::throwNotImplemented("tangle writes ParaView files of the whole model (output.vtk), not per body");
  });
}
