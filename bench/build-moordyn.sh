#!/usr/bin/env bash
# Builds MoorDyn's C library from its public source, for bench/moordyn-host.sh (issue 48: tangle side by side
# with MoorDyn itself). Nothing is fetched here: give a checkout of https://github.com/FloatingArrayDesign/MoorDyn
# (e.g. `git clone --branch v2.7.1 https://github.com/FloatingArrayDesign/MoorDyn.git`). Release build of the
# `moordyn` target only, with the system's Eigen (libeigen3-dev, which tangle uses too), without MoorDyn's Python,
# Fortran, Matlab wrappers and VTK output.
#
#   bench/build-moordyn.sh MOORDYN_SOURCE_DIR BUILD_DIR
#
# Prints the two folders bench/moordyn-host.sh takes (MoorDyn2.h's and libmoordyn.so's), e.g.
#   bench/moordyn-host.sh $(bench/build-moordyn.sh ~/MoorDyn /tmp/moordyn-build)
# Measured with v2.7.1 (2026-12-02): about 9 minutes on one core.
set -euo pipefail
if [ $# -ne 2 ]; then
  echo "usage: $0 MOORDYN_SOURCE_DIR BUILD_DIR" >&2
  exit 2
fi
src="$(cd "$1" && pwd)"
build="$2"
if [ ! -f "$src/source/MoorDyn2.h" ]; then
  echo "$0: $src does not look like MoorDyn's source (no source/MoorDyn2.h)" >&2
  exit 1
fi
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DPYTHON_WRAPPER=OFF -DFORTRAN_WRAPPER=OFF \
  -DMATLAB_WRAPPER=OFF -DEXTERNAL_EIGEN=ON -DUSE_VTK=OFF >&2
cmake --build "$build" -j "$(nproc)" --target moordyn >&2
build="$(cd "$build" && pwd)"
echo "$src/source $build/source"
