#!/usr/bin/env bash
# Coverage of the RTL (docs/verification.md, "Coverage"): builds the
# coverage build (CUBE4_RTL_COVERAGE=ON: every model verilated with
# --coverage; formal off), runs the RTL unit tests and the system tests in
# it (each verilated model writes its counts into one folder), merges them
# with verilator_coverage, writes annotated sources (every line with its
# count; `%` marks a line never reached), a per-module summary and the list
# of points never hit, and, with --doc, the "coverage" section of
# docs/verification.md. A slow job (a build of its own, models about twice
# as slow): `scripts/test.sh --slow` runs it.
#   scripts/coverage.sh [--labels REGEX] [--out DIR] [--doc] [--report-only]
#     --labels   ctest labels to run (default: rtl|system; `rtl` alone builds
#                only the RTL unit tests' executables)
#     --report-only  no build and no run: the report (and with --doc the
#                section) again from the last run's merged.dat, e.g. after a
#                change to scripts/coverage_report.py
#     --out      results (default: build-cov/coverage): merged.dat,
#                annotated/, summary.md, holes.md
# CUBE4_COVERAGE_BUILD: the coverage build folder (default: build-cov).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${CUBE4_COVERAGE_BUILD:-$here/build-cov}
labels='rtl|system'
out=
doc=0
report_only=0
while [ $# -gt 0 ]; do
  case $1 in
    --labels) labels=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --doc) doc=1; shift ;;
    --report-only) report_only=1; shift ;;
    *) echo "coverage.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
out=${out:-$build/coverage}
python=${CUBE4_PYTHON:-python3}

if [ $report_only = 0 ]; then
  "$here/scripts/setup.sh" --packages-only
  # The system model's RTL for p = 1, 2, 4 and 5 only: p = 8 and 16 run the
  # same unit code as p = 4 (the units are parameterised, not generated per p;
  # the address unit's p-dependent code is covered by its unit tests for every
  # p), and their rings are the largest part of a build that re-verilates
  # every model with --coverage. Configured every run, so an older coverage
  # build is brought to the same settings.
  echo "coverage.sh: configuring $build (verilates every model with --coverage)" >&2
  cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCUBE4_RTL_COVERAGE=ON -DCUBE4_FORMAL=OFF \
    -DCUBE4_SYSTEM_PIPES="1;2;4;5" -DCUBE4_SYSTEM_TAG_PIPES="2;4" -DCUBE4_SYSTEM_POLYGON_PIPES="1;4;5" >/dev/null
  # The RTL unit tests alone need only their own executables (about half
  # the build; the system model's RTL variants are the other half).
  targets=()
  if [ "$labels" = rtl ]; then
    mapfile -t targets < <(ninja -C "$build" -t targets all | grep -oE '^rtl/test_rtl_[a-z0-9_]+:' | tr -d : | sort -u)
  fi
  echo "coverage.sh: building $build${targets[*]:+ (${#targets[@]} RTL unit-test executables)}" >&2
  if [ ${#targets[@]} -gt 0 ]; then
    ninja -C "$build" -j "$(nproc)" "${targets[@]}"
  else
    cmake --build "$build" -j "$(nproc)"
  fi

  rm -rf "$out"
  mkdir -p "$out/dat"
  echo "coverage.sh: running the tests labelled $labels" >&2
  status=0
  (cd "$build" && CUBE4_COVERAGE_DIR="$out/dat" ctest -L "$labels" -LE slow -j "$(nproc)" --output-on-failure) || status=$?
  files=$(find "$out/dat" -name '*.dat' | wc -l)
  echo "coverage.sh: merging $files coverage files" >&2
  [ "$files" -gt 0 ] || { echo "coverage.sh: no coverage written: is $build a coverage build?" >&2; exit 1; }
  # In batches (one verilator_coverage call cannot take thousands of files),
  # each merged into what the batches before made.
  find "$out/dat" -name '*.dat' -print0 |
    xargs -0 -n 200 sh -c 'if [ -f "$0/merged.dat" ]; then set -- "$0/merged.dat" "$@"; fi
                           verilator_coverage --write "$0/merged.tmp" "$@" && mv "$0/merged.tmp" "$0/merged.dat"' "$out"
  # What the section's header says of the run, for --report-only.
  printf 'labels=%q\nfiles=%q\nstatus=%q\n' "$labels" "$files" "$status" > "$out/run.env"
else
  [ -f "$out/merged.dat" ] && [ -f "$out/run.env" ] ||
    { echo "coverage.sh: --report-only needs a finished run's $out/merged.dat and run.env" >&2; exit 1; }
  . "$out/run.env"
fi
rm -rf "$out/annotated"
verilator_coverage --annotate "$out/annotated" --annotate-min 1 "$out/merged.dat" >/dev/null
"$python" "$here/scripts/coverage_report.py" "$out/merged.dat" --holes "$out/holes.md" > "$out/summary.md"
rm -rf "$out/dat"
cat "$out/summary.md"
if [ $doc = 1 ]; then
  { echo "Generated $(date +%F) by \`scripts/coverage.sh --doc\` (ctest labels \`$labels\`, default vector counts, system model's RTL at p = 1, 2, 4, 5," \
         "$files coverage files merged; tests passed: $([ $status = 0 ] && echo all || echo "NOT all, exit $status")):"
    echo
    cat "$out/summary.md"; } | "$python" "$here/scripts/update_doc_section.py" "$here/docs/verification.md" coverage
fi
echo "coverage.sh: $out/summary.md, $out/holes.md, $out/annotated/" >&2
exit $status
