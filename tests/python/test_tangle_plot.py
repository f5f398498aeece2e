#!/usr/bin/python3
"""Tests of python/tangle_plot.py. Run with Debian's Python:

    /usr/bin/python3 tests/python/test_tangle_plot.py

Fabricates a small `tangle run` results directory in a temporary folder, makes the plots and checks
every PNG. Prints nothing unless a test fails; exits non-zero on failure.
"""

from __future__ import annotations

import contextlib
import io
import json
import math
import sys
import tempfile
import traceback
import warnings
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "python"))

import numpy as np  # noqa: E402

import tangle_plot  # noqa: E402

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
MIN_PNG_BYTES = 10_000  # a real plot with axes, ticks and curves is well above this

LINES = ("riser-1", "mooring_2")
WATER_DEPTH = 100.0


def write_csv(path: Path, header: list[str], rows) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    with path.open("w", encoding="utf-8") as f:
        f.write(",".join(header) + "\n")
        for row in rows:
            f.write(",".join(v if isinstance(v, str) else f"{v:.6e}" for v in row) + "\n")


def catenary(n: int, heading_deg: float):
    """A hanging line from (0, 0, -WATER_DEPTH) to about 300 m away at z = -10, with its plane
    rotated by `heading_deg` about z, plus a part lying on the seabed."""
    s = np.linspace(0.0, 400.0, n)
    a = 150.0
    h = np.where(s < 100.0, s, 100.0 + a * np.arcsinh((s - 100.0) / a))
    z = np.where(s < 100.0, -WATER_DEPTH, -WATER_DEPTH + a * (np.sqrt(1.0 + ((s - 100.0) / a) ** 2) - 1.0))
    c, sn = math.cos(math.radians(heading_deg)), math.sin(math.radians(heading_deg))
    return s, 50.0 + c * h, -20.0 + sn * h, z, h


def make_results(root: Path) -> None:
    """Writes every result file tangle_plot knows, in the exact formats of the C++ writers."""
    root.mkdir(parents=True, exist_ok=True)
    (root / "summary.json").write_text(
        json.dumps({"title": "test", "environment": {"water_depth_m": WATER_DEPTH}, "lines": []}), encoding="utf-8"
    )
    for k, line in enumerate(LINES):
        s, x, y, z, _ = catenary(41, 30.0 * k)
        tension = 1.0e5 + 2.0e3 * (z + WATER_DEPTH)
        moment = 1.0e3 * np.exp(-(((s - 100.0) / 20.0) ** 2))
        curvature = moment / 1.0e7
        write_csv(
            root / "statics" / f"{line}.csv",
            [
                "arc_length_m",
                "x_m",
                "y_m",
                "z_m",
                "effective_tension_N",
                "bending_moment_Nm",
                "curvature_1_per_m",
            ],
            zip(s, x, y, z, tension, moment, curvature),
        )
        rows = []
        for i in range(len(s)):
            rows.append(
                (
                    s[i],
                    0.8 * tension[i],
                    1.3 * tension[i],
                    tension[i],
                    0.5 * moment[i],
                    2.0 * moment[i],
                    moment[i],
                    0.5 * curvature[i],
                    2.0 * curvature[i],
                    curvature[i],
                )
            )
        write_csv(
            root / "dynamics" / line / "range.csv",
            [
                "arc_length_m",
                "tension_min_N",
                "tension_max_N",
                "tension_mean_N",
                "bending_moment_min_Nm",
                "bending_moment_max_Nm",
                "bending_moment_mean_Nm",
                "curvature_min_1_per_m",
                "curvature_max_1_per_m",
                "curvature_mean_1_per_m",
            ],
            rows,
        )
    t = np.linspace(0.0, 60.0, 301)
    header = ["time_s"]
    columns = [t]
    for k, line in enumerate(LINES):
        for end, phase in (("a", 0.0), ("b", 1.0)):
            header.append(f"{line}_end_{end}_tension_N")
            columns.append(1.0e5 * (1.0 + k) + 2.0e4 * np.sin(2.0 * math.pi * t / 12.0 + phase))
            for axis in "xyz":  # the signed force components the real file has beside each tension
                header.append(f"{line}_end_{end}_f{axis}_N")
                columns.append(-5.0e4 * np.cos(2.0 * math.pi * t / 12.0 + phase))
    write_csv(root / "dynamics" / "end_forces.csv", header, zip(*columns))

    write_csv(
        root / "contact" / "events.csv",
        [
            "event",
            "start_time_s",
            "end_time_s",
            "line_1",
            "line_2",
            "arc_1_start_m",
            "arc_2_start_m",
            "peak_force_N",
            "impulse_Ns",
            "impact_velocity_m_per_s",
            "impact_energy_J",
        ],
        [
            ("1", 3.0, 3.4, LINES[0], LINES[1], 120.0, 80.0, 2.0e4, 3.0e3, 0.8, 150.0),
            ("2", 15.1, 15.3, LINES[0], LINES[1], 121.0, 81.0, 3.5e4, 4.0e3, 1.1, 420.0),
            ("3", 27.0, 27.9, LINES[1], "umbilical", 60.0, 10.0, 1.0e4, 2.0e3, 0.4, 35.0),
        ],
    )
    rows = []
    for pair, offset in ((f"{LINES[0]}/{LINES[1]}", 0.4), (f"{LINES[1]}/umbilical", 1.5)):
        for ti in t[::5]:
            rows.append((f"{ti:.6e}", pair, offset + math.cos(2.0 * math.pi * ti / 12.0), 120.0, 80.0))
    write_csv(root / "contact" / "clearance.csv", ["time_s", "pair", "min_clearance_m", "arc_1_m", "arc_2_m"], rows)


EXPECTED_PNGS = [f"statics_{line}.png" for line in LINES] + [f"range_{line}.png" for line in LINES] + [
    "end_tensions.png",
    "clash_events.png",
    "clearance.png",
]


def assert_png(path: Path) -> None:
    assert path.is_file(), f"missing {path}"
    data = path.read_bytes()
    assert data[:8] == PNG_MAGIC, f"{path} is not a PNG"
    assert len(data) > MIN_PNG_BYTES, f"{path} is only {len(data)} bytes"


# ---------------------------------------------------------------------------------------------


def test_all_plots_from_a_full_results_directory(tmp: Path) -> None:
    results = tmp / "run"
    make_results(results)
    errors: list = []
    written = tangle_plot.plot_results(results, errors=errors)
    assert not errors, f"unexpected errors: {errors}"
    assert sorted(p.name for p in written) == sorted(EXPECTED_PNGS), written
    for name in EXPECTED_PNGS:
        assert_png(results / "plots" / name)


def test_main_writes_to_out_dir_and_returns_zero(tmp: Path) -> None:
    results = tmp / "run"
    make_results(results)
    out = tmp / "elsewhere" / "figs"
    stdout, stderr = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(stderr):
        status = tangle_plot.main([str(results), "--out", str(out)])
    assert status == 0, f"status {status}, stderr: {stderr.getvalue()}"
    assert stderr.getvalue() == "", stderr.getvalue()
    for name in EXPECTED_PNGS:
        assert_png(out / name)
        assert str(out / name) in stdout.getvalue().splitlines()
    assert not (results / "plots").exists()


def test_missing_parts_are_skipped_silently(tmp: Path) -> None:
    results = tmp / "run"
    make_results(results)
    for sub in ("dynamics", "contact"):
        for p in sorted((results / sub).rglob("*"), reverse=True):
            p.unlink() if p.is_file() else p.rmdir()
        (results / sub).rmdir()
    (results / "summary.json").unlink()
    errors: list = []
    written = tangle_plot.plot_results(results, errors=errors)
    assert not errors, errors
    assert sorted(p.name for p in written) == sorted(f"statics_{line}.png" for line in LINES)

    empty = tmp / "empty"
    empty.mkdir()
    assert tangle_plot.plot_results(empty, errors=errors) == [] and not errors


def test_a_pipe_line_shows_its_wall_tension(tmp: Path) -> None:
    # Issue 45: a line with a bore has wall_tension_N in statics/<line>.csv and wall_tension_{min,max,mean}_N
    # in range.csv: the statics figure draws it beside the effective tension, the range figure gives it a panel.
    s = np.linspace(0.0, 100.0, 11)
    te = 1.0e6 - 5.0e3 * s
    tw = te + 3.0e5
    write_csv(tmp / "statics.csv",
              ["arc_length_m", "x_m", "y_m", "z_m", "effective_tension_N", "wall_tension_N", "internal_pressure_Pa",
               "bending_moment_Nm", "curvature_1_per_m"],
              [[f"{a}", "0", "0", f"{a - 100.0}", f"{t}", f"{w}", "1e7", "0", "0"] for a, t, w in zip(s, te, tw)])
    fig = tangle_plot.statics_figure(tangle_plot.read_csv(tmp / "statics.csv"), "riser", None)
    labels = [ln.get_label() for ln in fig.axes[1].get_lines()]
    assert labels == ["effective tension", "wall tension"], labels
    assert np.allclose(fig.axes[1].get_lines()[1].get_ydata(), tw / 1e3)
    columns = ["arc_length_m"] + [f"{q}_{k}_{u}" for q, u in (("tension", "N"), ("wall_tension", "N"),
                                                             ("curvature", "1_per_m")) for k in ("min", "max", "mean")]
    write_csv(tmp / "range.csv", columns, [[f"{a}"] + ["1"] * 9 for a in s])
    fig = tangle_plot.range_figure(tangle_plot.read_csv(tmp / "range.csv"), "riser")
    assert len(fig.axes) == 3
    assert fig.axes[1].get_ylabel() == "wall tension [kN]"


def test_many_pairs_plot_the_nearest_only(tmp: Path) -> None:
    # A model of hundreds of lines (issue 45): clearance.png shows the 10 pairs that come nearest and
    # clearance_envelope.png the 12 sides with the smallest clearance, not a curve or panel for each of
    # thousands (a 300-line run's plots took longer than its analysis).
    rows = []
    for p in range(30):
        for t in range(3):
            rows.append([f"{t}.0", f"a{p}/b{p}", f"{float(p) + 0.1 * t}", "0", "0"])
    write_csv(tmp / "clearance.csv", ["time_s", "pair", "min_clearance_m", "arc_1_m", "arc_2_m"], rows)
    fig = tangle_plot.clearance_figure(tangle_plot.read_csv(tmp / "clearance.csv", text=("pair",)))
    curves = [ln.get_label() for ln in fig.axes[0].get_lines() if not ln.get_label().startswith("_")]
    assert len(curves) == tangle_plot.MAX_PAIR_CURVES
    assert all(label.startswith(f"a{p}/b{p} ") for p, label in enumerate(curves)), curves
    rows = []
    for p in range(30):
        for i in range(4):
            rows.append([f"a{p}", f"b{p}", f"{10.0 * i}", f"{100.0 - p}", f"{100.0 - p - i}", "1.0"])
    write_csv(tmp / "envelope.csv", ["line", "other_line", "arc_length_m", "static_clearance_m", "min_clearance_m",
                                     "time_of_min_s"], rows)
    fig = tangle_plot.clearance_envelope_figure(tangle_plot.read_csv(tmp / "envelope.csv", text=("line", "other_line")))
    assert len(fig.axes) == tangle_plot.MAX_ENVELOPE_PANELS
    assert fig.axes[0].get_title() == "Clearance from 'a29' to 'b29'"


def test_bad_file_is_reported_and_others_still_plotted(tmp: Path) -> None:
    results = tmp / "run"
    make_results(results)
    (results / "contact" / "clearance.csv").write_text("time_s,pair\n0.0,a/b\n", encoding="utf-8")
    errors: list = []
    written = tangle_plot.plot_results(results, errors=errors)
    assert len(errors) == 1 and errors[0][0].name == "clearance.csv", errors
    assert "min_clearance_m" in str(errors[0][1])
    assert len(written) == len(EXPECTED_PNGS) - 1
    stderr = io.StringIO()
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(stderr):
        assert tangle_plot.main([str(results)]) == 1
    assert "clearance.csv" in stderr.getvalue()
    try:
        tangle_plot.plot_results(results)
    except RuntimeError as exc:
        assert "clearance.csv" in str(exc)
    else:
        raise AssertionError("plot_results without an error list should raise")


def test_empty_event_and_clearance_files_still_give_a_plot(tmp: Path) -> None:
    write_csv(tmp / "events.csv", ["start_time_s", "end_time_s", "line_1", "line_2", "peak_force_N", "impact_energy_J"], [])
    write_csv(tmp / "clearance.csv", ["time_s", "pair", "min_clearance_m", "arc_1_m", "arc_2_m"], [])
    # A "no events" / "no data" message only: a valid but small PNG.
    assert tangle_plot.plot_clash_events(tmp / "events.csv", tmp / "e.png") == tmp / "e.png"
    assert tangle_plot.plot_clearance(tmp / "clearance.csv", tmp / "c.png") == tmp / "c.png"
    for name in ("e.png", "c.png"):
        data = (tmp / name).read_bytes()
        assert data[:8] == PNG_MAGIC and len(data) > 1000, name


def test_water_depth_is_found_anywhere_in_the_summary(tmp: Path) -> None:
    assert tangle_plot.water_depth({"water_depth_m": 250}) == 250.0
    assert tangle_plot.water_depth({"a": [{"b": {"water_depth_m": 1200.5}}]}) == 1200.5
    assert tangle_plot.water_depth({"lines": []}) is None
    assert tangle_plot.water_depth({"water_depth_m": None}) is None
    assert tangle_plot.water_depth({"water_depth_m": True}) is None
    make_results(tmp)
    assert tangle_plot.water_depth(tangle_plot.read_summary(tmp)) == WATER_DEPTH
    assert tangle_plot.read_summary(tmp / "nowhere") == {}


def test_horizontal_distance_is_measured_in_the_line_plane(tmp: Path) -> None:
    _, x, y, _, h = catenary(21, 37.0)
    assert np.allclose(tangle_plot.horizontal_distance(x, y), h, atol=1e-9)
    # Reversed line: still grows from its first node.
    assert np.allclose(tangle_plot.horizontal_distance(x[::-1], y[::-1]), h[-1] - h[::-1], atol=1e-9)
    # Vertical line.
    assert np.all(tangle_plot.horizontal_distance(np.ones(4), np.ones(4)) == 0.0)


def test_read_csv_types_and_errors(tmp: Path) -> None:
    p = tmp / "t.csv"
    p.write_text("time_s,pair,value\n0.5,a/b,1.5\n1.0,c/d,\n\n", encoding="utf-8")
    t = tangle_plot.read_csv(p)
    assert t["time_s"].dtype == float and list(t["time_s"]) == [0.5, 1.0]
    assert list(t["pair"]) == ["a/b", "c/d"]
    assert t["value"][0] == 1.5 and math.isnan(t["value"][1])
    p.write_text("line_1,line_2\n1,2\n", encoding="utf-8")
    t = tangle_plot.read_csv(p, text=("line_1",))
    assert list(t["line_1"]) == ["1"] and list(t["line_2"]) == [2.0]
    p.write_text("a,b\n1,2,3\n", encoding="utf-8")
    try:
        tangle_plot.read_csv(p)
    except ValueError as exc:
        assert "t.csv:2" in str(exc), exc
    else:
        raise AssertionError("row of wrong length accepted")


def test_figures_have_the_expected_subplots(tmp: Path) -> None:
    make_results(tmp)
    fig = tangle_plot.statics_figure(tangle_plot.read_csv(tmp / "statics" / f"{LINES[0]}.csv"), LINES[0], WATER_DEPTH)
    assert len(fig.axes) == 3
    profile = fig.axes[0]
    seabed = [ln for ln in profile.get_lines() if ln.get_label().startswith("seabed")]
    assert len(seabed) == 1 and np.allclose(seabed[0].get_ydata(), -WATER_DEPTH)
    fig = tangle_plot.statics_figure(tangle_plot.read_csv(tmp / "statics" / f"{LINES[0]}.csv"), LINES[0], None)
    assert not [ln for ln in fig.axes[0].get_lines() if ln.get_label().startswith("seabed")]
    fig = tangle_plot.range_figure(tangle_plot.read_csv(tmp / "dynamics" / LINES[1] / "range.csv"), LINES[1])
    assert len(fig.axes) == 3 and all(ax.collections for ax in fig.axes)  # shaded min-max band
    fig = tangle_plot.end_tensions_figure(tangle_plot.read_csv(tmp / "dynamics" / "end_forces.csv"))
    plotted = fig.axes[0].get_lines()
    labels = [ln.get_label() for ln in plotted]
    # Issue 45: tensions only (not the force components), labelled by line and end, a colour per line.
    assert labels == ["riser-1 end A", "riser-1 end B", "mooring_2 end A", "mooring_2 end B"], labels
    assert plotted[0].get_color() == plotted[1].get_color() != plotted[2].get_color() == plotted[3].get_color()
    assert [ln.get_linestyle() for ln in plotted] == ["-", "--", "-", "--"]
    fig = tangle_plot.clash_events_figure(tangle_plot.read_csv(tmp / "contact" / "events.csv"))
    assert len(fig.axes) == 2
    fig = tangle_plot.clearance_figure(tangle_plot.read_csv(tmp / "contact" / "clearance.csv"))
    assert len([ln for ln in fig.axes[0].get_lines() if not ln.get_label().startswith("_")]) == 2


def test_cable_line_figures_leave_out_the_bending_moment(tmp: Path) -> None:
    # Issue 45: a cable line's tables have no bending moment columns (tangle writes none for a line
    # without bending stiffness): its figures show the others, no empty or zero panel.
    s, x, y, z, _ = catenary(21, 0.0)
    tension = 1.0e5 + 2.0e3 * (z + WATER_DEPTH)
    curvature = np.full_like(s, 1.0e-4)
    write_csv(tmp / "statics" / "chain.csv",
              ["arc_length_m", "x_m", "y_m", "z_m", "effective_tension_N", "curvature_1_per_m"],
              zip(s, x, y, z, tension, curvature))
    write_csv(tmp / "dynamics" / "chain" / "range.csv",
              ["arc_length_m", "tension_min_N", "tension_max_N", "tension_mean_N", "curvature_min_1_per_m",
               "curvature_max_1_per_m", "curvature_mean_1_per_m"],
              zip(s, 0.9 * tension, 1.1 * tension, tension, 0.5 * curvature, 2.0 * curvature, curvature))
    fig = tangle_plot.statics_figure(tangle_plot.read_csv(tmp / "statics" / "chain.csv"), "chain", WATER_DEPTH)
    assert [ax.get_ylabel() for ax in fig.axes] == ["z [m]", "effective tension [kN]"]
    fig = tangle_plot.range_figure(tangle_plot.read_csv(tmp / "dynamics" / "chain" / "range.csv"), "chain")
    assert [ax.get_ylabel() for ax in fig.axes] == ["effective tension [kN]", "curvature [1/m]"]


# ---------------------------------------------------------------------------------------------


def test_clearance_envelope_plot_with_required_clearance(tmp: Path) -> None:
    rows = []
    for line, other in (("up", "down"), ("down", "up")):
        for i in range(11):
            rows.append([line, other, f"{10.0 * i}", f"{4.0 - 0.1 * i}", f"{3.0 - 0.2 * i}", f"{0.5 * i}"])
    write_csv(tmp / "clearance" / "envelope.csv",
              ["line", "other_line", "arc_length_m", "static_clearance_m", "min_clearance_m", "time_of_min_s"], rows)
    (tmp / "clearance" / "summary.json").write_text('{"required_clearance_m": 1.5, "pairs": []}', encoding="utf-8")
    fig = tangle_plot.clearance_envelope_figure(
        tangle_plot.read_csv(tmp / "clearance" / "envelope.csv", text=("line", "other_line")), 1.5)
    assert len(fig.axes) == 2
    labels = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
    assert labels == ["static (min 3 m)", "dynamic minimum (min 1 m)", "required 1.5 m"], labels
    written = tangle_plot.plot_results(tmp)
    assert tmp / "plots" / "clearance_envelope.png" in written
    # A statics-only run has no dynamic column values: only the static curve and the requirement.
    rows = [["up", "down", "0", "4", "nan", "nan"], ["up", "down", "10", "3.5", "nan", "nan"]]
    write_csv(tmp / "s.csv", ["line", "other_line", "arc_length_m", "static_clearance_m", "min_clearance_m",
                              "time_of_min_s"], rows)
    fig = tangle_plot.clearance_envelope_figure(tangle_plot.read_csv(tmp / "s.csv", text=("line", "other_line")), 1.5)
    assert len(fig.axes[0].get_lines()) == 2


def test_drift_path_draws_the_hit_points_paths_and_no_wave_frequency_vessel(tmp: Path) -> None:
    # Issue 46: the seed paper's Fig. 11 turn is the riser's (its point where it is hit), so the figure draws
    # that point's path over the whole run; a vessel's "<name>_wf_x_m" columns (wave-frequency motion) are
    # not a vessel of their own.
    t = np.linspace(0.0, 20.0, 41)
    write_csv(tmp / "dynamics" / "vessels.csv",
              ["time_s", "unit_x_m", "unit_y_m", "unit_z_m", "unit_wf_x_m", "unit_wf_y_m", "unit_wf_z_m"],
              zip(t, -0.5 * t, -0.5 * t, 0 * t, 0.1 * np.sin(t), 0 * t, 0 * t))
    arcs = np.linspace(0.0, 100.0, 11)
    for line, shift in (("riser", 0.0), ("leg", 5.0)):
        for axis, sign in (("x", 1.0), ("y", -1.0)):
            rows = [[ti] + list(-0.5 * ti + shift * sign + 0.01 * arcs) for ti in t]
            write_csv(tmp / "dynamics" / line / f"{axis}_m.csv", ["time_s"] + [f"s={a:.3f}m" for a in arcs], rows)
    write_csv(tmp / "contact" / "events.csv", ["event", "line_1", "line_2", "arc_1_start_m", "arc_2_start_m"],
              [("0", "leg", "riser", 40.0, 60.0)])
    write_csv(tmp / "contact" / "event_paths.csv", ["event", "time_s", "arc_1_m", "arc_2_m"],
              [("0", f"{ti:.6f}", 40.0, 60.0) for ti in t[20:]])
    fig = tangle_plot.drift_path_figure(tmp)
    lines = {ln.get_label(): ln for ln in fig.axes[0].get_lines() if not ln.get_label().startswith("_")}
    assert "unit_wf path" not in lines and "unit path" in lines, sorted(lines)
    riser = lines["riser at 60 m (event 0)"]
    assert len(riser.get_xdata()) == len(t)  # the whole run, before the contact too
    assert np.allclose(riser.get_xdata(), -0.5 * t + 0.6)
    assert len(lines["leg at 40 m (event 0)"].get_xdata()) == len(t)
    assert len(lines["contact point"].get_xdata()) == len(t) - 20


def main() -> int:
    tests = [(name, fn) for name, fn in globals().items() if name.startswith("test_") and callable(fn)]
    failed = 0
    for name, fn in tests:
        with tempfile.TemporaryDirectory(prefix="tangle_plot_test_") as tmp, warnings.catch_warnings():
            warnings.simplefilter("error")  # a matplotlib warning (e.g. empty legend) is a failure
            warnings.simplefilter("ignore", DeprecationWarning)
            warnings.simplefilter("ignore", PendingDeprecationWarning)
            try:
                fn(Path(tmp))
            except Exception:  # noqa: BLE001 - report every failing test
                failed += 1
                print(f"FAIL {name}", file=sys.stderr)
                traceback.print_exc()
    if failed:
        print(f"{failed} of {len(tests)} tests failed", file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

