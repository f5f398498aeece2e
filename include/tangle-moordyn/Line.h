/* Line.h: the line functions of the MoorDyn-compatible C API of tangle (MoorDyn v2.7.1's Line.h).
 *
 * A line is a line of the MoorDyn input file (its LINES table, ids from 1), even where tangle has joined it
 * with others in series into one tangle line. Its nodes are numbered from 0 at end A (AttachA) to N at end
 * B (AttachB), N the line's number of segments, as in MoorDyn. Results are those of the state after the
 * last MoorDyn_Init or MoorDyn_Step; before MoorDyn_Init the functions that need results return
 * MOORDYN_INVALID_VALUE. Units: SI (m, m/s, N). Every function returns MOORDYN_SUCCESS or an error code
 * (MoorDynAPI.h): MOORDYN_INVALID_VALUE for a NULL line, a NULL output or a node index above N.
 * Details and the differences from MoorDyn: docs/moordyn.md, "C API and Python coupling". */

#ifndef TANGLE_MOORDYN_LINE_H
#define TANGLE_MOORDYN_LINE_H

#include "MoorDynAPI.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A line of the mooring system. Valid until MoorDyn_Close of its system. (The struct tag is MoorDyn's.) */
typedef struct __MoorDynLine* MoorDynLine;

/* The line's id in the input file. */
int DECLDIR MoorDyn_GetLineID(MoorDynLine l, int* id);
/* The number of segments N (the line has N + 1 nodes). */
int DECLDIR MoorDyn_GetLineN(MoorDynLine l, unsigned int* n);
/* The number of nodes, N + 1. */
int DECLDIR MoorDyn_GetLineNumberNodes(MoorDynLine l, unsigned int* n);
/* The unstretched length [m]. */
int DECLDIR MoorDyn_GetLineUnstretchedLength(MoorDynLine l, double* ul);
/* Not implemented: tangle does not change a line's length during a run (MOORDYN_NON_IMPLEMENTED). */
int DECLDIR MoorDyn_SetLineUnstretchedLength(MoorDynLine l, double ul);
/* Not implemented (MOORDYN_NON_IMPLEMENTED). */
int DECLDIR MoorDyn_SetLineUnstretchedLengthVel(MoorDynLine l, double v);
/* Sets *b to 1: tangle's lines have a constant axial stiffness. */
int DECLDIR MoorDyn_IsLineConstantEA(MoorDynLine l, int* b);
/* The axial stiffness EA of the line's type [N]. */
int DECLDIR MoorDyn_GetLineConstantEA(MoorDynLine l, double* EA);
/* Not implemented: the line types are fixed when the system is created (MOORDYN_NON_IMPLEMENTED). */
int DECLDIR MoorDyn_SetLineConstantEA(MoorDynLine l, double EA);
/* Sets *b to 0: tangle has no internal pressure bending. */
int DECLDIR MoorDyn_IsLinePressBend(MoorDynLine l, int* b);
/* Not implemented (MOORDYN_NON_IMPLEMENTED). */
int DECLDIR MoorDyn_SetLinePressBend(MoorDynLine l, int b);
/* Not implemented (MOORDYN_NON_IMPLEMENTED). */
int DECLDIR MoorDyn_SetLinePressInt(MoorDynLine l, const double* p);

/* Position of node i (0 <= i <= N) [m]. */
int DECLDIR MoorDyn_GetLineNodePos(MoorDynLine l, unsigned int i, double pos[3]);
/* Velocity of node i [m/s]. */
int DECLDIR MoorDyn_GetLineNodeVel(MoorDynLine l, unsigned int i, double vel[3]);
/* Force on node i [N]. At the line's two ends: the force the line exerts on what holds the end (as
 * MoorDyn's net force on an end node, which is held). At the inner nodes: the node's structural mass times
 * its acceleration, the net force on it without the added mass (zero at rest; MoorDyn's includes the
 * added mass). */
int DECLDIR MoorDyn_GetLineNodeForce(MoorDynLine l, unsigned int i, double f[3]);
/* Tension vector at node i [N], pointing from end A towards end B along the line: at inner nodes the
 * effective tension of the node (the mean of its two segments) along the line's direction there; at the
 * line's two ends its end segment's tension along that segment (MoorDyn's Line::getNodeTen; MoorDyn's adds
 * the segment's axial damping). */
int DECLDIR MoorDyn_GetLineNodeTen(MoorDynLine l, unsigned int i, double t[3]);
/* Not implemented: tangle does not split the node forces by source (MOORDYN_NON_IMPLEMENTED). */
int DECLDIR MoorDyn_GetLineNodeBendStiff(MoorDynLine l, unsigned int i, double f[3]);
int DECLDIR MoorDyn_GetLineNodeWeight(MoorDynLine l, unsigned int i, double f[3]);
int DECLDIR MoorDyn_GetLineNodeDrag(MoorDynLine l, unsigned int i, double f[3]);
int DECLDIR MoorDyn_GetLineNodeFroudeKrilov(MoorDynLine l, unsigned int i, double f[3]);
int DECLDIR MoorDyn_GetLineNodeSeabedForce(MoorDynLine l, unsigned int i, double f[3]);
/* Curvature at node i [1/m]: M/EI for lines with bending stiffness, the discrete geometric curvature of the
 * node's two segments for lines without (where MoorDyn gives 0). */
int DECLDIR MoorDyn_GetLineNodeCurv(MoorDynLine l, unsigned int i, double* c);
/* Not implemented (MOORDYN_NON_IMPLEMENTED). */
int DECLDIR MoorDyn_GetLineNodeM(MoorDynLine l, unsigned int i, double m[3][3]);
/* Tension at end B (the fairlead in MoorDyn's convention) [N]: as MoorDyn's, its top segment's tension, the
 * norm of MoorDyn_GetLineNodeTen at node N. (tangle's end tension in dynamics/end_forces.csv is the force on
 * the end, MoorDyn_GetLineNodeForce's there: it adds the end node's own loads.) */
int DECLDIR MoorDyn_GetLineFairTen(MoorDynLine l, double* t);
/* Largest norm of MoorDyn_GetLineNodeTen over the nodes 0 to N - 1 at the current state [N] (MoorDyn's
 * range: the top node left out). */
int DECLDIR MoorDyn_GetLineMaxTen(MoorDynLine l, double* t);
/* Not implemented: tangle writes ParaView files itself (`tangle run`) (MOORDYN_NON_IMPLEMENTED). */
int DECLDIR MoorDyn_SaveLineVTK(MoorDynLine l, const char* filename);

#ifdef __cplusplus
}
#endif

#endif /* TANGLE_MOORDYN_LINE_H */
