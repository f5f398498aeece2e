/// @file MoorDynApi.cpp
/// The system functions of the MoorDyn v2 C API (include/tangle-moordyn/MoorDyn2.h) on capi::MoorDynSystem.
/// Every function catches every exception (CApiBoundary.hpp) and returns a MOORDYN_* code.

#include <algorithm>
#include <cstring>
#include <memory>
#include <string>

#include "MoorDyn2.h"
#include "tangle/capi/CApiBoundary.hpp"
#include "tangle/capi/MoorDynSystem.hpp"

namespace capi = tangle::capi;

namespace {

/// The system behind `handle`, or null after printing why (for the functions that return a handle).
capi::MoorDynSystem* systemOrReport(MoorDyn handle, const char* function) {
  capi::MoorDynSystem* system = capi::SystemRegistry::instance().find(handle);
  if (system == nullptr)
    capi::reportError(nullptr, function,
                      handle == nullptr ? "the system is NULL"
                                        : "the system is not open (closed, or not from MoorDyn_Create)");
  return system;
}

}  // namespace

extern "C" {

MoorDyn MoorDyn_Create(const char* infilename) {
  try {
    return capi::SystemRegistry::instance().add(
        std::make_unique<capi::MoorDynSystem>(infilename != nullptr ? infilename : ""));
  } catch (...) {
    capi::handleCurrentException(nullptr, "MoorDyn_Create");
    return nullptr;
  }
}

int MoorDyn_NCoupledDOF(MoorDyn system, unsigned int* n) {
  return capi::withSystem("MoorDyn_NCoupledDOF", system, [&](capi::MoorDynSystem& s) {
    capi::output(n, "n") = static_cast<unsigned int>(s.coupledDofCount());
  });
}

int MoorDyn_SetVerbosity(MoorDyn system, int verbosity) {
  return capi::withSystem("MoorDyn_SetVerbosity", system,
                          [&](capi::MoorDynSystem& s) { s.setVerbosity(verbosity); });
}

int MoorDyn_SetLogFile(MoorDyn system, const char* log_path) {
  return capi::withSystem("MoorDyn_SetLogFile", system,
                          [&](capi::MoorDynSystem& s) { s.setLogFile(&capi::output(log_path, "log_path")); });
}

int MoorDyn_SetLogLevel(MoorDyn system, int verbosity) {
  return capi::withSystem("MoorDyn_SetLogLevel", system,
                          [&](capi::MoorDynSystem& s) { s.setLogLevel(verbosity); });
}

int MoorDyn_Log(MoorDyn system, int level, const char* msg) {
  return capi::withSystem("MoorDyn_Log", system,
                          [&](capi::MoorDynSystem& s) { s.log(level, &capi::output(msg, "msg")); });
}

int MoorDyn_Init(MoorDyn system, const double* x, const double* xd) {
  return capi::withSystem("MoorDyn_Init", system, [&](capi::MoorDynSystem& s) { s.initialize(x, xd); });
}

int MoorDyn_Init_NoIC(MoorDyn system, const double* x, const double* xd) {
  // tangle always starts from the static equilibrium (it has no state file to load instead).
  return capi::withSystem("MoorDyn_Init_NoIC", system, [&](capi::MoorDynSystem& s) { s.initialize(x, xd); });
}

int MoorDyn_Step(MoorDyn system, const double* x, const double* xd, double* f, double* t, double* dt) {
  return capi::withSystem("MoorDyn_Step", system,
                          [&](capi::MoorDynSystem& s) { s.step(x, xd, f, t, capi::output(dt, "dt")); });
}

int MoorDyn_Close(MoorDyn system) {
  if (!capi::SystemRegistry::instance().remove(system)) {
    capi::reportError(nullptr, "MoorDyn_Close",
                      system == nullptr ? "the system is NULL"
                                        : "the system is not open (closed, or not from MoorDyn_Create)");
    return MOORDYN_INVALID_VALUE;
  }
  return MOORDYN_SUCCESS;
}

MoorDynWaves MoorDyn_GetWaves(MoorDyn system) {
  if (capi::MoorDynSystem* s = systemOrReport(system, "MoorDyn_GetWaves"))
    capi::reportError(
        s, "MoorDyn_GetWaves",
        "tangle has no waves object (the waves are the model's environment.waves): NULL returned");
  return nullptr;
}

MoorDynSeafloor MoorDyn_GetSeafloor(MoorDyn system) {
  // As MoorDyn without a SeafloorPath: NULL, the seabed is flat.
  systemOrReport(system, "MoorDyn_GetSeafloor");
  return nullptr;
}

// External wave kinematics (the deck's WaveKin 1): the host gives the fluid velocity and acceleration at
// every line node and point (MoorDynSystem::setWaveKinematics); without WaveKin 1 there are no points (as
// MoorDyn: Init returns 0 and Set is refused).
int MoorDyn_ExternalWaveKinInit(MoorDyn system, unsigned int* n) {
  return capi::withSystem("MoorDyn_ExternalWaveKinInit", system, [&](capi::MoorDynSystem& s) {
    capi::output(n, "n") = static_cast<unsigned int>(s.waveKinematicsPointCount());
  });
}

int MoorDyn_ExternalWaveKinGetN(MoorDyn system, unsigned int* n) {
  return capi::withSystem("MoorDyn_ExternalWaveKinGetN", system, [&](capi::MoorDynSystem& s) {
    capi::output(n, "n") = static_cast<unsigned int>(s.waveKinematicsPointCount());
  });
}

int MoorDyn_ExternalWaveKinGetCoordinates(MoorDyn system, double* r) {
  return capi::withSystem("MoorDyn_ExternalWaveKinGetCoordinates", system, [&](capi::MoorDynSystem& s) {
    const std::vector<double> points = s.waveKinematicsPoints();
    if (!points.empty()) std::copy(points.begin(), points.end(), &capi::output(r, "r"));
  });
}

int MoorDyn_ExternalWaveKinSet(MoorDyn system, const double* U, const double* Ud, double /*t*/) {
  // MoorDyn keeps the kinematics until the next call whatever t says (Waves::setWaveKinematics).
  return capi::withSystem("MoorDyn_ExternalWaveKinSet", system,
                          [&](capi::MoorDynSystem& s) { s.setWaveKinematics(U, Ud); });
}

int MoorDyn_GetNumberBodies(MoorDyn system, unsigned int* n) {
  return capi::withSystem("MoorDyn_GetNumberBodies", system, [&](capi::MoorDynSystem& s) {
    capi::output(n, "n") = static_cast<unsigned int>(s.bodyCount());
  });
}

MoorDynBody MoorDyn_GetBody(MoorDyn system, unsigned int b) {
  capi::MoorDynSystem* s = systemOrReport(system, "MoorDyn_GetBody");
  if (s == nullptr) return nullptr;
  if (capi::BodyHandle* h = s->body(b)) return reinterpret_cast<MoorDynBody>(h);
  capi::reportError(s, "MoorDyn_GetBody",
                    "there is no body " + std::to_string(b) + " (the input file has " +
                        std::to_string(s->bodyCount()) + "; ids start at 1)");
  return nullptr;
}

int MoorDyn_GetNumberRods(MoorDyn system, unsigned int* n) {
  return capi::withSystem("MoorDyn_GetNumberRods", system, [&](capi::MoorDynSystem& s) {
    capi::output(n, "n") = static_cast<unsigned int>(s.rodCount());
  });
}

MoorDynRod MoorDyn_GetRod(MoorDyn system, unsigned int r) {
  capi::MoorDynSystem* s = systemOrReport(system, "MoorDyn_GetRod");
  if (s == nullptr) return nullptr;
  if (capi::RodHandle* h = s->rod(r)) return reinterpret_cast<MoorDynRod>(h);
  capi::reportError(
      s, "MoorDyn_GetRod",
      "there is no rod " + std::to_string(r) + " (the input file has " + std::to_string(s->rodCount()) + ")");
  return nullptr;
}

int MoorDyn_GetNumberPoints(MoorDyn system, unsigned int* n) {
  return capi::withSystem("MoorDyn_GetNumberPoints", system, [&](capi::MoorDynSystem& s) {
    capi::output(n, "n") = static_cast<unsigned int>(s.pointCount());
  });
}

MoorDynPoint MoorDyn_GetPoint(MoorDyn system, unsigned int c) {
  capi::MoorDynSystem* s = systemOrReport(system, "MoorDyn_GetPoint");
  if (s == nullptr) return nullptr;
  capi::PointHandle* point = s->point(c);
  if (point == nullptr)
    capi::reportError(
        s, "MoorDyn_GetPoint",
        "there is no point " + std::to_string(c) + " (ids 1 to " + std::to_string(s->pointCount()) + ")");
  return point != nullptr ? capi::toHandle(point) : nullptr;
}

int MoorDyn_GetNumberLines(MoorDyn system, unsigned int* n) {
  return capi::withSystem("MoorDyn_GetNumberLines", system, [&](capi::MoorDynSystem& s) {
    capi::output(n, "n") = static_cast<unsigned int>(s.lineCount());
  });
}

MoorDynLine MoorDyn_GetLine(MoorDyn system, unsigned int l) {
  capi::MoorDynSystem* s = systemOrReport(system, "MoorDyn_GetLine");
  if (s == nullptr) return nullptr;
  capi::LineHandle* line = s->line(l);
  if (line == nullptr)
    capi::reportError(
        s, "MoorDyn_GetLine",
        "there is no line " + std::to_string(l) + " (ids 1 to " + std::to_string(s->lineCount()) + ")");
  return line != nullptr ? capi::toHandle(line) : nullptr;
}

int MoorDyn_GetFASTtens(MoorDyn system, const int* numLines, float FairHTen[], float FairVTen[],
                        float AnchHTen[], float AnchVTen[]) {
  return capi::withSystem("MoorDyn_GetFASTtens", system, [&](capi::MoorDynSystem& s) {
    const int count = capi::output(numLines, "numLines");
    if (count < 0 || count > s.lineCount())
      throw capi::InvalidValue("numLines is " + std::to_string(count) + "; the system has " +
                               std::to_string(s.lineCount()) + " lines");
    if (count == 0) return;
    capi::output(FairHTen, "FairHTen");
    capi::output(FairVTen, "FairVTen");
    capi::output(AnchHTen, "AnchHTen");
    capi::output(AnchVTen, "AnchVTen");
    for (int l = 0; l < count; ++l) {
      const tangle::Vec3 fair = s.endForce(l, 1);
      const tangle::Vec3 anchor = s.endForce(l, 0);
      FairHTen[l] = static_cast<float>(fair.head<2>().norm());
      FairVTen[l] = static_cast<float>(fair.z());
      AnchHTen[l] = static_cast<float>(anchor.head<2>().norm());
      AnchVTen[l] = static_cast<float>(anchor.z());
    }
  });
}

int MoorDyn_BreakLine(MoorDyn system, MoorDynPoint /*point*/, MoorDynLine /*line*/) {
  return capi::withSystem("MoorDyn_BreakLine", system, [](capi::MoorDynSystem&) {
    capi::throwNotImplemented("tangle has no line failures");
  });
}

int MoorDyn_GetDt(MoorDyn system, double* dt) {
  return capi::withSystem("MoorDyn_GetDt", system,
                          [&](capi::MoorDynSystem& s) { capi::output(dt, "dt") = s.timeStep(); });
}

int MoorDyn_SetDt(MoorDyn system, double dt) {
  return capi::withSystem("MoorDyn_SetDt", system, [&](capi::MoorDynSystem& s) { s.setTimeStep(dt); });
}

int MoorDyn_GetCFL(MoorDyn system, double* /*cfl*/) {
  return capi::withSystem("MoorDyn_GetCFL", system, [](capi::MoorDynSystem&) {
    capi::throwNotImplemented("tangle's implicit integrator has no CFL limit (the step is MoorDyn_GetDt)");
  });
}

int MoorDyn_SetCFL(MoorDyn system, double /*cfl*/) {
  return capi::withSystem("MoorDyn_SetCFL", system, [](capi::MoorDynSystem&) {
    capi::throwNotImplemented(
        "tangle's implicit integrator has no CFL limit (set the step with MoorDyn_SetDt)");
  });
}

int MoorDyn_GetTimeScheme(MoorDyn system, char* name, size_t* name_len) {
  return capi::withSystem("MoorDyn_GetTimeScheme", system, [&](capi::MoorDynSystem& s) {
    const std::string scheme = s.timeSchemeName();
    if (name_len != nullptr) *name_len = scheme.size() + 1;
    if (name != nullptr) std::memcpy(name, scheme.c_str(), scheme.size() + 1);
  });
}

int MoorDyn_SetTimeScheme(MoorDyn system, const char* /*name*/) {
  return capi::withSystem("MoorDyn_SetTimeScheme", system, [](capi::MoorDynSystem&) {
    capi::throwNotImplemented("the time scheme is the model's (dynamics.integrator of the converted model)");
  });
}

int MoorDyn_SaveState(MoorDyn system, const char* /*filepath*/) {
  return capi::withSystem("MoorDyn_SaveState", system, [](capi::MoorDynSystem&) {
    capi::throwNotImplemented("tangle has no state files");
  });
}

int MoorDyn_LoadState(MoorDyn system, const char* /*filepath*/) {
  return capi::withSystem("MoorDyn_LoadState", system, [](capi::MoorDynSystem&) {
    capi::throwNotImplemented("tangle has no state files");
  });
}

int MoorDyn_Serialize(MoorDyn system, size_t* /*size*/, uint64_t* /*data*/) {
  return capi::withSystem("MoorDyn_Serialize", system, [](capi::MoorDynSystem&) {
    capi::throwNotImplemented("tangle cannot serialize a system (its path-dependent state is not exported)");
  });
}

int MoorDyn_Deserialize(MoorDyn system, const uint64_t* /*data*/) {
  return capi::withSystem("MoorDyn_Deserialize", system, [](capi::MoorDynSystem&) {
    capi::throwNotImplemented("tangle cannot serialize a system (its path-dependent state is not exported)");
  });
}

int MoorDyn_Save(MoorDyn system, const char* /*filepath*/) {
  return capi::withSystem("MoorDyn_Save", system, [](capi::MoorDynSystem&) {
    capi::throwNotImplemented("tangle has no state files");
  });
}

int MoorDyn_Load(MoorDyn system, const char* /*filepath*/) {
  return capi::withSystem("MoorDyn_Load", system, [](capi::MoorDynSystem&) {
    capi::throwNotImplemented("tangle has no state files");
  });
}

int MoorDyn_SaveVTK(MoorDyn system, const char* /*filename*/) {
  return capi::withSystem("MoorDyn_SaveVTK", system, [](capi::MoorDynSystem&) {
    capi::throwNotImplemented(
        "`tangle run` writes ParaView files (vtk/lines.pvd) for a model run on its own");
  });
}

}  // extern "C"
