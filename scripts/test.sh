#!/usr/bin/env bash
# Sets up, builds, and runs the whole default test suite (every ctest label
# except `slow`). `scripts/test.sh --slow` runs the slow tests as well, and
# the coverage run (scripts/coverage.sh, a build of its own).
# Two builds: build/ (everything, RTL included) and build-san/, the
# reliability build (docs/reliability.md): no RTL (so CUBE4_RTL=OFF is
# checked too), clang with ASan + UBSan, whose unit tests and fuzzers run
# here (fuzzers about 25 s each; under --slow 5 minutes each).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$here/scripts/setup.sh"
slow=0
[ "${1:-}" = "--slow" ] && slow=1

status=0
cd "$here/build"
if [ $slow = 1 ]; then
  ctest --output-on-failure -j "$(nproc)" || status=1
else
  ctest --output-on-failure -j "$(nproc)" -LE slow || status=1
fi

san="$here/build-san"
if [ ! -f "$san/build.ninja" ]; then
  cmake -S "$here" -B "$san" -G Ninja -DCUBE4_RTL=OFF -DCUBE4_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ >/dev/null
fi
cmake --build "$san" -j "$(nproc)"
cd "$san"
ctest --output-on-failure -j "$(nproc)" -L 'unit|fuzz' || status=1
if [ $slow = 1 ]; then
  ctest --output-on-failure -j "$(nproc)" -R '^fuzz_slow[.]' || status=1
fi
# Coverage: a build of its own (docs/verification.md, "Coverage").
if [ $slow = 1 ]; then
  "$here/scripts/coverage.sh" || status=1
fi
exit $status
