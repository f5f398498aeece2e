#!/usr/bin/env bash
# Result volume of the 12-line case (bench/twelve_lines.py: 12 x 200 bars, 200 s, output every 0.1 s):
# CSV time histories (output.format: csv) against results.h5 (output.format: hdf5). Prints the sizes,
# their ratio and the wall times of the two runs (plots, report and ParaView off).
#
#   bench/results-volume.sh [path/to/tangle]        (default build/release/tangle)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
tangle="${1:-$root/build/release/tangle}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for f in csv hdf5; do
  /usr/bin/python3 "$root/bench/twelve_lines.py" "$root/examples/mooring-dynamics/model.yaml" "$work/$f.yaml" "$f"
  t0="$(date +%s.%N)"
  "$tangle" run "$work/$f.yaml" -o "$work/$f" --no-plots --no-report -q
  t1="$(date +%s.%N)"
  echo "$f $(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')" > "$work/$f.time"
done
csv_bytes=$(find "$work/csv/dynamics" -name '*.csv' ! -name range.csv ! -name end_forces.csv -printf '%s\n' | awk '{ s += $1 } END { print s }')
h5_bytes=$(( $(stat -c %s "$work/hdf5/results.h5") + $(stat -c %s "$work/hdf5/results.xdmf") ))
printf "CSV time histories:      %8.1f MB  (run %s s)\n" "$(awk -v b="$csv_bytes" 'BEGIN { print b / 1e6 }')" "$(cut -d' ' -f2 "$work/csv.time")"
printf "results.h5 + .xdmf:      %8.1f MB  (run %s s)\n" "$(awk -v b="$h5_bytes" 'BEGIN { print b / 1e6 }')" "$(cut -d' ' -f2 "$work/hdf5.time")"
printf "ratio:                   %8.1f x smaller\n" "$(awk -v a="$csv_bytes" -v b="$h5_bytes" 'BEGIN { print a / b }')"
