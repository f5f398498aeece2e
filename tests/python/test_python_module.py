"""The Python module `tangle` (docs/python.md) against the command line on the same models.

Run through ctest (it sets PYTHONPATH to <build>/python and TANGLE_CLI), or by hand:
    PYTHONPATH=build/ci/python TANGLE_CLI=build/ci/tangle /usr/bin/python3 -m pytest -q tests/python/test_python_module.py

Reference: the CLI's CSV files of the same model. Both sides run the same solver code on the same input,
so they agree to the CSV's printed precision (7 significant digits for forces, 1e-6 m for positions):
the tolerances are the rounding of the CSV, not a physical tolerance.
"""

from __future__ import annotations

import csv
import json
import math
import os
import subprocess
import threading
from pathlib import Path

import numpy as np
import pytest

import tangle

ROOT = Path(__file__).resolve().parents[2]
CLI = os.environ.get("TANGLE_CLI", str(ROOT / "build" / "ci" / "tangle"))
MOORING = ROOT / "examples" / "mooring-dynamics" / "model.yaml"
CONTACT = ROOT / "examples" / "risers-in-contact" / "model.yaml"

RTOL = 1e-6   # %.6e in the CSV: 7 significant digits
POS_ATOL = 1e-6  # %.6f in the CSV [m]


def read_csv(path: Path) -> tuple[list[str], np.ndarray]:
    with path.open() as f:
        rows = list(csv.reader(f))
    return rows[0], np.array([[float(v) for v in r] for r in rows[1:]])


def cli_run(model: tangle.Model, out: Path) -> Path:
    path = out.with_suffix(".yaml")
    model.save(path)
    r = subprocess.run([CLI, "run", str(path), "-o", str(out), "--no-plots", "-q"], capture_output=True, text=True,
                       timeout=600)
    assert r.returncode == 0, r.stderr
    return out


@pytest.fixture(scope="module")
def mooring() -> tangle.Model:
    m = tangle.Model.load(MOORING)
    m.set("dynamics.duration", 12)  # through the end of the 10 s ramp: tensions vary
    m.set("output.vtk", False)
    return m


def test_load_get_set_and_reader_errors(tmp_path: Path) -> None:
    m = tangle.Model.load(MOORING)
    assert m.get("environment.water_depth") == 345
    assert m.get("lines[mooring1].end_b.type") == "pinned"
    assert m.get("line_types[0].name") == "chain76"
    before = m.get("environment")
    with pytest.raises(tangle.ModelError, match=r"environment\.water_depth.*expected a number > 0") as e:
        m.set("environment.water_depth", -5)
    assert isinstance(e.value, ValueError)
    assert m.get("environment") == before  # unchanged after a refused change
    with pytest.raises(tangle.ModelError, match=r"lines\[nosuch\].*one of: mooring1"):
        m.set("lines[nosuch].length", 3)
    with pytest.raises(tangle.ModelError, match=r"unknown key|not a known key|one of"):
        m.set("environment.curent", {"speed": 1.0, "azimuth": 0})
    # Direct edits of data are checked at the run, with the reader's message.
    bad = m.copy()
    bad.data["line_types"][0]["axial_stiffness"] = "stiff"
    with pytest.raises(tangle.ModelError, match=r"line_types\[chain76\]\.axial_stiffness"):
        bad.run_statics()
    with pytest.raises(tangle.ModelError, match="cannot read"):
        tangle.Model.load(tmp_path / "missing.yaml")
    with pytest.raises(TypeError):
        m.set("title", object())


def test_model_from_a_dict_runs_like_the_file() -> None:
    from_file = tangle.Model.load(MOORING)
    from_dict = tangle.Model(from_file.data, "dict model")
    a = from_file.run_statics()
    b = from_dict.run_statics()
    for key in ("effective_tension_N", "position_m"):
        np.testing.assert_array_equal(a.lines["mooring1"][key], b.lines["mooring1"][key])


def test_statics_and_dynamics_equal_the_cli(mooring: tangle.Model, tmp_path: Path) -> None:
    out = cli_run(mooring, tmp_path / "cli")
    statics = mooring.run_statics()
    assert statics.converged
    header, table = read_csv(out / "statics" / "mooring1.csv")
    col = {h: i for i, h in enumerate(header)}
    line = statics.lines["mooring1"]
    np.testing.assert_allclose(line["arc_length_m"], table[:, col["arc_length_m"]], atol=POS_ATOL)
    np.testing.assert_allclose(line["position_m"], table[:, [col["x_m"], col["y_m"], col["z_m"]]], atol=POS_ATOL)
    np.testing.assert_allclose(line["effective_tension_N"], table[:, col["effective_tension_N"]], rtol=RTOL)

    calls: list[tuple[float, float]] = []
    run = mooring.run_dynamics(progress=lambda t, T: calls.append((t, T)))
    assert run.completed and not run.interrupted
    _, tension = read_csv(out / "dynamics" / "mooring1" / "effective_tension_N.csv")
    np.testing.assert_allclose(run.time_s, tension[:, 0], atol=1e-6)
    np.testing.assert_allclose(run.lines["mooring1"]["effective_tension_N"], tension[:, 1:], rtol=RTOL)
    _, x = read_csv(out / "dynamics" / "mooring1" / "x_m.csv")
    # x_m.csv prints 7 significant digits (%.6e), the statics table 1e-6 m (%.6f).
    np.testing.assert_allclose(run.lines["mooring1"]["position_m"][:, :, 0], x[:, 1:], rtol=RTOL, atol=POS_ATOL)
    # End angles and the equilibrium audit, as the CLI's summary.json.
    static_summary = json.loads((out / "summary.json").read_text())
    for end in ("a", "b"):
        angles = statics.end_angles("mooring1", end)
        cli_end = static_summary["lines"][0][f"end_{end}"]
        for key in ("angle_from_horizontal_deg", "angle_from_vertical_deg"):
            assert angles[key] == pytest.approx(cli_end[key], rel=1e-9, abs=1e-9), (end, key)
    assert [b["name"] for b in statics.equilibrium_audit] == ["mooring1"]
    audit = static_summary["equilibrium_audit"]["lines"][0]
    assert statics.equilibrium_audit[0]["relative_residual"] <= statics.equilibrium_audit[0]["tolerance"]
    assert statics.equilibrium_audit[0]["relative_residual"] == pytest.approx(audit["relative_residual"], abs=1e-12)
    header, ends = read_csv(out / "dynamics" / "end_forces.csv")
    col = {h: i for i, h in enumerate(header)}
    np.testing.assert_allclose(run.lines["mooring1"]["end_tension_N"][:, 1], ends[:, col["mooring1_end_b_tension_N"]],
                               rtol=RTOL)
    np.testing.assert_allclose(run.lines["mooring1"]["end_force_N"][:, 0, 0], ends[:, col["mooring1_end_a_fx_N"]],
                               rtol=RTOL, atol=1e-6 * np.abs(ends[:, col["mooring1_end_a_fx_N"]]).max())
    header, rng = read_csv(out / "dynamics" / "mooring1" / "range.csv")
    col = {h: i for i, h in enumerate(header)}
    graph = run.range_graph("mooring1", "effective_tension")
    for k in ("min", "max", "mean"):
        np.testing.assert_allclose(graph[k], rng[:, col[f"tension_{k}_N"]], rtol=RTOL)
    # Progress at every output time, with the duration.
    assert len(calls) == len(run.time_s) and calls[-1] == pytest.approx((12.0, 12.0))
    # The solver counters, as the CLI's dynamics/summary.json (the same iterations: the same results).
    summary = json.loads((out / "dynamics" / "summary.json").read_text())
    for key in ("newton_iterations", "newton_iterations_on_parts", "matrix_refreshes", "block_refreshes",
                "fallback_steps", "unload_rejections", "converged_blocks_left_out"):
        assert getattr(run, key) == summary[key], key
    assert run.matrix_refreshes > 0


def test_contact_events_and_clearance_equal_the_cli(tmp_path: Path) -> None:
    m = tangle.Model.load(CONTACT)
    m.set("dynamics.duration", 5)
    m.set("output.vtk", False)
    out = cli_run(m, tmp_path / "cli")
    run = m.run_dynamics()
    with (out / "contact" / "events.csv").open() as f:
        events = list(csv.DictReader(f))
    assert len(run.contact_events) == len(events) > 0
    for mine, ref in zip(run.contact_events, events):
        assert (mine["line_1"], mine["line_2"], mine["kind"]) == (ref["line_1"], ref["line_2"], ref["kind"])
        assert mine["peak_force_N"] == pytest.approx(float(ref["peak_force_N"]), rel=RTOL)
        assert mine["start_time_s"] == pytest.approx(float(ref["start_time_s"]), abs=1e-6)
    with (out / "clearance" / "envelope.csv").open() as f:
        env = [r for r in csv.DictReader(f)]
    first = run.clearance[0]
    ref = [r for r in env if r["line"] == first["line"] and r["other_line"] == first["other_line"]]
    np.testing.assert_allclose(first["min_clearance_m"], [float(r["min_clearance_m"]) for r in ref], rtol=RTOL,
                               atol=1e-9)


def test_progress_exception_stops_the_run_and_keeps_the_results(mooring: tangle.Model) -> None:
    class Stop(Exception):
        pass

    def progress(t: float, duration: float) -> None:
        if t >= 3.0:
            raise Stop()

    with pytest.raises(tangle.Interrupted) as e:
        mooring.run_dynamics(progress)
    assert isinstance(e.value.__cause__, Stop)
    partial = e.value.results
    assert partial.interrupted and not partial.completed
    assert 3.0 <= partial.time_s[-1] < 3.5
    assert partial.lines["mooring1"]["effective_tension_N"].shape[0] == len(partial.time_s)


def test_threads_run_side_by_side(mooring: tangle.Model) -> None:
    serial = mooring.run_dynamics()
    models = [mooring.copy() for _ in range(2)]
    results: list = [None, None]

    def work(i: int) -> None:
        results[i] = models[i].run_dynamics()

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for r in results:
        np.testing.assert_array_equal(r.lines["mooring1"]["effective_tension_N"],
                                      serial.lines["mooring1"]["effective_tension_N"])


def test_the_gil_is_released_during_a_run(mooring: tangle.Model) -> None:
    # While a run holds the GIL no other Python thread can execute a single bytecode: the main thread's
    # counter would stay near zero for the whole run.
    worker = threading.Thread(target=mooring.run_dynamics)
    worker.start()
    count = 0
    while worker.is_alive():
        count += 1
    worker.join()
    assert count > 10000


def model_that_stops_early() -> tangle.Model:
    """A wire whose end is thrown 40 m at 1 Hz, with no room to cut the step back (min_time_step =
    time_step): the first step cannot converge."""
    return tangle.Model({
        "title": "a run that cannot finish",
        "environment": {"water_depth": 100},
        "line_types": [{"name": "wire", "outer_diameter": 0.05, "mass_per_length": 10, "axial_stiffness": 1e8}],
        "lines": [{"name": "wire",
                   "end_a": {"type": "anchored", "position": [0, 0, -100]},
                   "end_b": {"type": "pinned", "position": [90, 0, -10],
                             "motion": {"amplitude": [40, 0, 0], "period": 1}},
                   "sections": [{"type": "wire", "length": 140, "elements": 20}]}],
        "dynamics": {"duration": 5, "time_step": 0.1, "min_time_step": 0.1, "ramp_time": 0},
    }, "stops early (test)")


def test_a_run_that_stops_early_raises_with_its_results() -> None:
    # A wire whose end is thrown 40 m at 1 Hz, with no room to cut the step back (min_time_step =
    # time_step): the step cannot converge. The run must raise, not return with completed = False.
    m = model_that_stops_early()
    with pytest.raises(tangle.DynamicsFailed) as e:
        m.run_dynamics()
    assert isinstance(e.value, tangle.ConvergenceError)
    partial = e.value.results
    assert not partial.completed and not partial.interrupted
    assert partial.message and str(e.value) == partial.message
    assert partial.time_s[-1] < 5.0


def test_results_at_an_arc_length(mooring: tangle.Model) -> None:
    # Linear interpolation between the nodes around the arc length: exact at a node, the mean halfway.
    statics = mooring.run_statics()
    line = statics.lines["mooring1"]
    arc, tension = line["arc_length_m"], line["effective_tension_N"]
    assert statics.at("mooring1", "effective_tension_N", arc[7]) == pytest.approx(tension[7], rel=1e-15)
    half = 0.5 * (arc[7] + arc[8])
    assert statics.at("mooring1", "effective_tension_N", half) == pytest.approx(0.5 * (tension[7] + tension[8]))
    np.testing.assert_allclose(statics.at("mooring1", "position_m", half),
                               0.5 * (line["position_m"][7] + line["position_m"][8]))
    with pytest.raises(ValueError, match="outside line"):
        statics.at("mooring1", "effective_tension_N", arc[-1] + 1.0)
    run = mooring.run_dynamics()
    d = run.lines["mooring1"]
    history = run.time_history("mooring1", "effective_tension_N", half)
    assert history.shape == run.time_s.shape
    np.testing.assert_allclose(history, 0.5 * (d["effective_tension_N"][:, 7] + d["effective_tension_N"][:, 8]))
    assert run.time_history("mooring1", "position_m", arc[3]).shape == (len(run.time_s), 3)
    with pytest.raises(KeyError):
        run.time_history("mooring1", "end_tension_N", 0.0)


def test_run_into_a_folder_writes_what_the_cli_writes(mooring: tangle.Model, tmp_path: Path) -> None:
    # Model.run(folder) is the command line's run (results::RunOutputs): the same files with the same
    # content, results.h5 and report.html included. Timing fields and the log's wording aside, byte for byte.
    import h5py

    cli = cli_run(mooring, tmp_path / "cli")
    py = mooring.run(tmp_path / "py")
    assert py == tmp_path / "py"
    skip = {"run.log", "tangle-run.json", "model.yaml", "report.html", "report/data.json"}
    cli_files = sorted(str(p.relative_to(cli)) for p in cli.rglob("*") if p.is_file() and "plots" not in p.parts)
    py_files = sorted(str(p.relative_to(py)) for p in py.rglob("*") if p.is_file() and "plots" not in p.parts)
    assert py_files == cli_files
    for name in cli_files:
        if name in skip or name.endswith(".h5") or name.endswith("summary.json"):
            continue
        assert (py / name).read_bytes() == (cli / name).read_bytes(), name
    # The model is named by its source; the wall time (also in the message) is the machine's.
    timing = {"wall_time_s", "real_time_factor", "model", "message"}
    for name in ("summary.json", "dynamics/summary.json"):
        a = json.loads((cli / name).read_text())
        b = json.loads((py / name).read_text())
        assert {k: v for k, v in a.items() if k not in timing} == {k: v for k, v in b.items() if k not in timing}
        assert a.get("message", "").split(" wall time")[0].rsplit(",", 1)[0] == b.get("message", "").split(" wall time")[0].rsplit(",", 1)[0]
    with h5py.File(cli / "results.h5") as a, h5py.File(py / "results.h5") as b:
        names: list[str] = []
        a.visit(lambda n: names.append(n) if isinstance(a[n], h5py.Dataset) else None)
        assert names and "dynamics/lines/mooring1/effective_tension" in names
        for n in names:
            np.testing.assert_array_equal(a[n][()], b[n][()], err_msg=n)
    assert (py / "report.html").stat().st_size > 0
    assert json.loads((py / "tangle-run.json").read_text())["status"] == "completed"
    # A second run into the same folder is refused unless asked to replace it.
    with pytest.raises(tangle.ModelError, match="already holds files"):
        mooring.run(tmp_path / "py")
    assert mooring.run(tmp_path / "py", overwrite=True, report=False) == tmp_path / "py"
    assert not (py / "report.html").exists()


def test_a_run_into_a_folder_that_stops_early_raises_and_keeps_its_results(tmp_path: Path) -> None:
    m = model_that_stops_early()
    with pytest.raises(tangle.ConvergenceError, match="failed: dynamics stopped"):
        m.run(tmp_path / "out")
    assert json.loads((tmp_path / "out" / "tangle-run.json").read_text())["status"].startswith("failed: dynamics")
    summary = json.loads((tmp_path / "out" / "dynamics" / "summary.json").read_text())
    assert not summary["completed"] and summary["end_time_s"] < 5.0 and "did not converge" in summary["message"]
    assert (tmp_path / "out" / "results.h5").exists()


def test_design_statistics_functions() -> None:
    # The compiled core's statistics from Python (tests/unit/analysis/FatigueStatisticsTest.cpp holds the
    # physics checks): ASTM E1049-85 Fig. 6, DNV-RP-C203 curve D by hand, a Gumbel fit by hand.
    from tangle import statistics as st

    cycles = tangle.rainflow(np.array([-2, 1, -3, 5, -1, 3, -4, 4, -2], dtype=float))
    counts: dict[float, float] = {}
    for rng, _, count in cycles:
        counts[rng] = counts.get(rng, 0.0) + count
    assert counts == {3.0: 0.5, 4.0: 1.5, 6.0: 0.5, 8.0: 1.0, 9.0: 0.5}
    curve = st.SnCurve.dnv_d()
    assert curve.cycles_to_failure(100e6) == pytest.approx(10 ** 6.164, rel=1e-12)
    assert st.miner_damage(np.array([[100e6, 0.0, 1000.0]]), curve) == pytest.approx(1000 / 10 ** 6.164, rel=1e-12)
    assert st.chain_damage(np.array([[0.5e6, 0.0, 1e6]]), 1e7) == pytest.approx(1e6 * 0.05 ** 3 / 316, rel=1e-12)
    g = st.gumbel_fit([10, 12, 11, 13, 14])
    assert g.mode == pytest.approx(11.288403397945563, abs=1e-12)
    assert g.quantile(0.9) == pytest.approx(14.062676240597945, abs=1e-12)
    # A regular wave of unit amplitude: every peak is 1, the storm's most probable maximum too.
    t = np.arange(0.0, 600.0, 0.05)
    e = st.extreme_estimate(t, np.sin(2 * np.pi * t / 10.0), storm_duration_s=3 * 3600.0)
    assert e.upcrossing_period_s == pytest.approx(10.0, rel=1e-3)
    assert e.peaks == pytest.approx(np.ones_like(e.peaks), abs=1e-3)
    assert e.rayleigh_sigma == pytest.approx(1 / np.sqrt(2), rel=1e-3)
    with pytest.raises(ValueError, match="up-crossings"):
        st.extreme_estimate(t, t)


def test_extreme_statistics_of_a_run_equal_the_library_on_its_own_history(tmp_path: Path) -> None:
    # dynamics/statistics.csv (theory 13.3) is the library's estimate on the end tension at every step after
    # the ramp (PeakTracker: turning points, time-weighted mean): recomputed here with tangle.statistics from
    # dynamics/end_forces.csv written at every step (printed to 7 digits). The fairlead held still in a
    # JONSWAP sea (6 m, 10 s): a wave-driven response, 235 s after the ramp. The run writes its fits only where
    # they are credible (issue 45: 20 peaks or more, a Weibull shape in [1.5, 3], a stationary record), else a
    # note saying why; this record's peaks fit a Weibull of shape 0.68 (a long tail), so the note must give the
    # library's shape, and the most probable maxima are compared with the library's own fits of the record.
    from tangle import statistics as st

    m = tangle.Model.load(MOORING)
    m.set("lines[mooring1].end_b.motion", {"amplitude": [0, 0, 0], "period": 10})
    m.set("environment.waves", {"type": "jonswap", "significant_height": 6, "peak_period": 10, "azimuth": 0})
    m.set("dynamics.duration", 240)
    m.set("dynamics.time_step", 0.05)
    m.set("dynamics.output_interval", 0.05)
    m.set("output.vtk", False)
    m.set("output.storm_duration", 7200)
    out = m.run(tmp_path / "run", report=False)
    header, ends = read_csv(out / "dynamics" / "end_forces.csv")
    col = {h: i for i, h in enumerate(header)}
    after = ends[:, 0] >= m.get("dynamics.ramp_time") - 1e-9
    with (out / "dynamics" / "statistics.csv").open() as f:
        rows = {r["end"]: r for r in csv.DictReader(f)}
    b = rows["B"]
    e = st.extreme_estimate(ends[after, 0], ends[after, col["mooring1_end_b_tension_N"]], storm_duration_s=7200)
    assert abs(int(b["samples"]) - int(after.sum())) <= 1  # the step at the ramp's end: a rounding of time
    # The same peaks (the largest values between up-crossings: exact, to the CSV's digits) ...
    assert int(b["peaks"]) == len(e.peaks) >= 20
    assert float(b["storm_duration_s"]) == 7200
    # ... the same mean (time-weighted by the trapezoid rule against the samples' mean: 1/n apart at the ends)
    # and so the same fits; Tz within 2 %: the run interpolates each up-crossing between the turning points
    # around it, not between samples, which moves the first and last crossing by up to a quarter period over
    # ~30 periods; the most probable maxima within 0.5 % (2 % on Tz is 0.3 % on ln N); the Weibull shape
    # within 1 %: its least-squares fit on ln(peak - mean) is sensitive to the mean through the smallest
    # excesses (0.6 % here for the means' 1e-5).
    assert float(b["mean_N"]) == pytest.approx(e.mean, rel=1e-4)
    assert float(b["upcrossing_period_s"]) == pytest.approx(e.upcrossing_period_s, rel=2e-2)
    # The Rayleigh sigma (sigma^2 = sum a^2 / 2n, a the peaks' excess over the mean) moves with the mean by
    # d sigma / d mean = -sum a / (2 n sigma), at most 1/sqrt(2) in size (Cauchy-Schwarz): here the response is
    # 90 N about a 200 kN mean, where the means' end effect (0.016 N in a run) moves sigma by 1.3e-4 (0.012 N).
    if b["note"]:
        assert b["note"].startswith("Weibull shape") and not 1.5 <= e.weibull_shape <= 3.0, b["note"]
        assert float(b["note"].split()[2]) == pytest.approx(e.weibull_shape, abs=0.01 + 1e-2 * e.weibull_shape)
        assert b["rayleigh_mpm_N"] == b["weibull_mpm_N"] == b["weibull_shape"] == ""
        return
    sigma_tolerance = 1e-4 * e.rayleigh_sigma + abs(float(b["mean_N"]) - e.mean) / math.sqrt(2.0)
    assert float(b["rayleigh_sigma_N"]) == pytest.approx(e.rayleigh_sigma, abs=sigma_tolerance)
    for key, value, tolerance in (("rayleigh_mpm_N", e.rayleigh_mpm, 5e-3), ("weibull_mpm_N", e.weibull_mpm, 5e-3),
                                  ("weibull_shape", e.weibull_shape, 1e-2)):
        assert float(b[key]) == pytest.approx(value, rel=tolerance), key
    assert float(b["rayleigh_mpm_N"]) > float(b["max_N"])  # a 2 h storm has more peaks than the run


def test_line_failures_equal_the_cli(mooring: tangle.Model, tmp_path: Path) -> None:
    """A line that parts (lines[].failure): the break in DynamicResults.line_failures is the CLI's
    dynamics/summary.json entry, and the fairlead holds nothing after it."""
    m = tangle.Model(json.loads(json.dumps(mooring.data)))
    m.set("dynamics.duration", 4)
    m.set("lines[mooring1].failure", {"time": 3, "at": "end_b"})
    res = m.run_dynamics()
    assert res.completed
    [b] = res.line_failures
    assert b["line"] == "mooring1" and b["trigger"] == "time" and b["time_s"] == pytest.approx(3.0, abs=1e-9)
    out = cli_run(m, tmp_path / "broken")
    [c] = json.loads((out / "dynamics" / "summary.json").read_text())["line_failures"]
    for key in ("line", "trigger", "message"):
        assert b[key] == c[key]
    for key in ("time_s", "value", "threshold", "parted_from_m", "parted_to_m"):
        assert b[key] == pytest.approx(c[key], rel=1e-9)
    after = res.time_s > 3.0 + 1e-9
    assert after.any() and np.all(res.lines["mooring1"]["end_tension_N"][after, 1] == 0.0)


def test_seabed_impacts_equal_the_cli(tmp_path: Path) -> None:
    """A pipe piece dropped onto a sloping seabed (statics.method none, issue 46): its impact in
    DynamicResults.seabed_impacts is the CLI's dynamics/seabed_impacts.csv row."""
    m = tangle.Model({
        "environment": {"water_depth": 100,
                        "seabed": {"slope": 10, "upslope_azimuth": 0, "normal_stiffness": 1.0e8}},
        "line_types": [{"name": "pipe", "outer_diameter": 0.5, "mass_per_length": 300, "axial_stiffness": 1.0e10,
                        "bending_stiffness": 1.0e9, "drag_normal": 0, "drag_axial": 0}],
        "lines": [{"name": "piece", "end_a": {"type": "free", "position": [20, -5, -95.71]},
                   "end_b": {"type": "free", "position": [20, 5, -95.71]},
                   "sections": [{"type": "pipe", "length": 10, "elements": 10}],
                   "start_shape": [[20, -5, -95.71], [20, 5, -95.71]]}],
        "statics": {"method": "none"},
        "dynamics": {"duration": 1.2, "time_step": 0.0005, "output_interval": 0.05},
    }, "drop")
    res = m.run_dynamics()
    assert res.completed
    [e] = [e for e in res.seabed_impacts if e["kind"] == "impact"]
    assert e["line"] == "piece" and e["impact_velocity_m_s"] > 1.0 and e["impact_energy_J"] > 0.0
    out = cli_run(m, tmp_path / "drop")
    with (out / "dynamics" / "seabed_impacts.csv").open(encoding="utf-8") as f:
        [c] = [r for r in csv.DictReader(f) if r["kind"] == "impact"]
    for key in ("start_time_s", "impact_velocity_m_s", "impact_energy_J", "eq5_mass_kg", "peak_force_N"):
        assert e[key] == pytest.approx(float(c[key]), rel=1e-4), key
    # The smallest seabed clearance over the run: 0 where the piece landed (every node), as range.csv's column.
    clearance = np.asarray(res.lines["piece"]["range"]["seabed_clearance_min_m"])
    assert clearance.shape == (11,) and np.all(clearance < 1e-3), clearance
    with (out / "dynamics" / "piece" / "range.csv").open(encoding="utf-8") as f:
        column = [float(r["seabed_clearance_min_m"]) for r in csv.DictReader(f)]
    np.testing.assert_allclose(clearance, column, atol=2e-6)


def test_hull_impacts_equal_the_cli(tmp_path: Path) -> None:
    """A pipe piece dropped onto a fixed pontoon's box hull (issue 46, hulls that can be hit): its impact in
    DynamicResults.hull_impacts is the CLI's dynamics/hull_impacts.csv row, and its summary.json entry."""
    m = tangle.Model({
        "environment": {"water_depth": 100},
        "line_types": [{"name": "pipe", "outer_diameter": 0.5, "mass_per_length": 300, "axial_stiffness": 1.0e10,
                        "bending_stiffness": 1.0e9, "drag_normal": 0, "drag_axial": 0}],
        "vessels": [{"name": "pontoon", "mode": "fixed", "position": [0, 0, 0],
                     "hull": [{"shape": "box", "centre": [0, 0, -20], "size": [20, 20, 10]}]}],
        "hull_contact": {"line_stiffness": 1.0e8, "restitution": 0.5, "point_spacing": 0.5},
        "lines": [{"name": "piece", "end_a": {"type": "free", "position": [0, -5, -14.25]},
                   "end_b": {"type": "free", "position": [0, 5, -14.25]},
                   "sections": [{"type": "pipe", "length": 10, "elements": 10}],
                   "start_shape": [[0, -5, -14.25], [0, 5, -14.25]]}],
        "statics": {"method": "none"},
        "dynamics": {"duration": 0.9, "time_step": 0.0005, "output_interval": 0.05},
    }, "pontoon")
    res = m.run_dynamics()
    assert res.completed
    [e] = [e for e in res.hull_impacts if e["kind"] == "line_impact"][:1]
    assert e["body_a"] == "piece" and e["body_b"] == "pontoon"
    assert e["impact_velocity_m_s"] > 0.5 and e["impact_energy_J"] > 0.0 and e["bodies_effective_mass_kg"] is None
    out = cli_run(m, tmp_path / "pontoon")
    with (out / "dynamics" / "hull_impacts.csv").open(encoding="utf-8") as f:
        [c] = [r for r in csv.DictReader(f) if r["kind"] == "line_impact"][:1]
    for key in ("start_time_s", "impact_velocity_m_s", "rebound_velocity_m_s", "impact_energy_J", "eq5_mass_kg",
                "peak_force_N", "impulse_Ns"):
        assert e[key] == pytest.approx(float(c[key]), rel=1e-4), key
    summary = json.loads((out / "dynamics" / "summary.json").read_text())
    assert summary["hull_impacts"][0]["impact_energy_J"] == pytest.approx(e["impact_energy_J"], rel=1e-9)
