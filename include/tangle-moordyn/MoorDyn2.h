/* MoorDyn2.h: the MoorDyn v2 C API (MoorDyn v2.7.1's MoorDyn2.h) implemented by tangle.
 *
 * A host program written against MoorDyn's header (OpenFAST-style glue, WEC-Sim, a user's own code)
 * compiles unchanged against this one and links against libtangle_moordyn (-ltangle_moordyn) instead of
 * libmoordyn. The system is read from a MoorDyn v2 input file, converted into a tangle model
 * (docs/moordyn.md), and run by tangle's implicit solver: MoorDyn_Step advances it over the host's step
 * with the model's own time steps inside, the coupled points moving from the position given at the step
 * start with the velocity given (x + xd (t - t0)), and returns the force the lines exert on each coupled
 * point at the end of the step.
 *
 * tangle has lines and points only: no bodies, rods, external wave kinematics, 3D seafloor, line failures
 * or state files. The functions for those exist so that hosts link, and return MOORDYN_NON_IMPLEMENTED (or
 * NULL) with a message on stderr naming the function.
 *
 * Errors: every function returns MOORDYN_SUCCESS or an error code (MoorDynAPI.h) and prints the reason on
 * stderr, prefixed "tangle (MoorDyn API): " (tangle's exceptions never cross the C boundary). Units: SI.
 * Valid C99 and C++. What each function returns: docs/moordyn.md, "C API and Python coupling". */

#ifndef TANGLE_MOORDYN2_H
#define TANGLE_MOORDYN2_H

#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "Body.h"
#include "Line.h"
#include "MoorDynAPI.h"
#include "Point.h"
#include "Rod.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A mooring system. (The struct tags are MoorDyn's, for hosts that name them.) */
typedef struct __MoorDyn* MoorDyn;
/* Kinds of objects tangle does not have; declared so that hosts written for MoorDyn compile. The
 * functions returning them return NULL. (Rods: Rod.h; bodies: Body.h.) */
typedef struct __MoorDynWaves* MoorDynWaves;
typedef struct __MoorDynSeafloor* MoorDynSeafloor;

/* Reads a MoorDyn v2 input file (NULL or "": "Mooring/lines.txt", as MoorDyn) and builds the system; call
 * MoorDyn_Init next. Returns NULL, with the reason on stderr, when the file cannot be read, holds an entry
 * tangle cannot represent (bodies, coupled rods, ...: named with its line) or has no valid model. */
MoorDyn DECLDIR MoorDyn_Create(const char* infilename);
/* Number of coupled degrees of freedom: 3 per coupled point (the length of x, xd and f). */
int DECLDIR MoorDyn_NCoupledDOF(MoorDyn system, unsigned int* n);

/* Messages: the system's messages (errors of its calls, MoorDyn_Log) go to stderr when their level is at
 * least the verbosity (default MOORDYN_MSG_LEVEL), and to the log file, if set, when at least the log
 * level (default MOORDYN_MSG_LEVEL). A failure of MoorDyn_Create, or a call with a NULL system, is
 * always printed on stderr. */
int DECLDIR MoorDyn_SetVerbosity(MoorDyn system, int verbosity);
/* Opens (truncates) the log file; MOORDYN_INVALID_OUTPUT_FILE when it cannot be opened. */
int DECLDIR MoorDyn_SetLogFile(MoorDyn system, const char* log_path);
int DECLDIR MoorDyn_SetLogLevel(MoorDyn system, int verbosity);
/* Logs msg as it is (no newline added) at the given level. */
int DECLDIR MoorDyn_Log(MoorDyn system, int level, const char* msg);

/* Puts the coupled points at x [m] (3 per coupled point, in input-file order) and solves the static
 * equilibrium there; xd [m/s] is kept as their velocity until the first step (NULL: zero). Time is then 0.
 * MOORDYN_NAN_ERROR when the statics do not converge, MOORDYN_INVALID_VALUE when called twice. */
int DECLDIR MoorDyn_Init(MoorDyn system, const double* x, const double* xd);
/* The same as MoorDyn_Init: tangle always solves the statics (it has no state file to load instead). */
int DECLDIR MoorDyn_Init_NoIC(MoorDyn system, const double* x, const double* xd);
/* Advances the system from its time by *dt [s], the coupled points moving as x + xd (t - t0) from the
 * step start t0 (x [m], xd [m/s], 3 per coupled point), and writes into f the force the lines exert on
 * each coupled point at the end of the step [N] (3 per coupled point; the lines' pull with the weight and
 * inertia of their end nodes). Sets *t to the system's time after the step (the value passed in is not
 * used). *dt <= 0: nothing is advanced, f gets the current forces. MOORDYN_NAN_ERROR when the model cannot
 * be advanced (the message names the time, the node and the force; the state stays the last converged
 * one), MOORDYN_INVALID_VALUE before MoorDyn_Init. */
int DECLDIR MoorDyn_Step(MoorDyn system, const double* x, const double* xd, double* f, double* t, double* dt);
/* Destroys the system; its line and point handles become invalid. */
int DECLDIR MoorDyn_Close(MoorDyn system);

/* NULL: tangle's waves come from the model (environment.waves), not from a waves object. */
MoorDynWaves DECLDIR MoorDyn_GetWaves(MoorDyn system);
/* NULL: tangle's seabed is flat (MoorDyn's 3D seafloor is not supported). */
MoorDynSeafloor DECLDIR MoorDyn_GetSeafloor(MoorDyn system);

/* External wave kinematics (a deck with option WaveKin 1; docs/moordyn.md): the points in MoorDyn's order
 * (every line's nodes, every rod's nodes, every point, the ground body, every body), their positions, and
 * the fluid velocity and acceleration there used from the next step on. Without WaveKin 1 there are no
 * points (MoorDyn counts them whatever WaveKin is) and Set returns MOORDYN_INVALID_VALUE: kinematics the
 * model would not use. */
int DECLDIR MoorDyn_ExternalWaveKinInit(MoorDyn system, unsigned int* n);
int DECLDIR MoorDyn_ExternalWaveKinGetN(MoorDyn system, unsigned int* n);
int DECLDIR MoorDyn_ExternalWaveKinGetCoordinates(MoorDyn system, double* r);
int DECLDIR MoorDyn_ExternalWaveKinSet(MoorDyn system, const double* U, const double* Ud, double t);
/* MoorDyn's deprecated names of the two functions above. */
static inline DEPRECATED int MoorDyn_GetWaveKinCoordinates(MoorDyn system, double* r) {
  return MoorDyn_ExternalWaveKinGetCoordinates(system, r);
}
static inline DEPRECATED int MoorDyn_SetWaveKin(MoorDyn system, const double* U, const double* Ud, double t) {
  return MoorDyn_ExternalWaveKinSet(system, U, Ud, t);
}

/* Bodies: tangle has none (count 0, handles NULL). */
int DECLDIR MoorDyn_GetNumberBodies(MoorDyn system, unsigned int* n);
MoorDynBody DECLDIR MoorDyn_GetBody(MoorDyn system, unsigned int b);
/* Number of rods of the input file, and rod r (1 to that number; NULL otherwise). */
int DECLDIR MoorDyn_GetNumberRods(MoorDyn system, unsigned int* n);
MoorDynRod DECLDIR MoorDyn_GetRod(MoorDyn system, unsigned int r);

/* Points and lines of the input file, by their 1-based ids; NULL for an id out of range. */
int DECLDIR MoorDyn_GetNumberPoints(MoorDyn system, unsigned int* n);
MoorDynPoint DECLDIR MoorDyn_GetPoint(MoorDyn system, unsigned int c);
int DECLDIR MoorDyn_GetNumberLines(MoorDyn system, unsigned int* n);
MoorDynLine DECLDIR MoorDyn_GetLine(MoorDyn system, unsigned int l);

/* FAST's customary end forces of lines 1 to *numLines [N]: at the fairlead (end B) and at the anchor
 * (end A), the horizontal magnitude and the vertical (z) component of the force the line exerts on what
 * holds that end (negative z: the line pulls it down). MOORDYN_INVALID_VALUE when *numLines exceeds the
 * number of lines or before MoorDyn_Init. */
int DECLDIR MoorDyn_GetFASTtens(MoorDyn system, const int* numLines, float FairHTen[], float FairVTen[],
                                float AnchHTen[], float AnchVTen[]);
/* Not implemented: tangle has no line failures (MOORDYN_NON_IMPLEMENTED). */
int DECLDIR MoorDyn_BreakLine(MoorDyn system, MoorDynPoint point, MoorDynLine line);

/* The model's time step (dtM; dynamics.time_step of the tangle model) [s]. */
int DECLDIR MoorDyn_GetDt(MoorDyn system, double* dt);
/* Sets the model's time step [s] (> 0); only before MoorDyn_Init (after it: MOORDYN_NON_IMPLEMENTED). */
int DECLDIR MoorDyn_SetDt(MoorDyn system, double dt);
/* Not implemented: tangle's implicit integrator has no CFL limit (MOORDYN_NON_IMPLEMENTED). */
int DECLDIR MoorDyn_GetCFL(MoorDyn system, double* cfl);
int DECLDIR MoorDyn_SetCFL(MoorDyn system, double cfl);
/* The name of tangle's time scheme ("generalized_alpha", "hht" or "newmark", the model's
 * dynamics.integrator); *name_len gets its length plus 1. Either pointer may be NULL. */
int DECLDIR MoorDyn_GetTimeScheme(MoorDyn system, char* name, size_t* name_len);
/* Not implemented: the scheme is the model's (MOORDYN_NON_IMPLEMENTED). */
int DECLDIR MoorDyn_SetTimeScheme(MoorDyn system, const char* name);

/* State files and serialization: not implemented (MOORDYN_NON_IMPLEMENTED). */
int DECLDIR MoorDyn_SaveState(MoorDyn system, const char* filepath);
int DECLDIR MoorDyn_LoadState(MoorDyn system, const char* filepath);
int DECLDIR MoorDyn_Serialize(MoorDyn system, size_t* size, uint64_t* data);
int DECLDIR MoorDyn_Deserialize(MoorDyn system, const uint64_t* data);
int DECLDIR MoorDyn_Save(MoorDyn system, const char* filepath);
int DECLDIR MoorDyn_Load(MoorDyn system, const char* filepath);
/* Not implemented: `tangle run` writes ParaView files (MOORDYN_NON_IMPLEMENTED). */
int DECLDIR MoorDyn_SaveVTK(MoorDyn system, const char* filename);

#ifdef __cplusplus
}
#endif

#endif /* TANGLE_MOORDYN2_H */
