/* moordyn_host.c: a host program written against MoorDyn's C API (MoorDyn2.h) only, as a MoorDyn user
 * writes one, linked against tangle's libtangle_moordyn (tests/python/test_moordyn_capi.py runs it).
 *
 * Usage: moordyn_host DECK OUT_CSV AMPLITUDE PERIOD DURATION DT [INIT_VELOCITY]
 *
 * Creates the system from DECK, reads the position of every coupled point (MoorDyn_GetPoint,
 * MoorDyn_GetPointType, MoorDyn_GetPointPos), initializes it there, then steps it by DT [s] up to DURATION
 * [s] with the first coupled point moved along x as x(t) = x0 + AMPLITUDE sin(2 pi t / PERIOD) (no ramp;
 * [m], [s]) and the others held. Each step is given the position at its start and the velocity
 * (x(t + DT) - x(t)) / DT, so that it ends exactly on the harmonic. MoorDyn_Init gets the velocity of the
 * first step (the point is already moving at t = 0), or zero when INIT_VELOCITY is 0 (default 1). Writes
 * time_s, the tension at end B of line 1 (MoorDyn_GetLineFairTen: its top segment's, as MoorDyn) [N] and
 * the magnitude of the force there (MoorDyn_GetLineNodeForce at node N: the segment's pull and the top
 * node's own loads, the force on the fairlead) [N], at t = 0 and after every step, to OUT_CSV. Exits with 1
 * on any API error (the call is named on stderr), 2 on bad arguments. C99. */

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "MoorDyn2.h"

/* Reports a failed call and returns nonzero: the caller jumps to its cleanup. */
static int failed(int code, const char* call) {
  if (code == MOORDYN_SUCCESS) return 0;
  fprintf(stderr, "moordyn_host: %s returned %d\n", call, code);
  return 1;
}

static int parseNumber(const char* text, const char* name, double* value) {
  char* end = NULL;
  *value = strtod(text, &end);
  if (end == text || *end != '\0' || !isfinite(*value)) {
    fprintf(stderr, "moordyn_host: %s must be a number, not '%s'\n", name, text);
    return 0;
  }
  return 1;
}

int main(int argc, char** argv) {
  const double pi = 3.14159265358979323846;
  double amplitude = 0.0, period = 0.0, duration = 0.0, dt = 0.0, initVelocity = 1.0;
  MoorDyn system = NULL;
  MoorDynLine line = NULL;
  FILE* out = NULL;
  double *x = NULL, *xd = NULL, *f = NULL;
  unsigned int dofs = 0, points = 0, p = 0;
  int firstCoupled = -1, status = 1;
  long steps = 0, k = 0;
  double x0 = 0.0, t = 0.0, tension = 0.0, force[3] = {0.0, 0.0, 0.0};
  unsigned int segments = 0;

  if (argc != 7 && argc != 8) {
    fprintf(stderr, "usage: moordyn_host DECK OUT_CSV AMPLITUDE PERIOD DURATION DT [INIT_VELOCITY]\n");
    return 2;
  }
  if (!parseNumber(argv[3], "AMPLITUDE", &amplitude) || !parseNumber(argv[4], "PERIOD", &period) ||
      !parseNumber(argv[5], "DURATION", &duration) || !parseNumber(argv[6], "DT", &dt) ||
      (argc == 8 && !parseNumber(argv[7], "INIT_VELOCITY", &initVelocity)))
    return 2;
  if (period <= 0.0 || dt <= 0.0 || duration < 0.0) {
    fprintf(stderr, "moordyn_host: PERIOD and DT must be > 0 and DURATION >= 0\n");
    return 2;
  }

  system = MoorDyn_Create(argv[1]);
  if (system == NULL) {
    fprintf(stderr, "moordyn_host: MoorDyn_Create failed for %s\n", argv[1]);
    return 1;
  }
  if (failed(MoorDyn_NCoupledDOF(system, &dofs), "MoorDyn_NCoupledDOF")) goto cleanup;
  if (dofs == 0) {
    fprintf(stderr, "moordyn_host: %s has no coupled point\n", argv[1]);
    goto cleanup;
  }
  x = calloc(dofs, sizeof(double));
  xd = calloc(dofs, sizeof(double));
  f = calloc(dofs, sizeof(double));
  if (x == NULL || xd == NULL || f == NULL) {
    fprintf(stderr, "moordyn_host: out of memory\n");
    goto cleanup;
  }

  /* The coupled DOFs are the coupled points' x, y, z in the order of the input file. */
  if (failed(MoorDyn_GetNumberPoints(system, &points), "MoorDyn_GetNumberPoints")) goto cleanup;
  {
    unsigned int filled = 0;
    for (p = 1; p <= points; ++p) {
      MoorDynPoint point = MoorDyn_GetPoint(system, p);
      int type = 0;
      if (point == NULL) {
        fprintf(stderr, "moordyn_host: MoorDyn_GetPoint(%u) returned NULL\n", p);
        goto cleanup;
      }
      if (failed(MoorDyn_GetPointType(point, &type), "MoorDyn_GetPointType")) goto cleanup;
      if (type != -1) continue; /* MoorDyn's COUPLED */
      if (filled + 3 > dofs) {
        fprintf(stderr, "moordyn_host: more coupled points than MoorDyn_NCoupledDOF says\n");
        goto cleanup;
      }
      if (failed(MoorDyn_GetPointPos(point, x + filled), "MoorDyn_GetPointPos")) goto cleanup;
      if (firstCoupled < 0) firstCoupled = (int)filled;
      filled += 3;
    }
    if (filled != dofs) {
      fprintf(stderr, "moordyn_host: %u coupled DOFs found, MoorDyn_NCoupledDOF says %u\n", filled, dofs);
      goto cleanup;
    }
  }
  x0 = x[firstCoupled];

  line = MoorDyn_GetLine(system, 1);
  if (line == NULL) {
    fprintf(stderr, "moordyn_host: MoorDyn_GetLine(1) returned NULL\n");
    goto cleanup;
  }
  out = fopen(argv[2], "w");
  if (out == NULL) {
    fprintf(stderr, "moordyn_host: cannot write %s\n", argv[2]);
    goto cleanup;
  }
  fprintf(out, "time_s,fairlead_tension_N,fairlead_force_N\n");
  if (failed(MoorDyn_GetLineN(line, &segments), "MoorDyn_GetLineN")) goto cleanup;

  if (initVelocity != 0.0) xd[firstCoupled] = amplitude * sin(2.0 * pi * dt / period) / dt;
  if (failed(MoorDyn_Init(system, x, xd), "MoorDyn_Init")) goto cleanup;
  if (failed(MoorDyn_GetLineFairTen(line, &tension), "MoorDyn_GetLineFairTen")) goto cleanup;
  if (failed(MoorDyn_GetLineNodeForce(line, segments, force), "MoorDyn_GetLineNodeForce")) goto cleanup;
  fprintf(out, "%.6f,%.9e,%.9e\n", 0.0, tension,
          sqrt(force[0] * force[0] + force[1] * force[1] + force[2] * force[2]));

  steps = (long)floor(duration / dt + 0.5);
  for (k = 0; k < steps; ++k) {
    const double start = (double)k * dt;
    const double end = (double)(k + 1) * dt;
    const double xStart = x0 + amplitude * sin(2.0 * pi * start / period);
    const double xEnd = x0 + amplitude * sin(2.0 * pi * end / period);
    double stepDt = dt;
    x[firstCoupled] = xStart;
    xd[firstCoupled] = (xEnd - xStart) / dt;
    t = start;
    if (failed(MoorDyn_Step(system, x, xd, f, &t, &stepDt), "MoorDyn_Step")) goto cleanup;
    if (failed(MoorDyn_GetLineFairTen(line, &tension), "MoorDyn_GetLineFairTen")) goto cleanup;
    if (failed(MoorDyn_GetLineNodeForce(line, segments, force), "MoorDyn_GetLineNodeForce")) goto cleanup;
    fprintf(out, "%.6f,%.9e,%.9e\n", t, tension,
            sqrt(force[0] * force[0] + force[1] * force[1] + force[2] * force[2]));
  }
  status = 0;

cleanup:
  if (out != NULL && fclose(out) != 0) {
    fprintf(stderr, "moordyn_host: error writing %s\n", argv[2]);
    status = 1;
  }
  free(x);
  free(xd);
  free(f);
  if (system != NULL && failed(MoorDyn_Close(system), "MoorDyn_Close")) status = 1;
  return status;
}
