#!/usr/bin/python3
"""Tests of the browser report (report.html). Run with Debian's Python:

    /usr/bin/python3 tests/python/test_report.py path/to/tangle

Runs `tangle run` on tests/data/report-contact.yaml (two risers touching under a wave, 0.1 s), then
- checks the data embedded in the page against the result files (positions, tensions, end tensions,
  static shape, contact events);
- opens the page in headless Chromium (WebGL through SwiftShader): no JavaScript error, the 3D canvas
  drawn, the time slider moves the lines, a clash-table row jumps the replay to its event (the page's
  self-test, `#selftest`, writes what it saw into <pre id="tangle-status">);
- takes a screenshot: not blank, and the tubes in the colours of the tension scale;
- rebuilds the page with `tangle report DIR`, writes a model view with `tangle view`, and checks the
  page of a run whose statics fail.
Exits 77 (ctest: skipped) when Chromium is not installed; prints nothing unless a test fails.
"""

from __future__ import annotations

import csv
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import traceback
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
MODEL = ROOT / "tests" / "data" / "report-contact.yaml"
SKIP = 77


def chromium_binary() -> str | None:
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def chromium(args: list[str], profile: Path) -> str:
    base = [chromium_binary(), "--headless=new", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader",
            "--enable-unsafe-swiftshader", "--no-first-run", f"--user-data-dir={profile}",
            "--virtual-time-budget=8000"]
    r = subprocess.run(base + args, capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, f"chromium failed ({r.returncode}): {r.stderr[-2000:]}"
    return r.stdout


def page_status(page: Path, profile: Path, hash_: str = "") -> dict:
    dom = chromium(["--dump-dom", page.resolve().as_uri() + hash_], profile)
    m = re.search(r'<pre id="tangle-status"[^>]*>([^<]*)</pre>', dom)
    assert m, "no status element in the page"
    text = m.group(1).replace("&quot;", '"').replace("&amp;", "&")
    assert text.startswith("{"), f"the page did not finish its script: {text[:300]}"
    return json.loads(text)


def embedded_data(page: Path) -> dict:
    html = page.read_text(encoding="utf-8")
    m = re.search(r'<script id="tangle-data" type="application/json">(.*?)</script>', html, re.S)
    assert m, "no data element in the page"
    return json.loads(m.group(1))


def read_table(path: Path) -> tuple[list[str], list[list[float]]]:
    with path.open(encoding="utf-8") as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(v) for v in r] for r in rows[1:] if r]


def close(a: float, b: float, rel: float, abs_: float) -> bool:
    return abs(a - b) <= rel * abs(b) + abs_


def check_data(run: Path, data: dict) -> None:
    on_disk = json.loads((run / "report" / "data.json").read_text(encoding="utf-8"))
    assert on_disk == data, "the page's data differ from report/data.json"
    assert data["kind"] == "run" and data["status"] == "completed", data["status"]
    names = [line["name"] for line in data["lines"]]
    assert names == ["upstream", "downstream"], names
    frames = data["frames"]
    dec = data["decimation"]
    assert dec["frames"] == len(frames) and dec["outputs"] == len(data["history"]["t"]), dec
    assert len(frames) == 41, len(frames)  # 10 s every 0.25 s: every output time kept
    checked = 0
    for li, name in enumerate(names):
        _, xs = read_table(run / "dynamics" / name / "x_m.csv")
        _, ys = read_table(run / "dynamics" / name / "y_m.csv")
        _, zs = read_table(run / "dynamics" / name / "z_m.csv")
        _, ts = read_table(run / "dynamics" / name / "effective_tension_N.csv")
        by_time = {round(r[0], 6): k for k, r in enumerate(xs)}
        for f in frames[:: 7] + [frames[-1]]:
            k = by_time[round(f["t"], 6)]
            p = f["lines"][li]["p"]
            tension = f["lines"][li]["T"]
            for i in range(0, len(p) // 3, 3):
                for q, table in enumerate((xs, ys, zs)):
                    assert close(p[3 * i + q] / 1000.0, table[k][1 + i], 0.0, 6e-4), \
                        f"{name} node {i} t={f['t']}: {p[3 * i + q]} mm against {table[k][1 + i]} m"
                assert close(tension[i] * 1000.0, ts[k][1 + i], 6e-4, 1.0), \
                    f"{name} node {i} t={f['t']}: tension {tension[i]} kN against {ts[k][1 + i]} N"
                checked += 1
    assert checked > 50, checked
    # End tensions at every output time against dynamics/end_forces.csv.
    header, ef = read_table(run / "dynamics" / "end_forces.csv")
    hist = data["history"]
    assert len(hist["t"]) == len(ef)
    for li, name in enumerate(names):
        for end, col in ((0, f"{name}_end_a_tension_N"), (1, f"{name}_end_b_tension_N")):
            c = header.index(col)
            series = hist["endTension"][2 * li + end]
            for k in range(0, len(ef), 5):
                assert close(series[k] * 1000.0, ef[k][c], 6e-5, 1.0), (col, k, series[k], ef[k][c])
    # The static frame against statics/<line>.csv.
    for li, name in enumerate(names):
        header, rows = read_table(run / "statics" / f"{name}.csv")
        cx, cz, ct = header.index("x_m"), header.index("z_m"), header.index("effective_tension_N")
        p = data["statics"]["lines"][li]["p"]
        for i, r in enumerate(rows):
            assert close(p[3 * i] / 1000.0, r[cx], 0.0, 6e-4) and close(p[3 * i + 2] / 1000.0, r[cz], 0.0, 6e-4)
            assert close(data["statics"]["lines"][li]["T"][i] * 1000.0, r[ct], 6e-4, 1.0)
    # Contact events against contact/events.csv.
    with (run / "contact" / "events.csv").open(encoding="utf-8") as f:
        events = list(csv.DictReader(f))
    # One sustained contact along the risers' tops from the statics on (until 2026-12-06 the tracker split
    # off its top end as a second event at 8.95 s, ContactEvents.AContactWhoseMiddleLiftsOffStaysOneEvent).
    assert len(events) == len(data["clash"]["events"]) >= 1, (len(events), len(data["clash"]["events"]))
    # Contact forces are drawn: some frame has a contact patch.
    assert any(f["k"] for f in frames)


def check_page(run: Path, data: dict, profile: Path) -> None:
    status = page_status(run / "report.html", profile, "#selftest")
    assert status["ready"], status
    assert status["errors"] == [], status["errors"]
    assert status["meshes"] == 2 and status["frames"] == len(data["frames"]), status
    assert status["pixelsDrawn"] > 2000, f"the 3D canvas looks empty: {status['pixelsDrawn']} pixels drawn"
    assert not math.isclose(status["checksumFirst"], status["checksumSlider"], rel_tol=1e-9), \
        "moving the time slider to the last frame did not move the lines"
    assert math.isclose(status["checksumSlider"], status["checksumLast"], rel_tol=1e-12), \
        "moving the time slider did not show the last frame"
    assert math.isclose(status["checksumBack"], status["checksumFirst"], rel_tol=1e-12)
    assert status["clashRows"] == len(data["clash"]["events"]), status
    # The last row (by event number) jumps to the output time at or just before its start, from the last
    # frame, where the slider left the replay.
    start = status["eventStart"]
    assert status["frameAfterRowClick"] < status["frames"] - 1, status
    interval = data["decimation"]["output_interval"] * data["decimation"]["stride"]
    assert start - interval - 1e-9 <= status["frameTimeAfterRowClick"] <= start + 1e-9, status
    assert status["plots"] >= 4 and "c" in status["quantities"], status


def read_png(path: Path):
    import matplotlib.image as mpimg  # Debian's python3-matplotlib
    return mpimg.imread(str(path))


def check_screenshot(run: Path, profile: Path, tmp: Path) -> None:
    shot = tmp / "shot.png"
    chromium([f"--screenshot={shot}", "--window-size=1200,900", (run / "report.html").resolve().as_uri()], profile)
    img = read_png(shot)
    assert img.shape[0] >= 800 and img.shape[1] >= 1000, img.shape
    rgb = img[..., :3]
    assert float(rgb.std()) > 0.05, "blank screenshot"
    # The 3D view (below the header): tubes coloured by tension, from the blue to the red end of the scale.
    view = rgb[100:700, 20:1180]
    r, g, b = view[..., 0], view[..., 1], view[..., 2]
    blue = ((b > 0.6) & (r < 0.35) & (g < 0.45)).sum()
    red = ((r > 0.6) & (g < 0.3) & (b < 0.3)).sum()
    assert blue > 20, f"no blue (low tension) tube pixels in the screenshot: {blue}"
    assert red > 20, f"no red (high tension) tube pixels in the screenshot: {red}"


def main() -> int:
    if len(sys.argv) != 2:
        print("usage: test_report.py path/to/tangle", file=sys.stderr)
        return 2
    tangle = sys.argv[1]
    if chromium_binary() is None:
        print("chromium not installed: skipped")
        return SKIP
    failures = 0
    with tempfile.TemporaryDirectory(prefix="tangle-report-") as t:
        tmp = Path(t)
        profile = tmp / "profile"
        run = tmp / "run"
        r = subprocess.run([tangle, "run", str(MODEL), "-o", str(run), "-q", "--no-plots"], capture_output=True,
                           text=True, timeout=120)
        if r.returncode != 0:
            print(f"tangle run failed ({r.returncode}):\n{r.stderr}")
            return 1
        data = embedded_data(run / "report.html")

        def rebuild() -> None:
            (run / "report.html").unlink()
            r2 = subprocess.run([tangle, "report", str(run)], capture_output=True, text=True, timeout=60)
            assert r2.returncode == 0, r2.stderr
            assert embedded_data(run / "report.html") == data, "tangle report embedded different data"
            # The rebuilt page has the whole run log (the run's own page has it up to the report).
            html = (run / "report.html").read_text(encoding="utf-8")
            assert "results written to" in html
            r3 = subprocess.run([tangle, "report", str(tmp)], capture_output=True, text=True, timeout=60)
            assert r3.returncode == 1 and "data.json" in r3.stderr, (r3.returncode, r3.stderr)

        def view() -> None:
            page = tmp / "view.html"
            r2 = subprocess.run([tangle, "view", str(MODEL), "-o", str(page)], capture_output=True, text=True,
                                timeout=60)
            assert r2.returncode == 0, r2.stderr
            d = embedded_data(page)
            assert d["kind"] == "view" and d["frames"] == [] and d["statics"] is not None
            status = page_status(page, profile)
            assert status["ready"] and status["errors"] == [], status
            assert status["frames"] == 1 and status["pixelsDrawn"] > 2000, status

        def failed_statics() -> None:
            # A run whose statics fail still leaves a page (model, log, where the solver stopped). The model
            # has no static equilibrium: a chain free at both ends on a frictionless seabed in a current
            # drifts away. (It used to be the contact model with statics.max_iterations 1, which the
            # coarser-mesh fallback now solves.)
            model = tmp / "fail.yaml"
            model.write_text("""environment:
  water_depth: 50
  seabed: {normal_stiffness: 1.0e5, friction_coefficient: 0}
  current: [{z: 0, speed: 0.5, azimuth: 90}, {z: -50, speed: 0.5, azimuth: 90}]
line_types:
  - {name: chain, outer_diameter: 0.1, mass_per_length: 100, axial_stiffness: 5.0e8}
lines:
  - name: chain
    end_a: {type: free, position: [0, 0, -50]}
    end_b: {type: free, position: [100, 0, -50]}
    sections:
      - {type: chain, length: 100, elements: 20}
dynamics: {duration: 10, time_step: 0.05}
""", encoding="utf-8")
            out = tmp / "fail"
            r2 = subprocess.run([tangle, "run", str(model), "-o", str(out), "-q", "--no-plots"], capture_output=True,
                                text=True, timeout=60)
            assert r2.returncode == 2, (r2.returncode, r2.stderr)
            d = embedded_data(out / "report.html")
            assert d["status"] == "failed: statics did not converge" and d["frames"] == [], d["status"]
            status = page_status(out / "report.html", profile)
            assert status["ready"] and status["errors"] == [] and status["frames"] == 1, status
            assert "did not converge" in (out / "report.html").read_text(encoding="utf-8")

        def sloping_seabed() -> None:
            # A seabed that is not flat (issue 46): the page gets its sampled heights and draws it; a pipe piece
            # dropped onto the slope (statics.method: none) writes its seabed impact.
            model = tmp / "slope.yaml"
            model.write_text("""environment:
  water_depth: 100
  seabed: {slope: 10, upslope_azimuth: 0, normal_stiffness: 1.0e8}
line_types:
  - {name: pipe, outer_diameter: 0.5, mass_per_length: 300, axial_stiffness: 1.0e10, bending_stiffness: 1.0e9,
     drag_normal: 0, drag_axial: 0}
lines:
  - name: piece
    end_a: {type: free, position: [20, -5, -95.71]}
    end_b: {type: free, position: [20, 5, -95.71]}
    sections: [{type: pipe, length: 10, elements: 10}]
    start_shape: [[20, -5, -95.71], [20, 5, -95.71]]
statics: {method: none}
dynamics: {duration: 1.2, time_step: 0.0005, output_interval: 0.05}
""", encoding="utf-8")
            out = tmp / "slope"
            r2 = subprocess.run([tangle, "run", str(model), "-o", str(out), "-q", "--no-plots"], capture_output=True,
                                text=True, timeout=60)
            assert r2.returncode == 0, (r2.returncode, r2.stderr)
            d = embedded_data(out / "report.html")
            sb = d["seabed"]
            assert sb["n"] == 41 and len(sb["z"]) == 41 * 41 and "plane" in sb["describe"], sb.get("describe")
            # The samples are the plane's heights: z = -100 + tan(10 deg) x.
            for k in (0, 20 * 41 + 20, 41 * 41 - 1):
                x = sb["x0"] + sb["step"] * (k % 41)
                assert close(sb["z"][k], -100.0 + math.tan(math.radians(10.0)) * x, 0.0, 2e-3), (k, sb["z"][k])
            with (out / "dynamics" / "seabed_impacts.csv").open(encoding="utf-8") as f:
                rows = list(csv.DictReader(f))
            assert rows and rows[0]["kind"] == "impact", rows
            # The impact is a row of the page's impacts table.
            assert [i["kind"] for i in d["impacts"]] == ["line on seabed"] * len(d["impacts"]) and d["impacts"]
            status = page_status(out / "report.html", profile)
            assert status["ready"] and status["errors"] == [], status
            assert status["impactRows"] == len(d["impacts"]), status

        def hulls() -> None:
            # Hulls that can be hit (issue 46): the page draws a vessel as its hull's shapes and lists the
            # impacts on them. A pipe piece dropped onto a fixed pontoon (a box) beside a column (a cylinder).
            model = tmp / "hull.yaml"
            model.write_text("""environment: {water_depth: 100}
line_types:
  - {name: pipe, outer_diameter: 0.5, mass_per_length: 300, axial_stiffness: 1.0e10, bending_stiffness: 1.0e9,
     drag_normal: 0, drag_axial: 0}
vessels:
  - name: pontoon
    mode: fixed
    position: [0, 0, 0]
    hull:
      - {shape: box, centre: [0, 0, -20], size: [20, 20, 10]}
      - {shape: cylinder, end_a: [8, 8, -15], end_b: [8, 8, 10], diameter: 4}
      - {shape: capsule, end_a: [-8, -8, -15], end_b: [-8, -8, 5], diameter: 2}
hull_contact: {line_stiffness: 1.0e8, restitution: 0.5, point_spacing: 0.5}
lines:
  - name: piece
    end_a: {type: free, position: [0, -5, -14.25]}
    end_b: {type: free, position: [0, 5, -14.25]}
    sections: [{type: pipe, length: 10, elements: 10}]
    start_shape: [[0, -5, -14.25], [0, 5, -14.25]]
statics: {method: none}
dynamics: {duration: 0.9, time_step: 0.0005, output_interval: 0.05}
""", encoding="utf-8")
            out = tmp / "hull"
            r2 = subprocess.run([tangle, "run", str(model), "-o", str(out), "-q", "--no-plots"], capture_output=True,
                                text=True, timeout=60)
            assert r2.returncode == 0, (r2.returncode, r2.stderr)
            d = embedded_data(out / "report.html")
            assert [h["kind"] for h in d["vessels"][0]["hull"]] == ["box", "cylinder", "capsule"], d["vessels"]
            assert d["vessels"][0]["hull"][0]["s"] == [20, 20, 10]
            kinds = [i["kind"] for i in d["impacts"]]
            assert kinds and set(kinds) == {"line on hull"}, kinds
            assert d["impacts"][0]["bodies"] == "piece / pontoon" and d["impacts"][0]["energy"] > 0.0
            status = page_status(out / "report.html", profile)
            assert status["ready"] and status["errors"] == [], status
            assert status["impactRows"] == len(kinds) and status["vessels"] == 1, status

        tests = [("data", lambda: check_data(run, data)), ("page", lambda: check_page(run, data, profile)),
                 ("screenshot", lambda: check_screenshot(run, profile, tmp)), ("rebuild", rebuild),
                 ("view", view), ("failed statics", failed_statics), ("sloping seabed", sloping_seabed),
                 ("hulls", hulls)]
        for name, test in tests:
            try:
                test()
            except Exception:  # noqa: BLE001 - report every failing test
                failures += 1
                print(f"FAIL {name}")
                traceback.print_exc()
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
