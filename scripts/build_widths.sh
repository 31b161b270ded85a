#!/usr/bin/env bash
# Builds `cube4` with the system's RTL verilated at other widths
# (docs/system.md, "RTL at other widths") and prints the program's path.
#
#   scripts/build_widths.sh [--pipes "4 5"] Name=value ...
#
# Name=value: Verilog width parameters (golden/precision.hpp's rtl_parameter
# names), for example AlphaBits=12 AccGuardBits=0 for VolumePro's
# compositor. --pipes: the p values to verilate (default 4; polygon hardware
# for each of them, no voxel-tag variants). A build per set of widths and
# pipes is kept under $CUBE4_WIDTH_BUILDS (default build-widths/ in the
# repository) and reused: a second call with the same widths only checks it
# is up to date. Progress goes to stderr; the path is the only stdout line.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
pipes="4"
if [ "${1:-}" = "--pipes" ]; then
  [ $# -ge 2 ] || { echo "build_widths: --pipes needs a list of p, for example --pipes \"4 5\"" >&2; exit 2; }
  pipes=$2
  shift 2
fi
for w in "$@"; do
  [[ $w =~ ^[A-Za-z]+=[0-9]+$ ]] || { echo "build_widths: \"$w\" is not Name=value (for example AlphaBits=12)" >&2; exit 2; }
done
for p in $pipes; do
  [[ $p =~ ^[1-9][0-9]*$ ]] || { echo "build_widths: --pipes: \"$p\" is not a pipeline count" >&2; exit 2; }
done

# One name per configuration, the same for any order of the arguments.
widths=$(printf '%s\n' "$@" | sort | paste -sd';' -)
pipe_list=$(printf '%s\n' $pipes | sort -n | paste -sd';' -)
name="p${pipe_list//;/_}${widths:+-${widths//;/-}}"
dir="${CUBE4_WIDTH_BUILDS:-$root/build-widths}/${name//=/}"

mkdir -p "$(dirname "$dir")"
if [ ! -f "$dir/build.ninja" ]; then
  echo "build_widths: configuring $dir (Verilator runs now, a minute or two)" >&2
  # A configure step that fails (a width out of range, say) leaves no
  # half-made build behind to be mistaken for one.
  if ! cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCUBE4_FORMAL=OFF \
      "-DCUBE4_SYSTEM_WIDTHS=$widths" "-DCUBE4_SYSTEM_PIPES=$pipe_list" "-DCUBE4_SYSTEM_POLYGON_PIPES=$pipe_list" "-DCUBE4_SYSTEM_ZDIFF_PIPES=$pipe_list" \
      -DCUBE4_SYSTEM_TAG_PIPES= >"$dir.configure.log" 2>&1; then
    grep -E 'CMake Error|CUBE4_SYSTEM_WIDTHS' -A3 "$dir.configure.log" >&2 || tail -20 "$dir.configure.log" >&2
    rm -rf "$dir"
    echo "build_widths: configuring failed (the whole log: $dir.configure.log)" >&2
    exit 1
  fi
fi
echo "build_widths: building cube4 in $dir" >&2
cmake --build "$dir" --target cube4 >&2
echo "$dir/tb/cube4"
