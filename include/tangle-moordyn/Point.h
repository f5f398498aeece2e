/* Point.h: the point functions of the MoorDyn-compatible C API of tangle (MoorDyn v2.7.1's Point.h).
 *
 * A point is a point of the MoorDyn input file (its POINTS table, ids from 1). Its type
 * (MoorDyn_GetPointType) takes MoorDyn's values: -1 coupled (Coupled, Vessel, Fairlead: moved by the host),
 * 0 free (Free, Point, Connect), 1 fixed (Fixed, Anchor). Units: SI (m, m/s, N). Every function returns
 * MOORDYN_SUCCESS or an error code (MoorDynAPI.h): MOORDYN_INVALID_VALUE for a NULL point or output.
 * Details and the differences from MoorDyn: docs/moordyn.md, "C API and Python coupling". */

#ifndef TANGLE_MOORDYN_POINT_H
#define TANGLE_MOORDYN_POINT_H

#include "Line.h"
#include "MoorDynAPI.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A point of the mooring system. Valid until MoorDyn_Close of its system. (The struct tag is MoorDyn's.) */
typedef struct __MoorDynPoint* MoorDynPoint;

/* The point's id in the input file. */
int DECLDIR MoorDyn_GetPointID(MoorDynPoint point, int* id);
/* The point's type: -1 coupled, 0 free, 1 fixed (MoorDyn's values). */
int DECLDIR MoorDyn_GetPointType(MoorDynPoint point, int* t);
/* Position [m]: before MoorDyn_Init the input file's; then the model's (a coupled point where the host put
 * it; an anchor on the seabed is where the model seats it, on the seabed's contact surface). */
int DECLDIR MoorDyn_GetPointPos(MoorDynPoint point, double pos[3]);
/* Velocity [m/s] (zero before MoorDyn_Init and for fixed points). */
int DECLDIR MoorDyn_GetPointVel(MoorDynPoint point, double v[3]);
/* Force on the point [N]. Coupled points: the force MoorDyn_Step returns for the point (the lines' pull
 * with the inertia of their end nodes). Fixed and free points: the sum of the forces the attached lines
 * exert on it; MoorDyn adds a free point's own weight, buoyancy and drag, which makes its net force zero
 * at rest. MOORDYN_INVALID_VALUE before MoorDyn_Init. */
int DECLDIR MoorDyn_GetPointForce(MoorDynPoint point, double f[3]);
/* Not implemented (MOORDYN_NON_IMPLEMENTED). */
int DECLDIR MoorDyn_GetPointM(MoorDynPoint point, double m[3][3]);
/* Number of line ends attached to the point. */
int DECLDIR MoorDyn_GetPointNAttached(MoorDynPoint point, unsigned int* n);
/* The i-th attached line (0 <= i < MoorDyn_GetPointNAttached) and which of its ends is attached (*e: 0 end
 * A, 1 end B, MoorDyn's ENDPOINT_A and ENDPOINT_B). */
int DECLDIR MoorDyn_GetPointAttached(MoorDynPoint point, unsigned int i, MoorDynLine* l, int* e);
/* Not implemented (MOORDYN_NON_IMPLEMENTED). */
int DECLDIR MoorDyn_SavePointVTK(MoorDynPoint point, const char* filename);

#ifdef __cplusplus
}
#endif

#endif /* TANGLE_MOORDYN_POINT_H */
