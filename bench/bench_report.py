#!/usr/bin/python3
"""Size, write time and open time of the browser report (issue 11). Wall-time measurements only.

    /usr/bin/python3 bench/bench_report.py build/ci/tangle [examples/drilling-riser-drift/model.yaml]

Runs the model twice (with and without the report: the run's own wall times, from run.log), prints
the report's size and the time tangle spent on it (collection during the run + writing, as run.log
states it), and opens the page in headless Chromium three times: the page's own time from navigation
start to its first drawn frame (performance.now() in its status) and the wall time of a Chromium
process that loads it, against the same for an empty page.
"""

import json
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
FLAGS = ["--headless=new", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
         "--no-first-run"]


def run(tangle, model, out, extra):
    t0 = time.perf_counter()
    subprocess.run([tangle, "run", str(model), "-o", str(out), "-q", "--no-plots", "--overwrite"] + extra, check=True)
    return time.perf_counter() - t0, (out / "run.log").read_text()


def open_page(url, profile):
    t0 = time.perf_counter()
    dom = subprocess.run(["chromium"] + FLAGS + [f"--user-data-dir={profile}", "--dump-dom", url],
                         capture_output=True, text=True, check=True).stdout
    wall = time.perf_counter() - t0
    m = re.search(r'<pre id="tangle-status"[^>]*>([^<]*)</pre>', dom)
    status = json.loads(m.group(1).replace("&quot;", '"')) if m else None
    return wall, status


def main():
    tangle = sys.argv[1]
    model = Path(sys.argv[2]) if len(sys.argv) > 2 else ROOT / "examples" / "drilling-riser-drift" / "model.yaml"
    with tempfile.TemporaryDirectory() as t:
        tmp = Path(t)
        wall_with, log = run(tangle, model, tmp / "with", [])
        wall_without, _ = run(tangle, model, tmp / "without", ["--no-report"])
        m = re.search(r"report written to .* \(([\d.]+) MB, ([\d.]+) s\)", log)
        total = re.search(r"results written to .* \(([\d.]+) s\)", log)
        page = tmp / "with" / "report.html"
        print(f"model: {model}")
        print(f"report.html: {page.stat().st_size / 1e6:.2f} MB; report/data.json "
              f"{(tmp / 'with' / 'report' / 'data.json').stat().st_size / 1e6:.2f} MB")
        print(f"run wall time: {wall_with:.2f} s with the report, {wall_without:.2f} s without (--no-report)")
        if m and total:
            print(f"report time as logged: {float(m.group(2)):.3f} s of a {float(total.group(1)):.2f} s run "
                  f"({100 * float(m.group(2)) / float(total.group(1)):.2f} %)")
        blank = tmp / "blank.html"
        blank.write_text("<html><body>blank</body></html>")
        for i in range(3):
            wall, status = open_page(page.as_uri(), tmp / "profile")
            wall0, _ = open_page(blank.as_uri(), tmp / "profile")
            print(f"open {i + 1}: page ready (first frame drawn) {status['openMs']} ms after navigation start; "
                  f"chromium process {wall:.2f} s (empty page {wall0:.2f} s); errors {status['errors']}")


if __name__ == "__main__":
    main()
