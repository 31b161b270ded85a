#!/usr/bin/env bash
# Sets up, builds, and renders a scene (default: the shaded composite of the
# MRI head brainsmall) through the system model with every unit at RTL,
# checked bit for bit against the golden model, to cube4.png. Extra
# arguments go to `cube4 render` (--model M replaces --model rtl).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$here/scripts/setup.sh" >/dev/null
model=(--model rtl)
for a in "$@"; do
  case "$a" in --model|--model=*) model=() ;; esac
done
exec "$here/build/tb/cube4" render "${model[@]}" "$@"
