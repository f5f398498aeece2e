#!/usr/bin/env bash
# Batch scaling: 8 load cases of the mooring line (examples/mooring-dynamics, 30 s of dynamics each,
# current 1 m/s from 8 headings) run one after another (-j 1), in 2 local processes (-j 2), and on 2 MPI
# ranks (mpirun -np 2). Prints wall times and the ratios to the serial run (target: <= 0.6 on 2 ranks).
#
#   bench/batch-scaling.sh [path/to/tangle]        (default build/release/tangle)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
tangle="${1:-$root/build/release/tangle}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cat > "$work/batch.yaml" <<YAML
model: $root/examples/mooring-dynamics/model.yaml
set:
  dynamics.duration: 30
  environment.seabed.friction_coefficient: 0.5
  environment.current: {speed: 1.0, azimuth: 0}
  output.vtk: false
parameters:
  - {name: heading, key: environment.current.azimuth, values: [0, 45, 90, 135, 180, 225, 270, 315]}
YAML
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
now() { date +%s.%N; }
run() {  # label, command...
  local label="$1"; shift
  local t0; t0="$(now)"
  "$@" > /dev/null || true  # exit 2 would mean a failed case: checked below
  local t1; t1="$(now)"
  echo "$label $(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')"
}
serial="$(run serial "$tangle" batch "$work/batch.yaml" -o "$work/serial" -j 1 -q)"
local2="$(run local2 "$tangle" batch "$work/batch.yaml" -o "$work/local2" -j 2 -q)"
mpi2="$(run mpi2 mpirun -np 2 "$tangle" batch "$work/batch.yaml" -o "$work/mpi2" -q)"
for d in serial local2 mpi2; do
  failed=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "status") c = i; next } $c != "completed"' \
           "$work/$d/summary.csv" | wc -l)
  [ "$failed" -eq 0 ] || { echo "error: $failed case(s) did not complete in $d"; exit 1; }
done
ts=$(echo "$serial" | cut -d' ' -f2); tl=$(echo "$local2" | cut -d' ' -f2); tm=$(echo "$mpi2" | cut -d' ' -f2)
printf "8 cases, one after another:   %6.2f s\n" "$ts"
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { print a / b }'; }
printf "8 cases, 2 local processes:   %6.2f s  (%.2f x serial)\n" "$tl" "$(ratio "$tl" "$ts")"
printf "8 cases, 2 MPI ranks:         %6.2f s  (%.2f x serial)\n" "$tm" "$(ratio "$tm" "$ts")"
