"""The MoorDyn-compatible C API against `tangle run` (docs/moordyn.md, "C API and Python coupling").

Run through ctest (it sets TANGLE_CLI and MOORDYN_HOST), or by hand:
    TANGLE_CLI=build/ci/tangle MOORDYN_HOST=build/ci/tests/moordyn_host \\
        /usr/bin/python3 -m pytest -q tests/python/test_moordyn_capi.py

The deck tests/data/moordyn/coupled_chain.txt (one 410 m chain in 50 m of water, from an anchor at
(400, 0, -50) to a coupled fairlead at the origin) is driven with the fairlead surge x(t) = 2 sin(2 pi t / 10) m,
no ramp, for 30 s, twice:
- by tests/capi/moordyn_host.c, a C99 host written against MoorDyn2.h only and linked against
  libtangle_moordyn: MoorDyn_Init, then MoorDyn_Step every dt with the position at the step start and the
  velocity of the chord to the next sample (MoorDyn's convention: the point moves at that constant velocity
  through the step), the force on the fairlead read with MoorDyn_GetLineNodeForce at the top node (the
  top segment's pull and the top node's own loads) and the fairlead tension with MoorDyn_GetLineFairTen
  (MoorDyn's: the top segment's tension);
- by `tangle run` of the deck converted with `tangle convert`, the fairlead end (the pinned end at the
  origin) given the motion itself, the same time step and `ramp_time: 0`; the fairlead end tension from
  dynamics/end_forces.csv (signed: negative while the end element is compressed; its magnitude is that of
  the force on the fairlead).

1. Same kinematics, same answer: `tangle run` with the host's own motion (a linear `table` of the samples:
   piecewise-linear position, the velocity of the step that ends at each sample, zero acceleration, at rest
   at t = 0 as the host is told with INIT_VELOCITY 0) gives the host's fairlead force at every step within
   1e-5 of the tension range. The C API adds nothing and loses nothing. Both run the deck with
   `1e-8 tangleTolerance`: at the deck's own tolerance (1e-5 of the chain's 1.37 MN weight, 13.7 N per
   node, 2e-5 of the range) two runs whose motions differ by round-off may each stop at a different iterate
   within it (the predictor's extrapolation puts many steps' first correction close to the tolerance:
   10-13 N apart); at 1e-8 that latitude is 0.014 N, and the difference measured is 0.5 N (7e-7 of the
   range), end_forces.csv's rounding to 0.1 N of a tension of 1 MN.
2. The harmonic motion itself (`motion: {amplitude: [2, 0, 0], period: 10}`, the host passing its velocity at
   t = 0 to MoorDyn_Init): the ranges after the first period (t >= 10 s) agree within 0.1 % and the
   histories within 0.5 % of the range at every common time, at dt = 0.002 s. The two differ by the
   coupling convention only: within a step the host's point moves at the chord velocity, which at the step
   end lags the harmonic's by about dt/2 x acceleration; through the chain's axial damping (BA = critical
   for its 10 m segments, 8.1e6 N s) that shows in the end tension. The difference is first order in dt:
   at dt = 0.01 s it is 0.60 % of the range (range 0.37 %), at 0.002 s 0.12 % (range 0.07 %). The test
   checks that order (between 0.8 and 1.2) as well.
"""

from __future__ import annotations

import csv
import json
import math
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest
import yaml

ROOT = Path(__file__).resolve().parents[2]
CLI = os.environ.get("TANGLE_CLI", str(ROOT / "build" / "ci" / "tangle"))
HOST = os.environ.get("MOORDYN_HOST", str(ROOT / "build" / "ci" / "tests" / "moordyn_host"))
DECK = ROOT / "tests" / "data" / "moordyn" / "coupled_chain.txt"

AMPLITUDE, PERIOD, DURATION = 2.0, 10.0, 30.0
COARSE_DT, FINE_DT = 0.01, 0.002
FAIRLEAD = np.array([0.0, 0.0, 0.0])  # point 2 of the deck (Coupled)
SETTLED = 10.0  # s: ranges after the first period


def run(*args) -> None:
    result = subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=500)
    assert result.returncode == 0, f"{' '.join(map(str, args))} exited {result.returncode}:\n{result.stderr}"


def read_columns(path: Path) -> dict[str, np.ndarray]:
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, data = rows[0], np.array(rows[1:], dtype=float)
    return {name: data[:, i] for i, name in enumerate(header)}


def fairlead_end(model: dict) -> tuple[dict, str]:
    """The line and end key ('end_a'/'end_b') of the converted model held at the coupled fairlead."""
    found = []
    for line in model["lines"]:
        for key in ("end_a", "end_b"):
            end = line[key]
            if end.get("type") == "pinned" and np.allclose(end.get("position"), FAIRLEAD, atol=1e-9):
                found.append((line, key))
    assert len(found) == 1, f"expected one pinned end at {FAIRLEAD} in the converted model, found {len(found)}"
    return found[0]


@pytest.fixture(scope="module")
def work(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("moordyn_capi")
    run(CLI, "convert", DECK, "-o", folder / "model.yaml")
    # The same deck converged to 1e-8 of the line's weight (docs/moordyn.md, OPTIONS: tangleTolerance).
    text = DECK.read_text()
    end = text.index("------------------------- END")
    (folder / "tight.txt").write_text(text[:end] + "1.0e-8     tangleTolerance\n" + text[end:])
    run(CLI, "convert", folder / "tight.txt", "-o", folder / "tight.yaml")
    return folder


def compare(work: Path, dt: float, motion: dict, init_velocity: int,
            tight: bool = False) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(times, C API force on the fairlead, tangle run's fairlead end tension's magnitude, C API fairlead
    tension) at the common output times [s], [N], [N], [N]; with `tight`, of the deck converged to 1e-8."""
    tag = f"{'table' if 'table' in motion else 'harmonic'}_{dt:g}{'_tight' if tight else ''}"
    host_csv = work / f"host_{tag}.csv"
    run(HOST, work / "tight.txt" if tight else DECK, host_csv, AMPLITUDE, PERIOD, DURATION, dt, init_velocity)
    host = read_columns(host_csv)

    model = yaml.safe_load((work / ("tight.yaml" if tight else "model.yaml")).read_text())
    line, key = fairlead_end(model)
    line[key]["motion"] = motion
    dynamics = model.get("dynamics") or {}
    dynamics.update({"duration": DURATION, "time_step": dt, "ramp_time": 0.0, "output_interval": dt})
    model["dynamics"] = dynamics
    edited = work / f"model_{tag}.yaml"
    edited.write_text(yaml.safe_dump(model, sort_keys=False))
    results = work / f"run_{tag}"
    run(CLI, "run", edited, "-o", results, "--no-plots", "--no-report", "-q")

    forces = read_columns(results / "dynamics" / "end_forces.csv")
    summary = json.loads((results / "summary.json").read_text())
    stem = next(l["file_stem"] for l in summary["lines"] if l["name"] == line["name"])
    column = f"{stem}_{key}_tension_N"
    assert column in forces, f"no column {column} in end_forces.csv: {sorted(forces)}"

    host_keys = np.rint(host["time_s"] / dt).astype(int)
    run_keys = np.rint(forces["time_s"] / dt).astype(int)
    common, hi, ri = np.intersect1d(host_keys, run_keys, return_indices=True)
    assert len(common) >= int(round(DURATION / dt)), f"only {len(common)} common output times"
    return (common * dt, host["fairlead_force_N"][hi], np.abs(forces[column][ri]),
            host["fairlead_tension_N"][hi])


def harmonic() -> dict:
    return {"amplitude": [AMPLITUDE, 0.0, 0.0], "period": PERIOD, "phase": 0.0}


def hosts_samples(dt: float) -> dict:
    """The host's kinematics as a motion table: the harmonic sampled at its steps, linear in between."""
    times = np.arange(int(round(DURATION / dt)) + 1) * dt
    return {"table": [[float(t), float(AMPLITUDE * math.sin(2.0 * math.pi * t / PERIOD)), 0.0, 0.0] for t in times]}


@pytest.fixture(scope="module")
def same_kinematics(work):
    return compare(work, COARSE_DT, hosts_samples(COARSE_DT), init_velocity=0, tight=True)


@pytest.fixture(scope="module")
def harmonic_fine(work):
    return compare(work, FINE_DT, harmonic(), init_velocity=1)


@pytest.fixture(scope="module")
def harmonic_coarse(work):
    return compare(work, COARSE_DT, harmonic(), init_velocity=1)


def test_the_host_ran_the_whole_motion(same_kinematics):
    t, capi, _, _ = same_kinematics
    assert abs(t[-1] - DURATION) < 1e-9
    assert np.all(np.isfinite(capi))
    # The surge moves the fairlead 2 m towards and away from the anchor: the tension must swing.
    settled = t >= SETTLED
    assert np.ptp(capi[settled]) > 0.05 * np.mean(capi[settled])


def test_with_the_hosts_kinematics_the_histories_are_the_same(same_kinematics):
    t, capi, tangle, _ = same_kinematics
    scale = np.ptp(tangle[t >= SETTLED])
    worst = int(np.argmax(np.abs(capi - tangle)))
    assert np.all(np.abs(capi - tangle) <= 1e-5 * scale), (
        f"largest difference {capi[worst] - tangle[worst]:.6g} N at t = {t[worst]:.2f} s (range {scale:.6g} N)")


def test_harmonic_tension_ranges_agree(harmonic_fine):
    t, capi, tangle, _ = harmonic_fine
    settled = t >= SETTLED
    range_capi, range_run = np.ptp(capi[settled]), np.ptp(tangle[settled])
    assert range_capi == pytest.approx(range_run, rel=1e-3), (
        f"fairlead tension range {range_capi:.6g} N (C API) vs {range_run:.6g} N (tangle run), dt = {FINE_DT} s")


def test_harmonic_tension_histories_agree(harmonic_fine):
    t, capi, tangle, _ = harmonic_fine
    scale = np.ptp(tangle[t >= SETTLED])
    worst = int(np.argmax(np.abs(capi - tangle)))
    assert np.all(np.abs(capi - tangle) <= 5e-3 * scale), (
        f"largest difference {capi[worst] - tangle[worst]:.6g} N at t = {t[worst]:.2f} s "
        f"(0.5 % of the range is {5e-3 * scale:.6g} N), dt = {FINE_DT} s")


def test_the_harmonic_difference_is_first_order_in_the_step(harmonic_coarse, harmonic_fine):
    def largest(histories):
        t, capi, tangle, _ = histories
        settled = t >= SETTLED
        return np.max(np.abs(capi - tangle)[settled])

    order = math.log(largest(harmonic_coarse) / largest(harmonic_fine)) / math.log(COARSE_DT / FINE_DT)
    assert 0.8 <= order <= 1.2, f"observed order {order:.3f} of the C API's difference from the harmonic run"

