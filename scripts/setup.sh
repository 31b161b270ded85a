#!/usr/bin/env bash
# Installs what cube4 needs (Debian packages, idempotent) and builds it.
# Usage: scripts/setup.sh [build-dir]   (default: build)
#        scripts/setup.sh --packages-only
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-$here/build}

packages=(build-essential cmake ninja-build pkg-config zlib1g-dev libpng-dev
  verilator libsystemc-dev libgtest-dev libopenimageio-dev openimageio-tools yosys
  libcli11-dev nlohmann-json3-dev libnifti2-dev libvolpack1-dev libassimp-dev libxml2-utils z3 ccache
  parallel python3-matplotlib
  slurm-wlm  # the job-array tests start a one-node Slurm of their own (tb/tests/one_node_slurm.hpp)
  clang libclang-rt-14-dev)  # clang: the sanitizer and fuzzer build (docs/reliability.md)
"$here/scripts/install_packages.sh" setup "${packages[@]}"
[ "$build" = --packages-only ] && exit 0

if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" -j "$(nproc)"
