#!/usr/bin/python3
"""Large steps against an older commit (issue 33): the mooring benchmark (the mooring example's 1130 m
chain-wire-chain line, fairlead 5 m / 10 s, 200 s) at 50 / 100 / 200 / 400 bars and the 12-line model,
the OLD binary at its defaults (dt 0.01 s, tolerance 1e-6, every time history written) against the NEW
binary at dt 0.05 s and tolerance 1e-4 writing the effective tension only (docs/model-format.md,
"Choosing the time step and tolerance"). Each run's CPU time (user + sys of the process and its threads)
and wall time; the fairlead tension range after 100 s against a converged run of the NEW binary (dt
0.0025 s, tolerance 1e-8). Runs alternate OLD / NEW, REPEATS times; the best CPU time is kept.

    /usr/bin/python3 bench/large_steps.py OLD_BINARY NEW_BINARY [REPEATS (default 2)] [MESHES (default 50,100,200,400)]
"""
import csv
import json
import math
import os
import pathlib
import re
import subprocess
import sys
import tempfile

root = pathlib.Path(__file__).resolve().parent.parent
old_binary, new_binary = sys.argv[1], sys.argv[2]
repeats = int(sys.argv[3]) if len(sys.argv) > 3 else 2
meshes = [int(m) for m in sys.argv[4].split(",")] if len(sys.argv) > 4 else [50, 100, 200, 400]
base = (root / "examples" / "mooring-dynamics" / "model.yaml").read_text()
base = re.sub(r"(?m)^  vtk: true", "  vtk: false", base)
base = re.sub(r"(?m)^  plots: true", "  plots: false", base)
shares = [40, 130, 30]


def mesh(text, total):
    counts = [round(s * total / 200) for s in shares[:2]]
    counts.append(total - sum(counts))
    for old, new in zip(shares, counts):
        text = re.sub(rf"elements: {old}\}}", f"elements: @{new}}}", text, count=1)
    return text.replace("@", "")


def settings(text, dt, tolerance, histories=None):
    text = re.sub(r"(?m)^  time_step: .*", f"  time_step: {dt}", text)
    text = re.sub(r"(?m)^  tolerance: 1.0e-6(.*)$", f"  tolerance: {tolerance}", text)  # statics and dynamics
    text = re.sub(r"(?m)^  output_interval: .*", f"  output_interval: {max(dt, 0.1)}", text)
    if histories is not None:
        text = text.replace("output:\n", f"output:\n  time_histories: {histories}\n")
    return text


def run(binary, text, folder):
    path = folder.with_suffix(".yaml")
    path.write_text(text)
    pid = os.fork()
    if pid == 0:
        os.execv(binary, [binary, "run", str(path), "-o", str(folder), "--overwrite", "--no-plots", "--no-report", "-q"])
    t0 = os.times().elapsed
    _, status, usage = os.wait4(pid, 0)
    wall = os.times().elapsed - t0
    if status != 0:
        raise RuntimeError(f"{binary} failed on {path}")
    return usage.ru_utime + usage.ru_stime, wall


def fairlead_range(folder):
    """The range of the first line's fairlead (end B) tension after 100 s [N] (the 12-line model: line1, the
    line moved along itself)."""
    with open(folder / "dynamics" / "end_forces.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    column = next(c for c in rows[0] if c.endswith("_end_b_tension_N"))
    values = [float(r[column]) for r in rows if float(r["time_s"]) >= 100.0]
    return max(values) - min(values)


with tempfile.TemporaryDirectory() as tmp:
    tmp = pathlib.Path(tmp)
    print(f"{'case':>10} {'converged kN':>12} {'old kN':>8} {'new kN':>8} {'new err %':>9} {'old CPU s':>9} "
          f"{'new CPU s':>9} {'CPU ratio':>9} {'old wall':>8} {'new wall':>8} {'new RTF':>7} {'new it/step':>11}")
    cases = [(f"{n} bars", mesh(base, n)) for n in meshes]
    twelve = tmp / "twelve.yaml"
    (tmp / "base.yaml").write_text(base)
    subprocess.run(["/usr/bin/python3", str(root / "bench" / "twelve_lines.py"), str(tmp / "base.yaml"), str(twelve)],
                   check=True)
    cases.append(("12 lines", twelve.read_text()))
    for name, text in cases:
        key = name.replace(" ", "-")
        converged = tmp / f"ref-{key}"
        run(new_binary, settings(text, 0.0025, "1e-8", "none"), converged)
        reference = fairlead_range(converged)
        best = {"old": (math.inf, 0.0), "new": (math.inf, 0.0)}
        for _ in range(repeats):
            for which, binary, model in (("old", old_binary, settings(text, 0.01, "1.0e-6")),
                                         ("new", new_binary, settings(text, 0.05, "1e-4", "[effective_tension]"))):
                cpu, wall = run(binary, model, tmp / f"{which}-{key}")
                if cpu < best[which][0]:
                    best[which] = (cpu, wall)
        old_range = fairlead_range(tmp / f"old-{key}")
        new_range = fairlead_range(tmp / f"new-{key}")
        summary = json.loads((tmp / f"new-{key}" / "dynamics" / "summary.json").read_text())
        print(f"{name:>10} {reference / 1e3:12.1f} {old_range / 1e3:8.1f} {new_range / 1e3:8.1f} "
              f"{100 * (new_range / reference - 1):9.2f} {best['old'][0]:9.2f} {best['new'][0]:9.2f} "
              f"{best['old'][0] / best['new'][0]:9.2f} {best['old'][1]:8.2f} {best['new'][1]:8.2f} "
              f"{200.0 / best['new'][1]:7.1f} {summary['newton_iterations'] / summary['steps']:11.2f}")
