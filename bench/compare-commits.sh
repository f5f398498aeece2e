#!/usr/bin/env bash
# Speed against an older commit (issue 8), built side by side and run alternately on the same machine:
#   1. the mooring example (1130 m chain-wire-chain line, 200 bars, 200 s at dt 0.01 s, fairlead 5 m / 10 s);
#   2. the same line 12 times around a point (12 x 200 bars, fairleads on a 20 m circle, same motion);
#   3. the drilling-riser application (examples/drilling-riser-drift, 200 s).
# Each run is `tangle run --no-plots -q` with ParaView output off; the best of REPEATS wall times is kept
# (the machines are noisy). Prints wall time, real-time factor (simulated / wall) and the speed-up.
#
#   bench/compare-commits.sh [OLD_COMMIT (default 467623e)] [REPEATS (default 3)]
# The old commit is built in a temporary worktree (Release, the tangle target only); the current tree is
# built in build/release.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
old="${1:-467623e}"
repeats="${2:-3}"
work="$(mktemp -d)"
cleanup() { git -C "$root" worktree remove --force "$work/old" >/dev/null 2>&1 || true; rm -rf "$work"; }
trap cleanup EXIT

git -C "$root" worktree add --detach "$work/old" "$old" >/dev/null
(cd "$work/old" && cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DTANGLE_BUILD_TESTS=OFF -DTANGLE_BUILD_BENCHMARKS=OFF \
   >/dev/null && cmake --build build -j 2 --target tangle >/dev/null)
(cd "$root" && cmake --preset release >/dev/null && cmake --build --preset release -j 2 --target tangle >/dev/null)
new_bin="$root/build/release/tangle"
old_bin="$work/old/build/tangle"

# Case models: ParaView output off; the 12-line model made from the example's text.
mkdir -p "$work/cases"
sed -e 's/^  vtk: true/  vtk: false/' "$root/examples/mooring-dynamics/model.yaml" > "$work/cases/mooring.yaml"
sed -e 's/^  vtk: true/  vtk: false/' "$root/examples/drilling-riser-drift/model.yaml" > "$work/cases/drilling-riser.yaml"
/usr/bin/python3 "$root/bench/twelve_lines.py" "$work/cases/mooring.yaml" "$work/cases/twelve-lines.yaml"

best() {  # binary model -> best wall time [s] of $repeats runs
  local bin="$1" model="$2" bestt=""
  for _ in $(seq "$repeats"); do
    local out="$work/out-$$"
    rm -rf "$out"
    local t0 t1
    t0="$(date +%s.%N)"
    "$bin" run "$model" -o "$out" --no-plots -q
    t1="$(date +%s.%N)"
    bestt="$(awk -v a="$t0" -v b="$t1" -v c="$bestt" 'BEGIN { t = b - a; if (c == "" || t < c) print t; else print c }')"
  done
  echo "$bestt"
}

printf "%-16s %12s %12s %10s %10s %9s\n" case "old wall s" "new wall s" "old RTF" "new RTF" speed-up
# The drilling-riser model file changed keys since older commits: each binary runs its own tree's example.
sed -e 's/^  vtk: true/  vtk: false/' "$work/old/examples/drilling-riser-drift/model.yaml" > "$work/cases/drilling-riser-old.yaml"
for c in mooring twelve-lines drilling-riser; do
  model="$work/cases/$c.yaml"
  old_model="$model"
  [ "$c" = drilling-riser ] && old_model="$work/cases/drilling-riser-old.yaml"
  to="$(best "$old_bin" "$old_model")"
  tn="$(best "$new_bin" "$model")"
  awk -v c="$c" -v a="$to" -v b="$tn" 'BEGIN { printf "%-16s %12.2f %12.2f %10.1f %10.1f %8.2fx\n", c, a, b, 200 / a, 200 / b, a / b }'
done
echo "(old = $old, new = $(git -C "$root" rev-parse --short HEAD); wall time of the whole run: reading, statics, dynamics, result files)"
