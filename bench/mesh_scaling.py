#!/usr/bin/python3
"""Scaling of a dynamic run with the mesh (issue 8): the mooring example (1130 m chain-wire-chain line,
fairlead 5 m / 10 s, dt 0.01 s) meshed with 50 to 800 bars, the sections' shares kept (40/130/30 of 200).

Prints, per mesh: wall time of the dynamic analysis and its real-time factor (from the run's
dynamics/summary.json), wall time of the whole `tangle run`, Newton residual assemblies per step, and the
fairlead tension range (to show that the results converge with the mesh while the cost grows).

    /usr/bin/python3 bench/mesh_scaling.py [TANGLE_BINARY (default build/release/tangle)] [DURATION_S (default 100)]
"""
import json
import pathlib
import re
import subprocess
import sys
import tempfile
import time

root = pathlib.Path(__file__).resolve().parent.parent
binary = sys.argv[1] if len(sys.argv) > 1 else str(root / "build" / "release" / "tangle")
duration = float(sys.argv[2]) if len(sys.argv) > 2 else 100.0
text = (root / "examples" / "mooring-dynamics" / "model.yaml").read_text()
text = re.sub(r"(?m)^  vtk: true", "  vtk: false", text)
text = re.sub(r"(?m)^  duration: 200 ", f"  duration: {duration:g} ", text)
shares = [40, 130, 30]

print(f"{'bars':>5} {'dyn wall s':>10} {'RTF':>7} {'run wall s':>10} {'us/step':>8} {'assemblies/step':>15} "
      f"{'fairlead T min kN':>17} {'max kN':>8}")
with tempfile.TemporaryDirectory() as tmp:
    for total in (50, 100, 200, 400, 800):
        counts = [round(s * total / 200) for s in shares[:2]]
        counts.append(total - sum(counts))
        model = text
        for old, new in zip(shares, counts):
            model = re.sub(rf"elements: {old}\}}", f"elements: @{new}}}", model, count=1)
        model = model.replace("@", "")
        path = pathlib.Path(tmp) / f"mooring-{total}.yaml"
        path.write_text(model)
        out = pathlib.Path(tmp) / f"out-{total}"
        t0 = time.perf_counter()
        subprocess.run([binary, "run", str(path), "-o", str(out), "--no-plots", "--no-report", "-q"], check=True)
        wall = time.perf_counter() - t0
        summary = json.loads((out / "dynamics" / "summary.json").read_text())
        line = summary["lines"][0]
        steps = summary["steps"]
        print(f"{total:5d} {summary['wall_time_s']:10.2f} {summary['real_time_factor']:7.1f} {wall:10.2f} "
              f"{1e6 * summary['wall_time_s'] / steps:8.1f} {summary['newton_iterations'] / steps:15.2f} "
              f"{line['end_b_min_tension_N'] / 1e3:17.1f} {line['end_b_max_tension_N'] / 1e3:8.1f}")
