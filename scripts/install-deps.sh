#!/usr/bin/env bash
# Installs the Debian packages tangle needs, only those that are missing (run as root on Debian 12).
set -euo pipefail
packages=(g++ cmake make libeigen3-dev libyaml-cpp-dev libcli11-dev libfmt-dev libgtest-dev libgmock-dev
          libbenchmark-dev python3-numpy python3-matplotlib clang gcc python3-dev pybind11-dev python3-pytest
          libhdf5-dev python3-h5py python3-paraview openmpi-bin libopenmpi-dev libjs-three chromium)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
