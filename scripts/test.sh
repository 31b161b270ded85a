#!/usr/bin/env bash
# Sets up, builds, and runs the whole default test suite (every ctest label
# except `slow`). `scripts/test.sh --slow` runs the slow tests as well.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$here/scripts/setup.sh"
cd "$here/build"
if [ "${1:-}" = "--slow" ]; then
  exec ctest --output-on-failure -j "$(nproc)"
fi
exec ctest --output-on-failure -j "$(nproc)" -LE slow
