/* Body.h: the body functions of the MoorDyn-compatible C API of tangle (MoorDyn v2.7.1's Body.h).
 *
 * A body is a body of the MoorDyn input file (its BODIES table, ids from 1). Its type (MoorDyn_GetBodyType)
 * takes MoorDyn's values: -1 coupled, 0 free, 1 fixed, 2 coupled and pinned. tangle models a free body as a
 * free vessel (6 degrees of freedom) whose reference point is the centre of gravity of the body and its
 * points; these functions answer for the body's own reference point (the input file's X0, Y0, Z0 moved with
 * it). A fixed body holds what is on it where the input file puts it. A coupled body takes 6 of the host's
 * coupled DOFs, ahead of the points' as MoorDyn orders them (x, y, z and roll, pitch, yaw, XYZ Euler angles,
 * and their rates, the angles' taken as the angular velocity); they move the points on it rigidly, and
 * MoorDyn_Step returns for it the force and moment of the lines on its points about its reference point (its
 * own weight, buoyancy, inertia and drag are the host's). Rods on a coupled body and CoupledPinned bodies are
 * refused by MoorDyn_Create. Attitudes are MoorDyn's XYZ Euler angles (R = Rx(roll) Ry(pitch) Rz(yaw)).
 * Units: SI (m, rad, m/s, rad/s). Every function returns MOORDYN_SUCCESS or an error code (MoorDynAPI.h):
 * MOORDYN_INVALID_VALUE for a NULL body or output. Details: docs/moordyn.md, "Bodies". */

#ifndef TANGLE_MOORDYN_BODY_H
#define TANGLE_MOORDYN_BODY_H

#include "MoorDynAPI.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A body of the mooring system. Valid until MoorDyn_Close of its system. (The struct tag is MoorDyn's.) */
typedef struct __MoorDynBody* MoorDynBody;

/* The body's id in the input file. */
int DECLDIR MoorDyn_GetBodyID(MoorDynBody b, int* id);
/* The body's type: -1 coupled, 0 free, 1 fixed, 2 coupled pinned (MoorDyn's values). */
int DECLDIR MoorDyn_GetBodyType(MoorDynBody b, int* t);
/* Position of its reference point and its XYZ Euler angles [m, rad]; velocity and angular velocity [m/s,
 * rad/s]: the input file's, at rest, before MoorDyn_Init and for a held body. */
int DECLDIR MoorDyn_GetBodyState(MoorDynBody b, double r[6], double rd[6]);
/* Position of its reference point [m]. */
int DECLDIR MoorDyn_GetBodyPos(MoorDynBody b, double r[3]);
/* Its XYZ Euler angles [rad]. */
int DECLDIR MoorDyn_GetBodyAngle(MoorDynBody b, double r[3]);
/* Velocity of its reference point [m/s]. */
int DECLDIR MoorDyn_GetBodyVel(MoorDynBody b, double rd[3]);
/* Angular velocity, global axes [rad/s]. */
int DECLDIR MoorDyn_GetBodyAngVel(MoorDynBody b, double rd[3]);
/* A coupled body's force [N] and moment [N m] about its reference point: what MoorDyn_Step returned for it
 * (after MoorDyn_Init, at the initial state). Not implemented (MOORDYN_NON_IMPLEMENTED) for a free or fixed
 * body. */
int DECLDIR MoorDyn_GetBodyForce(MoorDynBody b, double f[6]);
/* Not implemented (MOORDYN_NON_IMPLEMENTED): the body's mass matrix. */
int DECLDIR MoorDyn_GetBodyM(MoorDynBody b, double m[6][6]);
/* Not implemented (MOORDYN_NON_IMPLEMENTED): tangle writes ParaView files of the whole model instead. */
int DECLDIR MoorDyn_SaveBodyVTK(MoorDynBody b, const char* filename);

#ifdef __cplusplus
}
#endif

#endif /* TANGLE_MOORDYN_BODY_H */
