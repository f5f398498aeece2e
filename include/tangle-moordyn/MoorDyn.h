/* MoorDyn.h: MoorDyn's old (v1-style) C API (MoorDyn v2.7.1's MoorDyn.h) implemented by tangle.
 *
 * One system per process, held by the library: MoorDynInit creates and initializes it (closing any earlier
 * one), MoorDynStep advances it, MoorDynClose destroys it. Each function is the MoorDyn2.h function of the
 * same meaning on that system (see MoorDyn2.h for what they return). New code should use MoorDyn2.h.
 * Valid C99 and C++. */

#ifndef TANGLE_MOORDYN_H
#define TANGLE_MOORDYN_H

#include "MoorDynAPI.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Reads the input file (NULL or "": "Mooring/lines.txt"), builds the system and solves its statics with
 * the coupled points at x [m] (velocities xd [m/s], NULL: zero). MOORDYN_UNHANDLED_ERROR when the system
 * cannot be created (reason on stderr), else MoorDyn_Init's code. */
int DECLDIR MoorDynInit(const double x[], const double xd[], const char* infilename);
/* MoorDyn_Step on the system. MOORDYN_INVALID_VALUE when there is none. */
int DECLDIR MoorDynStep(const double x[], const double xd[], double f[], double* t, double* dt);
/* Destroys the system. MOORDYN_INVALID_VALUE when there is none. */
int DECLDIR MoorDynClose(void);

/* External wave kinematics (a deck with option WaveKin 1): MoorDyn_ExternalWaveKinInit,
 * MoorDyn_ExternalWaveKinGetCoordinates and MoorDyn_ExternalWaveKinSet on the system. externalWaveKinInit
 * returns the number of points (0 when there is no system or on an error); the other two do nothing when
 * there is no system. */
int DECLDIR externalWaveKinInit(void);
void DECLDIR getWaveKinCoordinates(double r_out[]);
void DECLDIR setWaveKin(const double U_in[], const double Ud_in[], double t_in);

/* MoorDyn_GetLineFairTen of line l (1-based): its top segment's tension [N]; -1 when there is no system or
 * no such line. */
double DECLDIR GetFairTen(int l);
/* MoorDyn_GetFASTtens on the system (MOORDYN_MEM_ERROR when there is none, as MoorDyn). */
int DECLDIR GetFASTtens(int* numLines, float FairHTen[], float FairVTen[], float AnchHTen[],
                        float AnchVTen[]);
/* Position and force of point l (1-based) [m], [N] (MOORDYN_MEM_ERROR when there is no system). */
int DECLDIR GetPointPos(int l, double pos[3]);
int DECLDIR GetPointForce(int l, double force[3]);
/* Position of node NodeNum (0 at end A) of line LineNum (1-based) [m]. */
int DECLDIR GetNodePos(int LineNum, int NodeNum, double pos[3]);
/* Does nothing (as in MoorDyn v2: outputs are written by the steps). */
void DECLDIR AllOutput(double t, double dt);
/* Does nothing (MoorDyn opens a console window on Windows only). */
void DECLDIR SetDisableConsole(int disable);

#ifdef __cplusplus
}
#endif

#endif /* TANGLE_MOORDYN_H */
