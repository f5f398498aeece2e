#!/usr/bin/python3
"""Writes the 12-line benchmark model: the mooring example's line (examples/mooring-dynamics) 12 times
around a point, fairleads on a 20 m circle, anchors 1000 m further out, every fairlead moved 5 m / 10 s
along x, 200 s at dt 0.01 s (issue 8's "12 lines around a point").

    bench/twelve_lines.py BASE_MODEL.yaml OUT.yaml [FORMAT] [--contact]
        FORMAT: output.format (default: keep)
        --contact: contact between every pair of lines (66 pairs, apart all the run: the cost of contact and
                   its no-collision check when nothing touches, issue 43's "5 % when apart")
"""
import math
import sys

contact = "--contact" in sys.argv
if contact:
    sys.argv.remove("--contact")
text = open(sys.argv[1]).read()
head, rest = text.split("lines:\n", 1)
tail = rest[rest.index("\nstatics:"):]
tail = tail.replace("  vtk: true", "  vtk: false")
if len(sys.argv) > 3:
    tail = tail.replace("output:\n", f"output:\n  format: {sys.argv[3]}\n")
block = []
for k in range(12):
    az = math.radians(30 * k)
    c, s = math.cos(az), math.sin(az)
    fx, fy = 20 * c, 20 * s
    ax, ay = fx + 1000 * c, fy + 1000 * s
    block.append(f"""  - name: line{k + 1}
    end_a: {{type: anchored, position: [{ax:.3f}, {ay:.3f}, -345]}}
    end_b:
      type: pinned
      position: [{fx:.3f}, {fy:.3f}, -20]
      motion: {{amplitude: [5, 0, 0], period: 10, phase: 0}}
    sections:
      - {{type: chain76, length: 250, elements: 40}}
      - {{type: wire96, length: 780, elements: 130}}
      - {{type: chain76, length: 100, elements: 30}}
""")
if contact:
    tail += "\ncontact:\n  restitution: 0.5\n"
open(sys.argv[2], "w").write(head + "lines:\n" + "".join(block) + tail)
