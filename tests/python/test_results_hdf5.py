"""results.h5 and results.xdmf (docs/results-hdf5.md) read back with h5py, against the CSV files of the
same run.

Run through ctest (it sets TANGLE_CLI), or by hand:
    TANGLE_CLI=build/ci/tangle /usr/bin/python3 -m pytest -q tests/python/test_results_hdf5.py

Tolerances: the time series are stored in single precision (7 significant digits) and the CSV files print
7 significant digits (%.6e): they agree to a few units of the 7th digit (rtol 1e-6 plus float32 rounding,
2e-7 relative). Statics and range graphs are stored in double precision: equal to the CSV's rounding.
The XDMF files (results.xdmf for ParaView's XDMF 3 readers, results.xdmf2 for its XDMF 2 reader) are checked
twice: by parsing them (every HDF5 reference exists with the declared dimensions and every frame equals the
time series at its output time) and by opening them in ParaView (Debian's python3-paraview, which replaces
python3-vtk9, whose VTK has no XDMF reader: pvpython, with the "XDMF Reader" on results.xdmf2 and the
"Xdmf3 Reader S" and "T" on results.xdmf): the number of frames, the points and the tension range of a frame
against results.h5.
"""

from __future__ import annotations

import csv
import os
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import h5py
import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
CLI = os.environ.get("TANGLE_CLI", str(ROOT / "build" / "ci" / "tangle"))
RTOL = 1.5e-6


def read_csv(path: Path) -> tuple[list[str], np.ndarray]:
    with path.open() as f:
        rows = list(csv.reader(f))
    return rows[0], np.array([[float(v) for v in r] for r in rows[1:]])


def run(model: Path, out: Path, changes: dict[str, str]) -> Path:
    text = model.read_text()
    for old, new in changes.items():
        assert old in text, old
        text = text.replace(old, new)
    path = out.parent / (out.name + ".yaml")
    path.write_text(text)
    r = subprocess.run([CLI, "run", str(path), "-o", str(out), "--no-plots", "--no-report", "-q"],
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    return out


@pytest.fixture(scope="module")
def mooring(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("h5") / "mooring"
    return run(ROOT / "examples" / "mooring-dynamics" / "model.yaml", out,
               {"  duration: 200 ": "  duration: 12 ", "output:\n": "output:\n  format: both\n"})


def test_every_dataset_has_units_and_a_description(mooring: Path) -> None:
    with h5py.File(mooring / "results.h5", "r") as f:
        seen = []

        def check(name, obj):
            if isinstance(obj, h5py.Dataset):
                seen.append(name)
                assert isinstance(obj.attrs["units"], str) and obj.attrs["units"], name
                assert isinstance(obj.attrs["description"], str) and obj.attrs["description"], name

        f.visititems(check)
        expected = {f"dynamics/lines/mooring1/{q}" for q in
                    ("position", "effective_tension", "bending_moment", "bending_moment_vector", "curvature",
                     "torque", "end_tension", "end_force", "arc_length")}
        expected |= {f"statics/lines/mooring1/{q}" for q in
                     ("position", "effective_tension", "bending_moment", "curvature", "torque", "arc_length")}
        expected |= {f"dynamics/lines/mooring1/range/{q}_{k}" for q in ("effective_tension", "bending_moment",
                                                                        "curvature") for k in ("min", "max", "mean")}
        expected |= {"dynamics/time"}
        assert expected <= set(seen), expected - set(seen)
        assert f.attrs["model_text"] == (mooring / "model.yaml").read_text()
        assert f.attrs["tangle_version"]
        # Time series: chunked along time and compressed.
        ds = f["dynamics/lines/mooring1/effective_tension"]
        assert ds.chunks[1:] == ds.shape[1:] and ds.compression == "gzip" and ds.shuffle


def test_values_equal_the_csv_files(mooring: Path) -> None:
    with h5py.File(mooring / "results.h5", "r") as f:
        g = f["dynamics/lines/mooring1"]
        _, tension = read_csv(mooring / "dynamics" / "mooring1" / "effective_tension_N.csv")
        np.testing.assert_allclose(f["dynamics/time"][...], tension[:, 0], atol=1e-6)
        np.testing.assert_allclose(g["effective_tension"][...], tension[:, 1:], rtol=RTOL)
        for k, q in enumerate(("x_m", "y_m", "z_m")):
            _, x = read_csv(mooring / "dynamics" / "mooring1" / f"{q}.csv")
            np.testing.assert_allclose(g["position"][:, :, k], x[:, 1:], rtol=RTOL, atol=1e-6)
        header, ends = read_csv(mooring / "dynamics" / "end_forces.csv")
        col = {h: i for i, h in enumerate(header)}
        np.testing.assert_allclose(g["end_tension"][:, 1], ends[:, col["mooring1_end_b_tension_N"]], rtol=RTOL)
        header, rng = read_csv(mooring / "dynamics" / "mooring1" / "range.csv")
        col = {h: i for i, h in enumerate(header)}
        for k in ("min", "max", "mean"):
            np.testing.assert_allclose(g["range"][f"effective_tension_{k}"][...], rng[:, col[f"tension_{k}_N"]],
                                       rtol=1e-6)
        header, st = read_csv(mooring / "statics" / "mooring1.csv")
        col = {h: i for i, h in enumerate(header)}
        s = f["statics/lines/mooring1"]
        np.testing.assert_allclose(s["effective_tension"][...], st[:, col["effective_tension_N"]], rtol=1e-6)
        np.testing.assert_allclose(s["position"][:, 2], st[:, col["z_m"]], atol=1e-6)


def xdmf_items(path: Path) -> tuple[list[ET.Element], list[tuple[str, tuple[int, ...], tuple[int, ...], tuple[int, ...]]]]:
    """The frames (temporal grid's children) of an XDMF file and its HDF references: (dataset, dimensions of
    the item, start of the part read, dimensions of the dataset). results.xdmf reads a row of a frame series
    as XDMF 3 does ("file:/path|start:stride:count:dims"), results.xdmf2 by HyperSlab items (XDMF 2)."""
    root = ET.parse(path).getroot()
    temporal = root.find("Domain/Grid")
    assert temporal.get("CollectionType") == "Temporal"
    refs = []
    for item in root.iter("DataItem"):
        if item.get("ItemType") == "HyperSlab":
            slab, data = item.findall("DataItem")
            numbers = [int(v) for v in slab.text.split()]
            rank = len(numbers) // 3
            assert numbers[rank:2 * rank] == [1] * rank  # stride
            file, dataset = data.text.strip().split(":")
            assert file == "results.h5"
            refs.append((dataset, tuple(int(d) for d in item.get("Dimensions").split()), tuple(numbers[:rank]),
                         tuple(int(d) for d in data.get("Dimensions").split())))
        elif item.get("Format") == "HDF" and item.text and "|" in item.text:
            target, slab = item.text.strip().split("|")
            file, dataset = target.split(":")
            assert file == "results.h5"
            start, stride, count, dims = ([int(v) for v in part.split()] for part in slab.split(":"))
            assert stride == [1] * len(start) and count == [1] + [int(d) for d in item.get("Dimensions").split()]
            refs.append((dataset, tuple(count[1:]), tuple(start), tuple(dims)))
    return temporal.findall("Grid"), refs


@pytest.mark.parametrize("name", ["results.xdmf", "results.xdmf2"])
def test_xdmf_references_exist_with_their_dimensions(mooring: Path, name: str) -> None:
    frames, refs = xdmf_items(mooring / name)
    times = [float(g.find("Time").get("Value")) for g in frames]
    assert times == sorted(times) and times[0] == 0.0 and times[-1] == pytest.approx(12.0)
    assert len(frames) == 13  # output.vtk_interval 1 s
    assert len(refs) == 13 * 5  # position, tension, bending moment, curvature, torque per frame
    with h5py.File(mooring / "results.h5", "r") as f:
        np.testing.assert_allclose(f["xdmf/frame_time"][...], times, atol=1e-9)
        for dataset, item_dims, start, dims in refs:
            assert f[dataset].shape == dims, dataset
            assert dims[1:] == item_dims and start[1:] == (0,) * len(item_dims) and start[0] < dims[0]
        # Each frame is the lines at its output time: equal to the time series row of that time.
        time = f["dynamics/time"][...]
        series = f["dynamics/lines/mooring1"]
        for frame, t in enumerate(times):
            (k,) = np.flatnonzero(np.abs(time - t) < 1e-9)
            g = f["xdmf/mooring1/frames"]
            for field in ("position", "effective_tension", "bending_moment", "curvature", "torque"):
                np.testing.assert_array_equal(g[field][frame], series[field][k])
        # The topology is a whole dataset in both files.
        assert f["xdmf/mooring1/segments"].shape == (200, 2)


def test_hdf5_only_run_with_contact_and_clearance(tmp_path: Path) -> None:
    out = run(ROOT / "examples" / "risers-in-contact" / "model.yaml", tmp_path / "contact",
              {"  duration: 20": "  duration: 5", "output:\n": "output:\n  format: hdf5\n"})
    assert not (out / "dynamics" / "upstream" / "effective_tension_N.csv").exists()
    assert (out / "dynamics" / "upstream" / "range.csv").exists()  # the small tables stay
    with (out / "contact" / "events.csv").open() as fh:
        events = list(csv.DictReader(fh))
    with h5py.File(out / "results.h5", "r") as f:
        e = f["contact/events"]
        assert e.attrs["count"] == len(events) > 0
        np.testing.assert_allclose(e["peak_force"][...], [float(r["peak_force_N"]) for r in events], rtol=1e-6)
        names = e.attrs["line_names"].split(",")
        assert [names[int(i)] for i in e["line_1"][...]] == [r["line_1"] for r in events]
        c = f["clearance/upstream/downstream"]
        with (out / "clearance" / "envelope.csv").open() as fh:
            env = [r for r in csv.DictReader(fh) if r["line"] == "upstream"]
        np.testing.assert_allclose(c["min_clearance"][...], [float(r["min_clearance_m"]) for r in env], rtol=1e-6,
                                   atol=1e-9)


PARAVIEW_CHECK = """
import json, sys
from paraview.simple import XDMFReader, Xdmf3ReaderS, Xdmf3ReaderT
out = {}
for name, make in (("xdmf2", lambda d: XDMFReader(FileNames=[d + "/results.xdmf2"])),
                   ("xdmf3s", lambda d: Xdmf3ReaderS(FileName=[d + "/results.xdmf"])),
                   ("xdmf3t", lambda d: Xdmf3ReaderT(FileName=[d + "/results.xdmf"]))):
    reader = make(sys.argv[1])
    times = list(reader.TimestepValues)
    reader.UpdatePipeline(float(sys.argv[2]))
    info = reader.GetDataInformation()
    out[name] = {"times": times, "points": info.GetNumberOfPoints(), "cells": info.GetNumberOfCells(),
                 "tension": list(reader.PointData["effective_tension"].GetRange()),
                 "bounds": list(info.DataInformation.GetBounds())}
print("RESULT" + json.dumps(out))
"""


def test_xdmf_opens_in_paraview(mooring: Path, tmp_path: Path) -> None:
    script = tmp_path / "check.py"
    script.write_text(PARAVIEW_CHECK)
    r = subprocess.run(["pvpython", "--force-offscreen-rendering", str(script), str(mooring.resolve()), "5"],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr[-2000:]
    import json
    (line,) = [ln for ln in r.stdout.splitlines() if ln.startswith("RESULT")]
    result = json.loads(line[len("RESULT"):])
    with h5py.File(mooring / "results.h5", "r") as f:
        time = f["dynamics/time"][...]
        (k,) = np.flatnonzero(np.abs(time - 5.0) < 1e-9)
        tension = f["dynamics/lines/mooring1/effective_tension"][k]
        position = f["dynamics/lines/mooring1/position"][k]
    for name, got in result.items():
        assert got["times"] == pytest.approx(list(range(13))), name
        assert got["points"] == 201 and got["cells"] == 200, name
        assert got["tension"] == pytest.approx([tension.min(), tension.max()], rel=1e-6), name
        bounds = [position[:, 0].min(), position[:, 0].max(), position[:, 1].min(), position[:, 1].max(),
                  position[:, 2].min(), position[:, 2].max()]
        assert got["bounds"] == pytest.approx(bounds, rel=1e-6, abs=1e-5), name


def test_time_histories_written_are_those_the_model_asks_for(mooring: Path, tmp_path: Path) -> None:
    # output.time_histories: [effective_tension, position] writes those two (CSV and results.h5) and no
    # other time history along the line; end forces, range graphs and statistics stay; the values equal
    # the full run's.
    out = run(ROOT / "examples" / "mooring-dynamics" / "model.yaml", tmp_path / "some",
              {"  duration: 200 ": "  duration: 12 ",
               "output:\n": "output:\n  format: both\n  time_histories: [effective_tension, position]\n"})
    files = sorted(p.name for p in (out / "dynamics" / "mooring1").iterdir())
    assert files == ["effective_tension_N.csv", "range.csv", "statistics.csv", "x_m.csv", "y_m.csv", "z_m.csv"]
    assert (out / "dynamics" / "end_forces.csv").is_file()
    with h5py.File(out / "results.h5", "r") as some, h5py.File(mooring / "results.h5", "r") as full:
        g = some["dynamics/lines/mooring1"]
        assert sorted(g.keys()) == ["arc_length", "effective_tension", "end_force", "end_tension", "position", "range"]
        np.testing.assert_array_equal(g["effective_tension"][...], full["dynamics/lines/mooring1/effective_tension"][...])
    header, a = read_csv(out / "dynamics" / "mooring1" / "effective_tension_N.csv")
    header_full, b = read_csv(mooring / "dynamics" / "mooring1" / "effective_tension_N.csv")
    assert header == header_full
    np.testing.assert_array_equal(a, b)
    # `none`: no time history along the lines at all.
    out = run(ROOT / "examples" / "mooring-dynamics" / "model.yaml", tmp_path / "none",
              {"  duration: 200 ": "  duration: 2 ", "output:\n": "output:\n  format: both\n  time_histories: none\n"})
    assert sorted(p.name for p in (out / "dynamics" / "mooring1").iterdir()) == ["range.csv", "statistics.csv"]


def test_quiet_prints_only_errors_and_the_log_keeps_the_warnings(tmp_path: Path) -> None:
    # Issue 45: `-q` ("print only errors") still printed warnings. A model with one (a line type lighter than
    # the water it displaces) run with -q prints nothing; run.log keeps the warning; without -q it is printed.
    model = tmp_path / "floats.yaml"
    model.write_text(
        "environment: {water_depth: 100}\n"
        "line_types:\n"
        "  - {name: hose, outer_diameter: 0.5, mass_per_length: 50, axial_stiffness: 1.0e8}\n"
        "lines:\n"
        "  - name: hose\n"
        "    end_a: {type: anchored, position: [0, 0, -100]}\n"
        "    end_b: {type: anchored, position: [80, 0, -100]}\n"
        "    sections: [{type: hose, length: 100, elements: 10}]\n")
    quiet = subprocess.run([CLI, "run", str(model), "-o", str(tmp_path / "q"), "--no-plots", "--no-report", "-q"],
                           capture_output=True, text=True)
    assert quiet.returncode == 0, quiet.stderr
    assert quiet.stdout == "" and quiet.stderr == "", (quiet.stdout, quiet.stderr)
    assert "floats" in (tmp_path / "q" / "run.log").read_text()
    loud = subprocess.run([CLI, "run", str(model), "-o", str(tmp_path / "l"), "--no-plots", "--no-report"],
                          capture_output=True, text=True)
    assert loud.returncode == 0 and "warning" in loud.stderr and "floats" in loud.stderr, loud.stderr
