/* Rod.h: the rod functions of the MoorDyn-compatible C API of tangle (MoorDyn v2.7.1's Rod.h).
 *
 * A rod is a rod of the MoorDyn input file (its RODS table, ids from 1). Its type (MoorDyn_GetRodType) takes
 * MoorDyn's values: -2 coupled, -1 coupled and pinned, 0 free, 1 pinned, 2 fixed. tangle models a pinned or
 * free rod of length > 0 as a stiff beam line whose nodes are the rod's (NumSegs + 1 of them), a fixed rod by
 * its ends (the nodes stay where the input file puts them), a zero-length rod as a point (one node). Coupled
 * rods are refused by MoorDyn_Create. Units: SI (m, m/s). Every function returns MOORDYN_SUCCESS or an error
 * code (MoorDynAPI.h): MOORDYN_INVALID_VALUE for a NULL rod or output, or a node index above NumSegs.
 * Details and the differences from MoorDyn: docs/moordyn.md, "Rods". */

#ifndef TANGLE_MOORDYN_ROD_H
#define TANGLE_MOORDYN_ROD_H

#include "MoorDynAPI.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A rod of the mooring system. Valid until MoorDyn_Close of its system. (The struct tag is MoorDyn's.) */
typedef struct __MoorDynRod* MoorDynRod;

/* The rod's id in the input file. */
int DECLDIR MoorDyn_GetRodID(MoorDynRod rod, int* id);
/* The rod's type: -2 coupled, -1 coupled pinned, 0 free, 1 pinned, 2 fixed (MoorDyn's values). */
int DECLDIR MoorDyn_GetRodType(MoorDynRod rod, int* t);
/* Not implemented (MOORDYN_NON_IMPLEMENTED): the net force and moment on the rod. */
int DECLDIR MoorDyn_GetRodForce(MoorDynRod rod, double f[6]);
/* Not implemented (MOORDYN_NON_IMPLEMENTED). */
int DECLDIR MoorDyn_GetRodM(MoorDynRod rod, double m[6][6]);
/* Number of segments, NumSegs (nodes: NumSegs + 1). */
int DECLDIR MoorDyn_GetRodN(MoorDynRod rod, unsigned int* n);
/* Number of nodes, NumSegs + 1. */
int DECLDIR MoorDyn_GetRodNumberNodes(MoorDynRod rod, unsigned int* n);
/* Position of node i (0 at end A to NumSegs at end B) [m]: before MoorDyn_Init the input file's. */
int DECLDIR MoorDyn_GetRodNodePos(MoorDynRod rod, unsigned int i, double pos[3]);
/* Velocity of node i [m/s] (zero before MoorDyn_Init and for fixed rods). */
int DECLDIR MoorDyn_GetRodNodeVel(MoorDynRod rod, unsigned int i, double vel[3]);
/* Not implemented (MOORDYN_NON_IMPLEMENTED): tangle writes ParaView files of the whole model instead. */
int DECLDIR MoorDyn_SaveRodVTK(MoorDynRod rod, const char* filename);

#ifdef __cplusplus
}
#endif

#endif /* TANGLE_MOORDYN_ROD_H */
