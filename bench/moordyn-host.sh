#!/usr/bin/env bash
# A coupled host against MoorDyn itself (issue 48): tests/capi/moordyn_host.c, a C99 program written against
# MoorDyn2.h only, is compiled twice, once against tangle's libtangle_moordyn and once against a MoorDyn
# library you provide (built from MoorDyn's public source, e.g. v2.7.1, by bench/build-moordyn.sh; this script
# does not fetch or build it). Both run the same deck at the host's step, alternately, REPEATS times; the best
# CPU time (user + sys) of each is kept, with its wall time, and the fairlead tension range after HALF of the
# run is compared.
#
#   bench/moordyn-host.sh MOORDYN_INCLUDE_DIR MOORDYN_LIBRARY_DIR [DECK] [HOST_DT (0.01)] [DURATION (100)] [REPEATS (3)]
#
# MOORDYN_INCLUDE_DIR holds MoorDyn2.h (and what it includes), MOORDYN_LIBRARY_DIR libmoordyn.so. DECK
# defaults to bench/moordyn/chain-1130m.txt (the mooring example's geometry as one chain; MoorDyn at RK4 with
# dtM 0.002 s, its largest stable step: 0.003 s diverges). The fairlead moves 5 m / 10 s along x from t = 0.
# tangle is the current tree's Release build (build/release, configured here if missing). With OLD_TANGLE_LIB set
# to the folder of an older commit's libtangle_moordyn.so (built side by side, e.g. from a git worktree:
# `cmake -S old -B old/build -DCMAKE_BUILD_TYPE=Release && cmake --build old/build --target tangle_moordyn`),
# that library's host runs in the same alternation and the ratio to it is printed too.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
md_include="$1"; md_lib="$2"
deck="${3:-$root/bench/moordyn/chain-1130m.txt}"
dt="${4:-0.01}"; duration="${5:-100}"; repeats="${6:-3}"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
# A copy of the deck in the work folder: MoorDyn writes its output files next to the deck.
cp "$deck" "$work/deck.txt"; deck="$work/deck.txt"

(cd "$root" && cmake --preset release >/dev/null && cmake --build --preset release -j 2 --target tangle_moordyn >/dev/null)
# The host compiled as host_NAME against INCLUDE_DIR's MoorDyn2.h and LIBRARY in LIBRARY_DIR.
host() {  # NAME INCLUDE_DIR LIBRARY LIBRARY_DIR
  cc -O2 -std=c99 -o "$work/host_$1" "$root/tests/capi/moordyn_host.c" -I"$2" -L"$4" -l"$3" -lm -Wl,-rpath,"$4"
}
host tangle "$root/include/tangle-moordyn" tangle_moordyn "$root/build/release"
host moordyn "$md_include" moordyn "$md_lib"
programs="moordyn tangle"
if [ -n "${OLD_TANGLE_LIB:-}" ]; then
  # The same MoorDyn2.h API: the current tree's header serves the older library.
  host old "$root/include/tangle-moordyn" tangle_moordyn "$OLD_TANGLE_LIB"
  programs="moordyn old tangle"
fi

/usr/bin/python3 - "$work" "$deck" "$dt" "$duration" "$repeats" "$programs" <<'PY'
import os, sys
import numpy as np
work, deck, dt, duration, repeats = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4]), int(sys.argv[5])
programs = sys.argv[6].split()
best = {}
for _ in range(repeats):
    for name in programs:
        out = os.path.join(work, f"{name}.csv")
        pid = os.fork()
        if pid == 0:
            null = os.open(os.devnull, os.O_WRONLY)
            os.dup2(null, 1)  # MoorDyn prints every step's time on stdout
            os.execv(os.path.join(work, f"host_{name}"), [f"host_{name}", deck, out, "5", "10", str(duration), dt, "0"])
        t0 = os.times().elapsed
        _, status, usage = os.wait4(pid, 0)
        wall = os.times().elapsed - t0
        if status != 0:
            sys.exit(f"host_{name} failed on {deck}")
        cpu = usage.ru_utime + usage.ru_stime
        if name not in best or cpu < best[name][0]:
            best[name] = (cpu, wall)
ranges = {}
for name in best:
    data = np.loadtxt(os.path.join(work, f"{name}.csv"), delimiter=",", skiprows=1)
    late = data[data[:, 0] >= duration / 2, 1]
    ranges[name] = late.max() - late.min()
print(f"{'program':>8} {'CPU s':>7} {'wall s':>7} {'range kN':>9}")
for name in programs:
    print(f"{name:>8} {best[name][0]:7.3f} {best[name][1]:7.3f} {ranges[name] / 1e3:9.3f}")
print(f"MoorDyn / tangle CPU: {best['moordyn'][0] / best['tangle'][0]:.2f}x; "
      f"tangle's range {100 * (ranges['tangle'] / ranges['moordyn'] - 1):+.3f} % of MoorDyn's "
      f"(host step {dt} s, {duration:g} s, best of {repeats})")
if "old" in best:
    print(f"old / tangle CPU: {best['old'][0] / best['tangle'][0]:.2f}x; MoorDyn / old: "
          f"{best['moordyn'][0] / best['old'][0]:.2f}x")
PY
