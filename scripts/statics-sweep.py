#!/usr/bin/python3
"""Statics robustness sweep on variations of the examples (issue 12): runs `tangle run --statics-only`
on each variant and lists the ones that do not converge. Not part of the test suite (about 4 min);
run it after changing the static solver:

    /usr/bin/python3 scripts/statics-sweep.py build/ci/tangle
"""
import itertools
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
TANGLE = sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "build" / "release" / "tangle")


def no_output(text):
    return text.replace("vtk: true", "vtk: false").replace("plots: true", "plots: false")


def variants():
    catenary = no_output((ROOT / "examples/catenary-mooring/model.yaml").read_text())
    for span, speed, azimuth in itertools.product([800, 900, 1000], [0.5, 1.0, 1.5], range(0, 181, 30)):
        s = catenary.replace("position: [1000, 0, -345]", f"position: [{span}, 0, -345]")
        s = s.replace("friction_coefficient: 0 ", "friction_coefficient: 0.5 ")
        s = s.replace("  seabed:", f"  current: {{speed: {speed}, azimuth: {azimuth}}}\n  seabed:")
        yield f"catenary span {span} m, current {speed} m/s at {azimuth} deg, friction 0.5", s
    for span, stiffness, mesh in itertools.product([565, 700, 850, 1050], [1e4, 1e6], [0.1, 1, 3]):
        s = catenary.replace("position: [1000, 0, -345]", f"position: [{span}, 0, -345]")
        s = s.replace("normal_stiffness: 1.0e5", f"normal_stiffness: {stiffness}")
        for n in (40, 130, 30):
            s = s.replace(f"elements: {n}}}", f"elements: {max(1, int(n * mesh))}}}")
        yield f"catenary span {span} m, seabed {stiffness:g} N/m/m, mesh x{mesh}, frictionless", s
    for ratio, load, n in itertools.product([1e2, 1e4, 1e6, 1e7], [1, 2, 10], [5, 40, 200]):
        ea, length = 1e10, 10.0
        ei = ea * (length / n) ** 2 / ratio
        mass = load * ei / length**2 / 9.80665
        self_weight = 30.0 * 9.80665 * length**3 / ei  # w L^3 / EI of the line's own weight (in air)
        yield (f"cantilever EA Le^2/EI {ratio:g}, tip PL^2/EI {load}, self-weight wL^3/EI {self_weight:.3g}, "
               f"{n} elements"), f"""environment:
  water_depth: 100
line_types:
  - {{name: t, outer_diameter: 0.2, mass_per_length: 30, axial_stiffness: {ea}, bending_stiffness: {ei}}}
lines:
  - name: c
    contact: false
    end_a: {{type: fixed, position: [0, 0, 10]}}
    end_b: {{type: free, position: [10, 0, 10]}}
    sections:
      - {{type: t, length: 10, elements: {n}}}
    attachments:
      - {{arc_length: 10, mass: {mass}}}
"""
    riser = no_output((ROOT / "examples/riser-in-current/model.yaml").read_text())
    for scale, n in itertools.product([0.5, 1.5, 2.0], [25, 200, 800]):
        s = riser
        for speed in (1.0, 0.6, 0.2):
            s = s.replace(f"speed: {speed}", f"speed: {speed * scale}")
        yield f"riser in current x{scale}, {n} elements", s.replace("elements: 50", f"elements: {n}")


def main():
    failed = []
    total = 0
    with tempfile.TemporaryDirectory() as tmp:
        model = pathlib.Path(tmp) / "model.yaml"
        for name, text in variants():
            total += 1
            model.write_text(text)
            r = subprocess.run([TANGLE, "run", str(model), "-o", str(pathlib.Path(tmp) / "out"), "--statics-only",
                                "--no-plots", "-q", "--overwrite"], capture_output=True, text=True, timeout=300)
            if r.returncode != 0:
                failed.append(name)
                print(f"FAILED {name}")
    print(f"{total - len(failed)} passed, {len(failed)} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
