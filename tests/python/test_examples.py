"""The examples' results, checked by a test instead of by hand (issue 31).

Every example model in examples/ (not the batch) is run as a user runs it, through the same code as `tangle run`
(tangle.Model.run, results::RunOutputs), with the dynamics cut to their first MAX_DURATION seconds and without
the VTK files, plots and report (they are drawn from the same numbers). Every number of the run's summaries
(summary.json, dynamics/summary.json, contact/summary.json, clearance/summary.json) except timings is compared
with tests/data/examples-reference.json.

Tolerance: the runs are deterministic (same binary, same input: the same bits, measured across runs and
builds); RTOL leaves room only for the last digit of a different libm or compiler on another machine, so any
change of the physics, the solver's path or the output shows. Integers (steps, iterations, events) must match
exactly. An intended change updates the reference with

    TANGLE_UPDATE_EXAMPLES=1 PYTHONPATH=build/ci/python /usr/bin/python3 -m pytest -q tests/python/test_examples.py

and the commit says what changed and why (results bit-identical or explained).
"""

from __future__ import annotations

import csv
import json
import math
import os
from pathlib import Path
from typing import Any

import pytest

import tangle

ROOT = Path(__file__).resolve().parents[2]
REFERENCE = ROOT / "tests" / "data" / "examples-reference.json"
EXAMPLES = sorted(p.parent.name for p in (ROOT / "examples").glob("*/model.yaml"))
MAX_DURATION = 30.0  # [s] of dynamics per example: the full runs have their own regression tests
SUMMARIES = ("summary.json", "dynamics/summary.json", "contact/summary.json", "clearance/summary.json")
RTOL = 1e-9
ATOL = 1e-9  # [SI units] for values that are round-off around zero (a force component of 1e-9 N)
NOT_RESULTS = {"wall_time_s", "real_time_factor", "message", "model", "tangle_version", "seconds"}


def results_of(value: Any) -> Any:
    """The summary without timings and the model's path."""
    if isinstance(value, dict):
        return {k: results_of(v) for k, v in value.items() if k not in NOT_RESULTS}
    if isinstance(value, list):
        return [results_of(v) for v in value]
    return value


def run_example(name: str, folder: Path) -> dict[str, Any]:
    model = tangle.Model.load(ROOT / "examples" / name / "model.yaml")
    if "dynamics" in model.data and model.get("dynamics.duration") > MAX_DURATION:
        model.set("dynamics.duration", MAX_DURATION)
    model.set("output.vtk", False)
    model.run(folder, report=False, plots=False)
    return {s: results_of(json.loads((folder / s).read_text())) for s in SUMMARIES if (folder / s).exists()}


def differences(reference: Any, value: Any, where: str = "") -> list[str]:
    if isinstance(reference, dict) and isinstance(value, dict):
        out = [f"{where}.{k}: missing" for k in reference if k not in value]
        out += [f"{where}.{k}: new" for k in value if k not in reference]
        for k in reference.keys() & value.keys():
            out += differences(reference[k], value[k], f"{where}.{k}")
        return out
    if isinstance(reference, list) and isinstance(value, list):
        if len(reference) != len(value):
            return [f"{where}: {len(value)} items, reference {len(reference)}"]
        return [d for i, (a, b) in enumerate(zip(reference, value)) for d in differences(a, b, f"{where}[{i}]")]
    if isinstance(reference, float) or isinstance(value, float):
        if isinstance(reference, (int, float)) and isinstance(value, (int, float)) and not isinstance(value, bool):
            if math.isclose(value, reference, rel_tol=RTOL, abs_tol=ATOL):
                return []
    elif reference == value:
        return []
    return [f"{where}: {value!r}, reference {reference!r}"]


def malformed_tables(folder: Path) -> list[str]:
    """Issue 45: every CSV a run writes has as many fields in every row as in its header (an absent value is an
    empty field, never a missing one), and in the extreme statistics every row without a most probable maximum
    (or minimum) says why in its note column."""
    problems = []
    for path in sorted(folder.rglob("*.csv")):
        with path.open(newline="") as f:
            rows = list(csv.reader(f))
        where = path.relative_to(folder)
        if not rows:
            problems.append(f"{where}: empty")
            continue
        header = rows[0]
        for i, row in enumerate(rows[1:], start=2):
            if len(row) != len(header):
                problems.append(f"{where}:{i}: {len(row)} fields, header {len(header)}")
        if "statistics" not in path.name:
            continue
        for column, name in enumerate(header):
            if "mpm_" not in name and "mp_min_" not in name:
                continue
            note = header.index(name.split("rayleigh_")[0].split("weibull_")[0] + "note")
            for i, row in enumerate(rows[1:], start=2):
                if len(row) == len(header) and row[column] == "" and row[note] == "":
                    problems.append(f"{where}:{i}: no {name} and no note saying why")
    return problems


@pytest.fixture(scope="module")
def reference() -> dict[str, Any]:
    return json.loads(REFERENCE.read_text()) if REFERENCE.exists() else {}


def test_every_example_has_a_reference(reference: dict[str, Any]) -> None:
    if os.environ.get("TANGLE_UPDATE_EXAMPLES"):
        pytest.skip("updating the reference")
    assert EXAMPLES and sorted(reference) == EXAMPLES


@pytest.mark.parametrize("name", EXAMPLES)
def test_example_results_equal_the_reference(name: str, reference: dict[str, Any], tmp_path: Path) -> None:
    results = run_example(name, tmp_path / name)
    assert "summary.json" in results
    problems = malformed_tables(tmp_path / name)
    assert not problems, f"{name}: {len(problems)} malformed table row(s):\n" + "\n".join(problems[:40])
    if os.environ.get("TANGLE_UPDATE_EXAMPLES"):
        stored = json.loads(REFERENCE.read_text()) if REFERENCE.exists() else {}
        stored[name] = results
        REFERENCE.write_text(json.dumps(dict(sorted(stored.items())), indent=1, sort_keys=True) + "\n")
        return
    assert name in reference, f"no reference for {name}: run with TANGLE_UPDATE_EXAMPLES=1"
    found = differences(reference[name], results)
    assert not found, f"{name}: {len(found)} result(s) changed:\n" + "\n".join(found[:40])


def test_the_comparison_sees_a_change() -> None:
    # Test the test: a changed digit, a changed count and a new key are all reported.
    ref = {"lines": [{"max_tension_N": 1.0e5, "slack_events": 3}]}
    assert differences(ref, {"lines": [{"max_tension_N": 1.0e5 * (1 + 1e-6), "slack_events": 3}]})
    assert differences(ref, {"lines": [{"max_tension_N": 1.0e5, "slack_events": 4}]})
    assert differences(ref, {"lines": [{"max_tension_N": 1.0e5, "slack_events": 3, "x": 1}]})
    assert not differences(ref, {"lines": [{"max_tension_N": 1.0e5 * (1 + 1e-12), "slack_events": 3}]})
