#!/usr/bin/env bash
# Builds the libFuzzer harness of the model reader (tests/fuzz/ReaderFuzz.cpp) with clang and runs it.
#   scripts/fuzz-reader.sh [seconds] [work-dir]
# seconds: how long to fuzz (default 60); work-dir: where the binary, corpus and findings go
# (default build/fuzz). Exit 0: no finding; 1: a finding (crash-*, timeout-* or oom-* in work-dir);
# 77: clang++ or its libFuzzer runtime is missing (ctest reports the test as skipped).
# FUZZ_OPT: the optimisation of the harness (default -O1; ctest's 20 s smoke run builds at -O0, which
# compiles in about half the time: the whole smoke run took 90 s wall at -O0 against 155 s at -O1).
set -euo pipefail
seconds=${1:-60}
root=$(cd "$(dirname "$0")/.." && pwd)
work=${2:-$root/build/fuzz}
cxx=${CLANGXX:-clang++}
if ! command -v "$cxx" > /dev/null; then
  echo "fuzz-reader: $cxx not found (install clang: scripts/install-deps.sh); skipped"
  exit 77
fi
mkdir -p "$work/corpus"
sources=("$root/tests/fuzz/ReaderFuzz.cpp" "$root/src/tangle/io/ModelReader.cpp" "$root/src/tangle/core/Error.cpp"
         "$root/src/tangle/analysis/SnCurve.cpp" "$root/src/tangle/io/MoorDynDeck.cpp"
         "$root/src/tangle/io/MoorDynConversion.cpp" "$root/src/tangle/seabed/SeabedSurface.cpp"
         "$root/src/tangle/geometry/HullShape.cpp" "$root/src/tangle/geometry/Rotation.cpp"
         "$root/src/tangle/core/WordTable.cpp" "$root/src/tangle/hydro/CurrentGrid.cpp"
         "$root/src/tangle/element/SyropeAxialLaw.cpp" "$root/src/tangle/model/PrescribedMotion.cpp")
opt=${FUZZ_OPT:--O1}
binary="$work/reader-fuzz$opt"
# Rebuild only when a source or header of the reader is newer than the binary.
rebuild=1
if [ -x "$binary" ]; then
  rebuild=0
  for f in "${sources[@]}" "$root"/src/tangle/io/ModelReader.hpp "$root"/src/tangle/model/ModelSpec.hpp "$root"/src/tangle/io/MoorDyn*.hpp \
           "$root"/src/tangle/core/*.hpp "$root"/src/tangle/section/LineType.hpp "$root"/src/tangle/model/PrescribedMotion.hpp "$0"; do
    [ "$f" -nt "$binary" ] && rebuild=1
  done
fi
if [ $rebuild = 1 ]; then
  echo "fuzz-reader: building $binary"
  if ! "$cxx" -std=c++20 "$opt" -g -fno-omit-frame-pointer -fsanitize=fuzzer,address,undefined \
       -fno-sanitize-recover=undefined -I"$root/src" -isystem /usr/include/eigen3 "${sources[@]}" -lyaml-cpp -lfmt -o "$binary.tmp"; then
    if ! echo 'extern "C" int LLVMFuzzerTestOneInput(const char*, unsigned long){return 0;}' |
         "$cxx" -x c++ -fsanitize=fuzzer - -o /dev/null 2> /dev/null; then
      echo "fuzz-reader: $cxx has no libFuzzer runtime; skipped"
      exit 77
    fi
    exit 1
  fi
  mv "$binary.tmp" "$binary"
fi
# Seed corpus: the examples and the reader's test data (valid models the fuzzer mutates).
cp -f "$root"/tests/fuzz/corpus/* "$root"/tests/data/*.yaml "$work/corpus/" 2> /dev/null || true
for f in "$root"/examples/*/model.yaml; do cp -f "$f" "$work/corpus/example-$(basename "$(dirname "$f")").yaml"; done
cd "$work"
# -timeout: one input taking more than 10 s is a hang; -rss_limit_mb: runaway allocation is a finding.
exec "$binary" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
     -print_final_stats=1 corpus
