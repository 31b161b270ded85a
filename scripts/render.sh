#!/usr/bin/env bash
# Sets up, builds, and renders a scene (default: the shaded composite of the
# MRI head brainsmall) to cube4.png. Extra arguments go to `cube4 render`.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$here/scripts/setup.sh" >/dev/null
exec "$here/build/tb/cube4" render "$@"
