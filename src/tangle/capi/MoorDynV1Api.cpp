/// @file MoorDynV1Api.cpp
/// MoorDyn's old C API (include/tangle-moordyn/MoorDyn.h): the MoorDyn2.h functions on one system per
/// process. The system is owned by the registry like any other (CApiBoundary.hpp); this file only keeps
/// its handle.

#include <mutex>

#include "MoorDyn.h"
#include "MoorDyn2.h"
#include "tangle/capi/CApiBoundary.hpp"

namespace capi = tangle::capi;

namespace {

/// The system of the old API (null when there is none), and the lock of its replacement.
MoorDyn g_system = nullptr;
std::mutex g_systemMutex;

MoorDyn current() {
  const std::lock_guard<std::mutex> lock(g_systemMutex);
  return g_system;
}

void reportNoSystem(const char* function) {
  capi::reportError(nullptr, function, "there is no system: MoorDynInit has not succeeded");
}

}  // namespace

extern "C" {

int MoorDynInit(const double x[], const double xd[], const char* infilename) {
  MoorDyn system = MoorDyn_Create(infilename);
  if (system == nullptr) return MOORDYN_UNHANDLED_ERROR;  // as MoorDyn; the reason is on stderr
  const int error = MoorDyn_Init(system, x, xd);
  if (error != MOORDYN_SUCCESS) {
    MoorDyn_Close(system);
    return error;
  }
  MoorDyn previous = nullptr;
  {
    const std::lock_guard<std::mutex> lock(g_systemMutex);
    previous = g_system;
    g_system = system;
  }
  if (previous != nullptr) MoorDyn_Close(previous);
  return MOORDYN_SUCCESS;
}

int MoorDynStep(const double x[], const double xd[], double f[], double* t, double* dt) {
  MoorDyn system = current();
  if (system == nullptr) {
    reportNoSystem("MoorDynStep");
    return MOORDYN_INVALID_VALUE;
  }
  return MoorDyn_Step(system, x, xd, f, t, dt);
}

int MoorDynClose(void) {
  MoorDyn system = nullptr;
  {
    const std::lock_guard<std::mutex> lock(g_systemMutex);
    system = g_system;
    g_system = nullptr;
  }
  if (system == nullptr) {
    reportNoSystem("MoorDynClose");
    return MOORDYN_INVALID_VALUE;
  }
  return MoorDyn_Close(system);
}

int externalWaveKinInit(void) {
  // MoorDyn's MoorDyn.cpp: the system's count, 0 when there is no system or on an error.
  MoorDyn system = current();
  if (system == nullptr) {
    reportNoSystem("externalWaveKinInit");
    return 0;
  }
  unsigned int n = 0;
  if (MoorDyn_ExternalWaveKinInit(system, &n) != MOORDYN_SUCCESS) return 0;
  return static_cast<int>(n);
}

void getWaveKinCoordinates(double* r_out) {
  MoorDyn system = current();
  if (system == nullptr) {
    reportNoSystem("getWaveKinCoordinates");
    return;
  }
  MoorDyn_ExternalWaveKinGetCoordinates(system, r_out);
}

void setWaveKin(const double* U_in, const double* Ud_in, double t_in) {
  MoorDyn system = current();
  if (system == nullptr) {
    reportNoSystem("setWaveKin");
    return;
  }
  MoorDyn_ExternalWaveKinSet(system, U_in, Ud_in, t_in);
}

double GetFairTen(int l) {
  MoorDyn system = current();
  if (system == nullptr) {
    reportNoSystem("GetFairTen");
    return -1.0;
  }
  if (l < 1) {
    capi::reportError(nullptr, "GetFairTen", "line ids start at 1");
    return -1.0;
  }
  double tension = -1.0;
  MoorDynLine line = MoorDyn_GetLine(system, static_cast<unsigned int>(l));
  if (line == nullptr || MoorDyn_GetLineFairTen(line, &tension) != MOORDYN_SUCCESS) return -1.0;
  return tension;
}

int GetFASTtens(int* numLines, float FairHTen[], float FairVTen[], float AnchHTen[], float AnchVTen[]) {
  MoorDyn system = current();
  if (system == nullptr) {
    reportNoSystem("GetFASTtens");
    return MOORDYN_MEM_ERROR;  // MoorDyn's code for a missing system in the old API
  }
  return MoorDyn_GetFASTtens(system, numLines, FairHTen, FairVTen, AnchHTen, AnchVTen);
}

int GetPointPos(int l, double pos[3]) {
  MoorDyn system = current();
  if (system == nullptr) {
    reportNoSystem("GetPointPos");
    return MOORDYN_MEM_ERROR;
  }
  return MoorDyn_GetPointPos(MoorDyn_GetPoint(system, static_cast<unsigned int>(l)), pos);
}

int GetPointForce(int l, double force[3]) {
  MoorDyn system = current();
  if (system == nullptr) {
    reportNoSystem("GetPointForce");
    return MOORDYN_MEM_ERROR;
  }
  return MoorDyn_GetPointForce(MoorDyn_GetPoint(system, static_cast<unsigned int>(l)), force);
}

int GetNodePos(int LineNum, int NodeNum, double pos[3]) {
  MoorDyn system = current();
  if (system == nullptr) {
    reportNoSystem("GetNodePos");
    return MOORDYN_MEM_ERROR;
  }
  if (NodeNum < 0) {
    capi::reportError(nullptr, "GetNodePos", "node numbers start at 0");
    return MOORDYN_INVALID_VALUE;
  }
  return MoorDyn_GetLineNodePos(MoorDyn_GetLine(system, static_cast<unsigned int>(LineNum)),
                                static_cast<unsigned int>(NodeNum), pos);
}

void AllOutput(double /*t*/, double /*dt*/) {}

void SetDisableConsole(int /*disable*/) {}

}  // extern "C"
