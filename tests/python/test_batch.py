"""`tangle batch`: load cases in parallel processes and on MPI ranks (docs/batch.md).

Run through ctest (it sets TANGLE_CLI), or by hand:
    TANGLE_CLI=build/ci/tangle /usr/bin/python3 -m pytest -q tests/python/test_batch.py

The base model is the mooring example shortened to 4 s of dynamics (each case runs in about half a
second); the batch has 2 headings x 2 current speeds and a case whose model is invalid (a negative
section length), which must fail alone.
"""

from __future__ import annotations

import csv
import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
CLI = os.environ.get("TANGLE_CLI", str(ROOT / "build" / "ci" / "tangle"))
BASE = ROOT / "examples" / "mooring-dynamics" / "model.yaml"

BATCH = f"""
model: {BASE}
set:
  dynamics.duration: 4
  environment.seabed.friction_coefficient: 0.5
  environment.current: {{speed: 0.5, azimuth: 0}}
  output.vtk: false
cases:
  - name: intact
  - name: broken                               # a valid model whose dynamics cannot get past t = 0
    set: {{"dynamics.max_iterations": 1, "dynamics.min_time_step": 0.01}}
parameters:
  - {{name: heading, key: environment.current.azimuth, values: [0, 90]}}
  - {{name: current, key: environment.current.speed, values: [0.5, 1.5]}}
"""

MPI_ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")


def run(args, **kw):
    return subprocess.run(args, capture_output=True, text=True, timeout=600, **kw)


def rows(folder: Path) -> dict[str, dict[str, str]]:
    with (folder / "summary.csv").open() as f:
        return {r["case"]: r for r in csv.DictReader(f)}


@pytest.fixture(scope="module")
def batch_file(tmp_path_factory) -> Path:
    d = tmp_path_factory.mktemp("batch")
    p = d / "batch.yaml"
    p.write_text(BATCH)
    return p


def check_rows(table: dict[str, dict[str, str]]) -> None:
    assert len(table) == 8
    for heading in ("0", "90"):
        for current in ("0.5", "1.5"):
            ok = table[f"intact_heading={heading}_current={current}"]
            assert ok["status"] == "completed", ok
            assert ok["exit_code"] == "0"
            assert float(ok["mooring1_max_tension_N"]) > 1e5
            assert ok["heading"] == heading and ok["current"] == current
            bad = table[f"broken_heading={heading}_current={current}"]
            assert bad["status"].startswith("failed"), bad
            assert bad["exit_code"] == "2"
            assert "did not converge" in bad["message"], bad


def test_local_processes_and_rerun(batch_file: Path, tmp_path: Path) -> None:
    out = tmp_path / "local"
    r = run([CLI, "batch", str(batch_file), "-o", str(out), "-j", "2"])
    assert r.returncode == 2, r.stdout + r.stderr  # some cases failed, the others ran
    table = rows(out)
    check_rows(table)
    assert all(v["reused"] == "false" for v in table.values())

    # The summary equals the single runs: rerun one case's model on its own and compare.
    single = tmp_path / "single"
    case = "intact_heading=90_current=1.5"
    r1 = run([CLI, "run", str(out / "models" / f"{case}.yaml"), "-o", str(single), "--no-plots", "-q"])
    assert r1.returncode == 0, r1.stderr
    dyn = json.loads((single / "dynamics" / "summary.json").read_text())
    assert float(table[case]["mooring1_max_tension_N"]) == pytest.approx(dyn["lines"][0]["max_tension_N"], rel=1e-5)

    # One number for one quantity: every column of every case is its own summary's value (the table prints
    # 6 significant digits), also for the broken cases, whose dynamics stopped at t = 0 with a summary.
    for name, row in table.items():
        own = json.loads((out / "cases" / name / "dynamics" / "summary.json").read_text())["lines"][0]
        for column, key in (("max_tension_N", "max_tension_N"), ("min_tension_N", "min_tension_N"),
                            ("end_a_max_tension_N", "end_a_max_tension_N"),
                            ("end_b_max_tension_N", "end_b_max_tension_N"), ("slack_events", "slack_events")):
            assert float(row["mooring1_" + column]) == pytest.approx(own[key], rel=1e-5, abs=1e-3), (name, column)
        # The line's maximum includes its ends.
        assert own["max_tension_N"] >= max(own["end_a_max_tension_N"], own["end_b_max_tension_N"])

    # A rerun skips the finished cases and runs the failed ones again.
    stamp = (out / "cases" / case / "summary.json").stat().st_mtime_ns
    r2 = run([CLI, "batch", str(batch_file), "-o", str(out)])
    assert r2.returncode == 2
    assert "4 already done, 4 to run" in r2.stdout, r2.stdout
    again = rows(out)
    check_rows(again)
    assert again[case]["reused"] == "true"
    assert again["broken_heading=0_current=0.5"]["reused"] == "false"
    assert again[case]["mooring1_max_tension_N"] == table[case]["mooring1_max_tension_N"]
    assert (out / "cases" / case / "summary.json").stat().st_mtime_ns == stamp


@pytest.mark.skipif(shutil.which("mpirun") is None, reason="mpirun (openmpi-bin) not installed")
def test_columns_stay_when_every_case_fails(tmp_path: Path) -> None:
    """A batch whose every case fails has the same columns as one that runs: they come from the models."""
    batch = tmp_path / "batch.yaml"
    batch.write_text(f"""
model: {BASE}
set:
  dynamics.duration: 4
  dynamics.max_iterations: 1
  dynamics.min_time_step: 0.01
  environment.current: {{speed: 0.5, azimuth: 0}}
  output.vtk: false
parameters:
  - {{name: current, key: environment.current.speed, values: [0.5, 1.5]}}
""")
    out = tmp_path / "out"
    r = run([CLI, "batch", str(batch), "-o", str(out), "-j", "2"])
    assert r.returncode == 2, r.stdout + r.stderr
    with (out / "summary.csv").open() as f:
        reader = csv.DictReader(f)
        table = list(reader)
        header = reader.fieldnames
    assert len(table) == 2 and all(row["status"].startswith("failed") for row in table), table
    for column in ("mooring1_max_tension_N", "mooring1_min_tension_N", "mooring1_end_a_max_tension_N",
                   "mooring1_end_b_max_tension_N", "mooring1_slack_events", "max_offset_m"):
        assert column in header


def test_mpi_ranks_share_the_cases(batch_file: Path, tmp_path: Path) -> None:
    local = tmp_path / "local"
    assert run([CLI, "batch", str(batch_file), "-o", str(local), "-j", "1", "-q"]).returncode == 2
    out = tmp_path / "mpi"
    r = run(["mpirun", "-np", "2", "--oversubscribe", CLI, "batch", str(batch_file), "-o", str(out)], env=MPI_ENV)
    assert r.returncode == 2, r.stdout + r.stderr
    table = rows(out)
    check_rows(table)
    # Both ranks ran cases (rank 0 between dispatches, rank 1 on request).
    assert {v["rank"] for v in table.values()} == {"0", "1"}, table
    # Same results as the one-process batch.
    for name, row in rows(local).items():
        assert table[name]["mooring1_max_tension_N"] == row["mooring1_max_tension_N"], name


def test_bad_batch_file_names_file_and_key(tmp_path: Path) -> None:
    p = tmp_path / "bad.yaml"
    p.write_text(f"model: {BASE}\nparameters:\n  - {{name: h, key: environment.curent.azimuth, values: [0]}}\n"
                 f"  - {{name: l, key: 'lines[nosuchline].length', values: [1]}}\n")
    r = run([CLI, "batch", str(p), "-o", str(tmp_path / "out")])
    assert r.returncode == 1
    assert str(p) in r.stderr and "nosuchline" in r.stderr and "mooring1" in r.stderr, r.stderr
    assert not (tmp_path / "out").exists()
    # A typo in a key path is refused before any case runs (issue 30: every case failed with "bad input").
    p.write_text(f"model: {BASE}\nparameters:\n  - {{name: h, key: environment.curent.azimuth, values: [0, 90]}}\n")
    r = run([CLI, "batch", str(p), "-o", str(tmp_path / "out")])
    assert r.returncode == 1
    assert str(p) in r.stderr and "curent" in r.stderr and "h=0" in r.stderr, r.stderr
    assert not (tmp_path / "out").exists()
    p.write_text(f"model: {BASE}\nparameter: []\n")
    r = run([CLI, "batch", str(p)])
    assert r.returncode == 1 and "parameter" in r.stderr and "one of the keys" in r.stderr, r.stderr


SEED_BATCH = f"""
model: {BASE}
set:
  dynamics.duration: 20
  output.vtk: false
  environment.waves: {{type: jonswap, significant_height: 6, peak_period: 10, azimuth: 0}}
parameters:
  - {{name: heading, key: environment.waves.azimuth, values: [0, 90]}}
seeds: [1, 2, 3]
statistics: {{probability: 0.9}}
"""


def test_seeds_give_statistics_over_the_seeds(tmp_path: Path) -> None:
    # Issue 32: every case repeated per JONSWAP seed, and summary_statistics.csv with the seeds' maxima,
    # their mean and standard deviation and the Gumbel fit (method of moments, theory 13.4), checked against
    # numpy on the maxima of summary.csv (printed to 6 digits there: rel 1e-5).
    p = tmp_path / "seeds.yaml"
    p.write_text(SEED_BATCH)
    out = tmp_path / "out"
    r = run([CLI, "batch", str(p), "-o", str(out), "-j", "2", "--no-report"])
    assert r.returncode == 0, r.stdout + r.stderr
    table = rows(out)
    assert sorted(table) == sorted(f"heading={h}_seed={s}" for h in (0, 90) for s in (1, 2, 3))
    # Issue 45: the terminal's statistics in kN, as the summary table beside them (the file stays in N).
    printed = [ln for ln in r.stdout.splitlines() if "mooring1_end_b_max_tension [kN]" in ln]
    assert len(printed) == 2, r.stdout
    assert "mooring1_end_b_max_tension_N " not in r.stdout
    with (out / "summary_statistics.csv").open() as f:
        stats = {(s["case"], s["quantity"]): s for s in csv.DictReader(f)}
    import numpy as np
    for h in (0, 90):
        s = stats[(f"heading={h}", "mooring1_end_b_max_tension_N")]
        assert s["heading"] == str(h) and s["seeds"] == "3" and s["completed_seeds"] == "3"
        maxima = np.array([float(v) for v in s["maxima"].split(";")])
        from_summary = np.array([float(table[f"heading={h}_seed={k}"]["mooring1_end_b_max_tension_N"]) for k in (1, 2, 3)])
        np.testing.assert_allclose(maxima, from_summary, rtol=1e-5)
        assert len(set(maxima)) == 3  # the seed changes the sea
        mean, sd = maxima.mean(), maxima.std(ddof=1)
        scale = sd * np.sqrt(6.0) / np.pi
        mode = mean - 0.5772156649015329 * scale
        # The maxima are printed to 7 digits (half a unit: 5e-7 of the value): the statistics of the printed
        # maxima agree with the file's (computed from the unrounded ones) to a few of those units.
        tol = 2e-6 * maxima.max()
        assert float(s["mean"]) == pytest.approx(mean, abs=tol)
        assert float(s["standard_deviation"]) == pytest.approx(sd, abs=tol)
        assert float(s["gumbel_scale"]) == pytest.approx(scale, abs=tol)
        assert float(s["most_probable_maximum"]) == pytest.approx(mode, abs=tol)
        assert float(s["value_at_90_percent"]) == pytest.approx(mode - scale * np.log(-np.log(0.9)), abs=2 * tol)
        line = next(ln for ln in printed if ln.startswith(f"heading={h} "))
        assert float(line.split()[-3]) == pytest.approx(float(s["mean"]) / 1000.0, rel=1e-5), line
    # Seeds need an irregular sea: the base model without one is refused before anything runs.
    p.write_text(f"model: {BASE}\nseeds: [1, 2]\n")
    r = run([CLI, "batch", str(p), "-o", str(tmp_path / "bad")])
    assert r.returncode == 1 and "seeds" in r.stderr and "jonswap" in r.stderr, r.stderr
    p.write_text(f"model: {BASE}\nseeds: [1]\n")
    r = run([CLI, "batch", str(p), "-o", str(tmp_path / "bad")])
    assert r.returncode == 1 and "at least two seeds" in r.stderr, r.stderr


BREAK_BATCH = f"""
model: {BASE}
set:
  dynamics.duration: 4
  output.vtk: false
break_each:
  lines: [mooring1]
  failure: {{time: 2, at: end_b}}
"""


def test_break_each_runs_the_intact_case_and_each_line_broken(tmp_path: Path) -> None:
    """The accidental limit state (docs/batch.md `break_each`): the intact case and one case per broken line,
    the break in the case's own dynamics summary and log; an unknown line is an error of the batch file."""
    p = tmp_path / "break.yaml"
    p.write_text(BREAK_BATCH)
    out = tmp_path / "out"
    r = run([CLI, "batch", str(p), "-o", str(out), "-j", "2"])
    assert r.returncode == 0, r.stdout + r.stderr
    table = rows(out)
    assert set(table) == {"intact", "broken=mooring1"}
    assert all(row["status"] == "completed" for row in table.values()), table
    intact = json.loads((out / "cases" / "intact" / "dynamics" / "summary.json").read_text())
    broken = json.loads((out / "cases" / "broken=mooring1" / "dynamics" / "summary.json").read_text())
    assert intact["line_failures"] == []
    [b] = broken["line_failures"]
    assert b["line"] == "mooring1" and b["trigger"] == "time" and b["time_s"] == pytest.approx(2.0, abs=1e-9)
    # Parted in its last element (end B, the fairlead): from there on the fairlead holds nothing.
    assert 0.0 < b["parted_from_m"] < b["parted_to_m"]
    log = (out / "cases" / "broken=mooring1" / "run.log").read_text()
    assert "line 'mooring1' parted at t = 2 s" in log, log
    with (out / "cases" / "broken=mooring1" / "dynamics" / "end_forces.csv").open() as f:
        after = [r for r in csv.DictReader(f) if float(r["time_s"]) > 2.0 + 1e-9]
    assert after and all(float(r["mooring1_end_b_tension_N"]) == 0.0 for r in after)

    p.write_text(BREAK_BATCH.replace("[mooring1]", "[mooring1, nosuchline]"))
    r = run([CLI, "batch", str(p), "-o", str(tmp_path / "bad")])
    assert r.returncode == 1
    assert "break_each" in r.stderr and "nosuchline" in r.stderr, r.stderr
