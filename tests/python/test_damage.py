"""Fatigue and clash damage along lines in a run (issue 32; docs/theory.md 13.5, 13.6).

Run through ctest (it sets TANGLE_CLI and PYTHONPATH), or by hand:
    PYTHONPATH=build/ci/python TANGLE_CLI=build/ci/tangle /usr/bin/python3 -m pytest -q tests/python/test_damage.py

Fatigue: the scr-fatigue example.
A steel catenary riser moved at its flex joint (1.5 m heave, 1 m surge, 10 s) for 70 s; the example writes
every step to results.h5, so this test recomputes the damage from the time histories with its own
rainflow count (ASTM E1049-85, written here in Python, not the core's) and the S-N formula by hand:
- the damage along the line follows the bending stress range (largest in the touchdown zone, the classic
  SCR hot spot; the flex joint frees the top);
- at the nodes that matter, the run's damage equals the independent one within the sampling of the
  circumference: the run takes the worst of 16 points round the section, the recomputation the extreme
  fibre of the in-plane bending, so the run's stress amplitude is within cos(11.25 deg) = 0.981 of it and
  its damage (slope 3) within 0.981^3 = 0.944 (and never above it by more than the rounding of results.h5's
  single-precision histories).
"""

from __future__ import annotations

import csv
import math
import os
import subprocess
from pathlib import Path

import h5py
import numpy as np
import pytest

from tangle import statistics as st

ROOT = Path(__file__).resolve().parents[2]
CLI = os.environ.get("TANGLE_CLI", str(ROOT / "build" / "ci" / "tangle"))
MODEL = ROOT / "examples" / "scr-fatigue" / "model.yaml"
CLASH_MODEL = ROOT / "tests" / "data" / "clash-damage.yaml"

# The example's fatigue data (examples/scr-fatigue/model.yaml).
D, T, SCF = 0.2731, 0.0159, 1.2
OCCURRENCE, DFF, START = 0.1, 3.0, 20.0
# DNV-RP-C203 (2021) Table 2-2, curve E in seawater with cathodic protection (t < 25 mm: no correction).
M1, LOG_A1, M2, LOG_A2, KNEE = 3.0, 11.610, 5.0, 15.350, 1e6
RHO_G = 1025.0 * 9.80665


def rainflow(x):
    """ASTM E1049-85 5.4.4 (three-point method, half cycles kept): [(range, count)]."""
    points = []
    for v in x:  # turning points
        if points and v == points[-1]:
            continue
        if len(points) >= 2 and (points[-1] - points[-2]) * (v - points[-1]) > 0:
            points.pop()
        points.append(v)
    stack, cycles = [], []
    for p in points:
        stack.append(p)
        while len(stack) >= 3:
            x_range, y_range = abs(stack[-1] - stack[-2]), abs(stack[-2] - stack[-3])
            if x_range < y_range:
                break
            if len(stack) == 3:
                cycles.append((y_range, 0.5))
                stack.pop(0)
            else:
                cycles.append((y_range, 1.0))
                del stack[-3:-1]
    cycles += [(abs(b - a), 0.5) for a, b in zip(stack, stack[1:])]
    return cycles


def cycles_to_failure(range_pa):
    log_s = math.log10(range_pa / 1e6)
    n1 = LOG_A1 - M1 * log_s
    return 10.0 ** (n1 if n1 <= math.log10(KNEE) else LOG_A2 - M2 * log_s)


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    out = tmp_path_factory.mktemp("scr") / "results"
    done = subprocess.run([CLI, "run", str(MODEL), "-o", str(out), "--no-report"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return out


def stress_histories(run):
    """The stress at the two extreme fibres of in-plane bending at every node [time, node, fibre] after the
    start time, from results.h5 (wall tension and bending moment, the example's pipe and SCF)."""
    with h5py.File(run / "results.h5", "r") as h5:
        t = h5["/dynamics/time"][:]
        tension = h5["/dynamics/lines/riser/effective_tension"][:]
        moment = h5["/dynamics/lines/riser/bending_moment_vector"][:]
        z = h5["/dynamics/lines/riser/position"][:, :, 2]
    counted = t >= START - 1e-9
    # The riser moves in the x-z plane: the moment is about y (the rest is round-off: results.h5 stores
    # single precision, 6e-8, and the moments come from differences of rotations).
    my = moment[counted][:, :, 1].astype(float)
    out_of_plane = np.abs(moment[counted][:, :, [0, 2]]).max()
    assert out_of_plane < 1e-5 * np.abs(my).max(), out_of_plane
    di = D - 2 * T
    area = math.pi / 4 * (D * D - di * di)
    inertia = math.pi / 64 * (D**4 - di**4)
    external = math.pi / 4 * D * D  # the buoyancy diameter is the outer diameter here
    # T_w = T_e + p_i A_i - p_e A_e (Sparks 1984; the example has no contents: p_i = 0)
    wall = tension[counted].astype(float) - RHO_G * np.maximum(0.0, -z[counted]) * external
    bending = my * (D / 2) / inertia
    return SCF * np.stack([wall / area + bending, wall / area - bending], axis=2), my


def test_damage_peaks_in_the_touchdown_zone_and_follows_the_stress_range(run):
    f = st.read_fatigue(run)["riser"]
    arc, damage = f["arc_length_m"], f["damage_run"]
    stress, my = stress_histories(run)
    stress_range = (stress.max(axis=0) - stress.min(axis=0)).max(axis=1)
    bending_range = my.max(axis=0) - my.min(axis=0)
    with h5py.File(run / "results.h5", "r") as h5:
        static_moment = h5["/statics/lines/riser/bending_moment"][:]
        t = h5["/dynamics/time"][:]
        z = h5["/dynamics/lines/riser/position"][:, :, 2][t >= START - 1e-9]
    # The touchdown point at each output time: the first node more than 5 cm above its resting height
    # (centreline 0.128 m above the seabed).
    lifted = z > -300.0 + 0.128 + 0.05
    touchdown = arc[np.argmax(lifted, axis=1)]
    worst = int(np.argmax(damage))
    # The largest damage is where the stress range is largest (within one 2.5 m element) ...
    assert abs(arc[worst] - arc[int(np.argmax(stress_range))]) <= 2.5 + 1e-9
    # ... in the sag bend, where the static bending moment is within 5 % of its largest (225-320 m here: a
    # catenary's curvature w T_h / (T_h^2 + (w s)^2) falls slowly above the touchdown point); the bending
    # moment range is largest where the touchdown point moves (190-243 m); not at the flex joint (end B)
    # or the anchor (end A).
    assert static_moment[worst] >= 0.95 * static_moment.max(), (arc[worst], static_moment[worst])
    peak_bending = arc[int(np.argmax(bending_range))]
    assert touchdown.min() <= peak_bending <= touchdown.max(), (peak_bending, touchdown.min(), touchdown.max())
    assert damage[worst] > 20.0 * damage[-1] and damage[worst] > 20.0 * damage[0]
    # Damage follows the stress range along the whole line: rank correlation above 0.95 (not 1: the mean
    # stress and the cycles' mix differ from node to node; damage depends on every cycle, not the largest).
    ranks = lambda v: np.argsort(np.argsort(v))
    rho = np.corrcoef(ranks(damage), ranks(stress_range))[0, 1]
    assert rho > 0.95, rho


def test_damage_equals_an_independent_count_from_the_time_histories(run):
    f = st.read_fatigue(run)["riser"]
    stress, _ = stress_histories(run)
    order = np.argsort(f["damage_run"])[::-1]
    for node in list(order[:5]) + [len(f["damage_run"]) // 2, len(f["damage_run"]) - 1]:
        best = max(sum(n / cycles_to_failure(r) for r, n in rainflow(stress[:, node, fibre]) if r > 0)
                   for fibre in (0, 1))
        ratio = f["damage_run"][node] / best
        # Above 1 by at most the rounding of the inputs: results.h5's single precision (6e-8 on the stress,
        # times 3 to 5 in the damage) and the CSV's 7 digits.
        assert 0.944 - 1e-5 < ratio < 1.0 + 1e-5, (node, ratio)


def test_annual_damage_life_and_summary(run):
    f = st.read_fatigue(run)["riser"]
    with open(run / "fatigue" / "summary.csv", newline="") as s:
        summary = list(csv.DictReader(s))
    assert len(summary) == 1
    row = summary[0]
    duration = float(row["counted_duration_s"])
    assert duration == pytest.approx(50.0, abs=1e-9)
    factor = OCCURRENCE * 365.25 * 86400.0 / duration
    np.testing.assert_allclose(f["damage_per_year"], f["damage_run"] * factor, rtol=1e-6)
    np.testing.assert_allclose(f["life_years"], 1.0 / (DFF * f["damage_run"] * factor), rtol=1e-6)
    worst = int(np.argmax(f["damage_run"]))
    assert float(row["arc_length_m"]) == pytest.approx(f["arc_length_m"][worst])
    assert float(row["life_years"]) == pytest.approx(f["life_years"][worst], rel=1e-6)
    # results.h5 holds the same numbers.
    with h5py.File(run / "results.h5", "r") as h5:
        np.testing.assert_allclose(h5["/fatigue/riser/damage_per_year"][:], f["damage_per_year"], rtol=1e-6)
        assert h5["/fatigue/riser"].attrs["counted_duration_s"] == pytest.approx(duration)
    log = (run / "run.log").read_text()
    assert "fatigue (fatigue/)" in log and "shortest life" in log


def test_statistics_along_the_line_read_back(run):
    # dynamics/riser/statistics.csv: every node, its largest tension at least its most probable maximum's
    # mean, and the regular motion's peaks at the motion's period (10 s) where the tension follows it.
    s = st.read_line_statistics(run)["riser"]
    f = st.read_fatigue(run)["riser"]
    np.testing.assert_allclose(s["arc_length_m"], f["arc_length_m"])
    assert np.all(s["tension_max_N"] >= s["tension_mean_N"])
    top = -1  # the flex joint, moved by the motion
    assert s["tension_upcrossing_period_s"][top] == pytest.approx(10.0, rel=0.02)
    assert s["tension_peaks"][top] == 5  # 60 s after the ramp (10 s): six up-crossings, five peaks between


def test_clash_damage_bins_the_impacts_of_the_clash_report(tmp_path):
    """tests/data/clash-damage.yaml: a hose striking a pipe once a period. contact/clash_damage.csv must hold
    every impact of contact/events.csv once on each line, in the bin where it began, with its energy; and
    the same numbers in results.h5."""
    out = tmp_path / "results"
    done = subprocess.run([CLI, "run", str(CLASH_MODEL), "-o", str(out), "--no-report"], capture_output=True,
                          text=True)
    assert done.returncode == 0, done.stderr
    with open(out / "contact" / "events.csv", newline="") as f:
        events = list(csv.DictReader(f))
    with open(out / "contact" / "clash_damage.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    impacts = [e for e in events if e["kind"].startswith("impact")]
    assert len(impacts) >= 2, [e["kind"] for e in events]  # the hose strikes every period after the ramp
    bin_length, threshold = 3.0, 5.0
    for line in ("pipe", "hose"):
        bins = [r for r in rows if r["line"] == line]
        assert len(bins) == 7  # 20 m in 3 m bins, the last 2 m
        assert float(bins[-1]["from_m"]) == 18.0 and float(bins[-1]["to_m"]) == 20.0
        expected_count = [0] * 7
        expected_energy = [0.0] * 7
        expected_above = [0] * 7
        for e in impacts:
            on_a = e["line_1"] == line
            arc = float(e["arc_1_start_m" if on_a else "arc_2_start_m"])
            k = min(int(arc // bin_length), 6)
            energy = float(e["impact_energy_J"])
            expected_count[k] += 1
            expected_energy[k] += energy
            expected_above[k] += energy > threshold
        assert [int(r["impacts"]) for r in bins] == expected_count
        assert [int(r["impacts_above_5_J"]) for r in bins] == expected_above
        np.testing.assert_allclose([float(r["energy_J"]) for r in bins], expected_energy, rtol=1e-5, atol=1e-9)
        # Both lines are struck near their mid-spans (10 m): the bin [9, 12).
        assert expected_count[3] == len(impacts)
    with h5py.File(out / "results.h5", "r") as h5:
        np.testing.assert_array_equal(h5["/contact/clash_damage/hose/impacts"][:],
                                      [int(r["impacts"]) for r in rows if r["line"] == "hose"])
    assert "clash damage (contact/clash_damage.csv)" in (out / "run.log").read_text()


def test_a_batch_of_sea_states_sums_their_damage_per_year(tmp_path):
    """`tangle batch` over two sea states of the scr-fatigue example (heave 0.75 m at 30 % of the year,
    1.5 m at 10 %): fatigue_total/riser.csv is the sum of the two cases' damage per year at every node (a
    scatter diagram's long-term damage, DNV-RP-F204 3.3), with the life 1 / (DFF D) and the larger share."""
    batch = tmp_path / "batch.yaml"
    batch.write_text(f"""
model: {MODEL}
set:
  dynamics.duration: 40
  fatigue.start_time: 15
cases:
  - name: moderate
    set: {{"lines[riser].end_b.motion.amplitude": [-0.5, 0, 0.75], "fatigue.occurrence": 0.3}}
  - name: severe
    set: {{"fatigue.occurrence": 0.1}}
""")
    out = tmp_path / "out"
    done = subprocess.run([CLI, "batch", str(batch), "-o", str(out), "-j", "2", "--no-report"], capture_output=True,
                          text=True, timeout=600)
    assert done.returncode == 0, done.stderr + done.stdout
    cases = {name: st.read_fatigue(out / "cases" / name)["riser"] for name in ("moderate", "severe")}
    with open(out / "fatigue_total" / "riser.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    total = np.array([float(r["damage_per_year"]) for r in rows])
    expected = cases["moderate"]["damage_per_year"] + cases["severe"]["damage_per_year"]
    np.testing.assert_allclose(total, expected, rtol=2e-6)  # the CSV's 7 digits, twice
    life = np.array([float(r["life_years"]) for r in rows])
    np.testing.assert_allclose(life, 1.0 / (DFF * expected), rtol=2e-6)
    larger = np.where(cases["severe"]["damage_per_year"] > cases["moderate"]["damage_per_year"], "severe", "moderate")
    assert [r["largest_sea_state"] for r in rows] == list(larger)
    assert "long-term fatigue over 2 sea state(s)" in done.stdout
