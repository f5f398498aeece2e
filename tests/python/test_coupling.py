"""tangle.Coupling: a model stepped by a host from Python (docs/moordyn.md, "C API and Python coupling").

Run through ctest (it sets TANGLE_CLI and PYTHONPATH), or by hand:
    PYTHONPATH=build/ci/python TANGLE_CLI=build/ci/tangle /usr/bin/python3 -m pytest -q tests/python/test_coupling.py

The deck tests/data/moordyn/coupled_chain.txt: one 410 m chain in 50 m of water from an anchor at
(400, 0, -50) to a coupled fairlead at the origin.
- Held still for 5 s, the force on the fairlead stays the static force `tangle run --statics-only` gives for
  that line end (summary.json `force_N`, the force the line exerts on what holds the end) within 1e-3: the
  coupling starts from the same statics and a model at rest stays at rest.
- Moved 1 m towards the anchor, the line slackens: the horizontal force drops.
- The converted YAML model with the same points gives the same forces as the deck.
- Bad input raises ModelError (files, end names), ValueError (array shapes) or RuntimeError (call order).
"""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import tangle

ROOT = Path(__file__).resolve().parents[2]
CLI = os.environ.get("TANGLE_CLI", str(ROOT / "build" / "ci" / "tangle"))
DECK = ROOT / "tests" / "data" / "moordyn" / "coupled_chain.txt"
YAML_MODEL = ROOT / "tests" / "data" / "model-reader-good.yaml"
ANCHOR_DIRECTION = np.array([1.0, 0.0, 0.0])  # from the fairlead (0, 0, 0) towards the anchor (400, 0, -50)


def run(*args) -> None:
    result = subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=500)
    assert result.returncode == 0, f"{' '.join(map(str, args))} exited {result.returncode}:\n{result.stderr}"


@pytest.fixture(scope="module")
def static_summary(tmp_path_factory):
    out = tmp_path_factory.mktemp("coupling") / "statics"
    run(CLI, "run", DECK, "-o", out, "--statics-only", "--no-plots", "--no-report", "-q")
    return json.loads((out / "summary.json").read_text())


def static_end_force(summary: dict, end_name: str) -> np.ndarray:
    """summary.json's force_N at a line end named 'line:a' / 'line:b'."""
    line, end = end_name.rsplit(":", 1)
    entry = next(l for l in summary["lines"] if l["name"] == line)
    return np.array(entry[f"end_{end}"]["force_N"], dtype=float)


def test_a_deck_couples_its_coupled_points():
    c = tangle.Coupling(DECK)
    assert c.n_points == 1
    assert len(c.points) == 1 and len(c.points[0]) == 1
    np.testing.assert_allclose(c.model_positions, [[0.0, 0.0, 0.0]], atol=1e-12)
    assert c.time == 0.0
    assert c.forces.shape == (1, 3) and not c.forces.any()


def test_held_still_the_force_stays_the_static_one(static_summary):
    c = tangle.Coupling(DECK)
    x = c.model_positions
    c.init(x)
    reference = static_end_force(static_summary, c.points[0][0])
    assert np.linalg.norm(reference) > 1e5
    assert np.linalg.norm(c.forces[0] - reference) <= 1e-3 * np.linalg.norm(reference)
    xd = np.zeros_like(x)
    for _ in range(50):
        f = c.step(x, xd, 0.1)
    assert c.time == pytest.approx(5.0, abs=1e-9)
    assert f.shape == (1, 3)
    np.testing.assert_array_equal(f, c.forces)
    assert np.linalg.norm(f[0] - reference) <= 1e-3 * np.linalg.norm(reference), (
        f"force after 5 s held still {f[0]} N, static {reference} N")
    tensions = c.line_tensions()
    line = c.points[0][0].rsplit(":", 1)[0]
    assert line in tensions and tensions[line].shape == (42,)  # 41 segments
    assert np.all(tensions[line] > 0.0)


def test_moving_towards_the_anchor_lowers_the_horizontal_force():
    c = tangle.Coupling(DECK)
    x0 = c.model_positions
    c.init(x0)
    h0 = np.hypot(*c.forces[0, :2])
    # 1 m towards the anchor over 5 s on a smooth (1 - cos) profile, then held 3 s; each step is given its
    # start position and the chord velocity to its end (the C host's convention).
    dt, ramp, hold = 0.05, 5.0, 3.0
    offset = lambda t: 0.5 * (1.0 - np.cos(np.pi * min(t, ramp) / ramp))  # noqa: E731  [m]
    for k in range(int(round((ramp + hold) / dt))):
        t = k * dt
        x = x0 + offset(t) * ANCHOR_DIRECTION
        xd = (offset(t + dt) - offset(t)) / dt * ANCHOR_DIRECTION[None, :]
        c.step(x, xd, dt)
    np.testing.assert_allclose(c.model_positions, x0 + ANCHOR_DIRECTION, atol=1e-9)
    h1 = np.hypot(*c.forces[0, :2])
    assert h1 < 0.99 * h0, f"horizontal force {h1:.6g} N after moving 1 m towards the anchor, {h0:.6g} N before"
    assert c.forces[0, 0] > 0.0  # still pulled towards the anchor


def test_the_converted_model_with_the_same_points_gives_the_same_forces(tmp_path):
    converted = tmp_path / "model.yaml"
    run(CLI, "convert", DECK, "-o", converted)
    deck = tangle.Coupling(DECK)
    model = tangle.Coupling(converted, points=deck.points)
    assert model.points == deck.points
    x = deck.model_positions
    deck.init(x)
    model.init(x)
    np.testing.assert_allclose(model.forces, deck.forces, rtol=1e-9, atol=1e-6)


def test_bad_input_raises(tmp_path):
    with pytest.raises(tangle.ModelError):
        tangle.Coupling(tmp_path / "missing.txt")
    with pytest.raises(tangle.ModelError, match="points"):
        tangle.Coupling(YAML_MODEL)  # a YAML model has no default points
    with pytest.raises(tangle.ModelError):
        tangle.Coupling(DECK, points=[["no_such_line:b"]])
    with pytest.raises(tangle.ModelError, match="line_name:a"):
        tangle.Coupling(DECK, points=[["chain:c"]])
    with pytest.raises(ValueError):
        tangle.Coupling(DECK, points=["chain:b"])  # a list of ends, not a list of points

    c = tangle.Coupling(DECK)
    x = c.model_positions
    with pytest.raises(RuntimeError):
        c.step(x, np.zeros_like(x), 0.1)  # before init
    with pytest.raises(RuntimeError):
        c.line_tensions()
    with pytest.raises(ValueError):
        c.init(np.zeros((2, 3)))
    c.init(x)
    with pytest.raises(RuntimeError):
        c.init(x)  # once only
    with pytest.raises(ValueError):
        c.step(x, np.zeros_like(x), 0.0)
    with pytest.raises(ValueError):
        c.step(x, np.zeros(4), 0.1)


def test_model_load_reads_a_deck_as_convert_writes_it() -> None:
    """tangle.Model.load on a MoorDyn deck: the converted model (docs/moordyn.md), editable and runnable."""
    model = tangle.Model.load(DECK)
    assert model.get("lines[line1].end_b.type") == "pinned"  # the coupled fairlead
    assert model.get("line_types[chain].outer_diameter") == pytest.approx(0.252)
    statics = model.run_statics()
    assert statics.converged
    lines = statics.lines if isinstance(statics.lines, dict) else {l["name"]: l for l in statics.lines}
    assert "line1" in lines


PENDULUM = """
environment: {water_depth: 100, water_density: 0, gravity: 9.81}
line_types:
  - {name: rod, outer_diameter: 0.1, mass_per_length: 20, axial_stiffness: 1.0e9, bending_stiffness: 1.0e7,
     drag_normal: 0, drag_axial: 0, added_mass_normal: 0}
vessels:
  - {name: pivot, mode: free, pinned: true, position: [0, 0, -10], mass: 1, inertia: [1, 1, 1],
     displaced_volume: 0}
lines:
  - {name: rod, end_a: {type: vessel, vessel: pivot, position: [0, 0, -2]},
     end_b: {type: vessel, vessel: pivot, position: [0, 0, -7]}, sections: [{type: rod, length: 5, elements: 5}]}
dynamics: {duration: 30, time_step: 0.01, ramp_time: 0, mass: consistent}
"""


def test_a_pinned_vessel_is_moved_by_the_host(tmp_path):
    """A pinned vessel (a 101 kg pendulum: a 100 kg rod under a 1 kg pivot) as a point ["vessel:pivot"],
    its pin's acceleration along y raised smoothly to a = 0.5 m/s^2 over 20 s (a = a0 (1 - cos(pi t / 20)) / 2,
    four times the pendulum's 4.5 s period, so it follows nearly at rest in the moving frame: a swing of
    about 1/80 of its 0.051 rad lean), then held 5 s, one host step of 0.01 s at a time. At the end the
    force on the host is that of the pendulum hanging at its lean, -M (0, a, g): 2 % along y (the residual
    swing, m d omega^2 theta = 0.5 N of 50.5 N), 0.5 % vertically (second order in the swing), and across
    within 1e-3 of M g (measured 0.07 N; 12 N with a rod 100 times stiffer: the noise of the reaction
    through the rod's stiff links grows with their stiffness); the pin ends where the host's last step put
    it."""
    model = tmp_path / "pendulum.yaml"
    model.write_text(PENDULUM)
    c = tangle.Coupling(model, points=[["vessel:pivot"]])
    assert c.points == [["vessel:pivot"]]
    assert np.allclose(c.model_positions, [[0.0, 0.0, -10.0]])
    a0, ramp, dt, total = 0.5, 20.0, 0.01, 101.0
    w = np.pi / ramp

    def pin(t: float) -> tuple[float, float]:  # y [m] and dy/dt [m/s] of the pin
        if t <= ramp:
            return (0.5 * a0 * (0.5 * t * t + (np.cos(w * t) - 1.0) / (w * w)),
                    0.5 * a0 * (t - np.sin(w * t) / w))
        y, v = pin(ramp)
        return y + v * (t - ramp) + 0.5 * a0 * (t - ramp) ** 2, v + a0 * (t - ramp)

    c.init(np.array([[0.0, 0.0, -10.0]]))
    steps = 2500
    for k in range(steps):
        y, v = pin(k * dt)
        force = c.step(np.array([[0.0, y, -10.0]]), np.array([[0.0, v, 0.0]]), dt)[0]
    assert force[0] == pytest.approx(0.0, abs=1e-3 * total * 9.81)
    assert force[1] == pytest.approx(-total * a0, rel=0.02)
    assert force[2] == pytest.approx(-total * 9.81, rel=0.005)
    y, v = pin((steps - 1) * dt)  # the host's last step: linear over it
    assert np.allclose(c.model_positions[0], [0.0, y + v * dt, -10.0], atol=1e-9)


def test_a_vessel_point_must_name_a_pinned_vessel(tmp_path):
    model = tmp_path / "pendulum.yaml"
    model.write_text(PENDULUM.replace("pinned: true, ", ""))
    with pytest.raises(tangle.ModelError, match="free and pinned"):
        tangle.Coupling(model, points=[["vessel:pivot"]])
