#!/usr/bin/env python3
"""Per-module summary of a merged Verilator coverage file (scripts/coverage.sh).

Reads the coverage points of `verilator_coverage --write` output and
counts, per RTL module, its line, toggle and user (cover property) points
and how many were hit at least once. A point is a source position (or a
signal bit, for toggles) of a module: the same point in several instances,
parameter sets or test executables counts once, hit if any hit it.

  coverage_report.py MERGED.dat [--holes FILE] [--goal PERCENT]

Prints a Markdown table on stdout; --holes writes every point never hit,
module by module, to FILE. Exit status 0 (the goal is reported, not
enforced: docs/verification.md explains the holes).
"""
import argparse
import collections
import re
import sys

KINDS = ("line", "toggle", "user")


def points(path):
    """(module, kind, key) -> hit, for every point in the file."""
    hit = {}
    line_re = re.compile(r"^C '(.*)' (\d+)$")
    for raw in open(path, encoding="latin-1"):
        m = line_re.match(raw.rstrip("\n"))
        if not m:
            continue
        fields = dict(kv.split("\x02", 1) for kv in m.group(1).split("\x01") if "\x02" in kv)
        page = fields.get("page", "")
        if "/" not in page:
            continue
        kind, module = page.split("/", 1)
        # Verilator names each parameter set of a module apart
        # (cube4_delay_ram__W18_M18): one unit, its source lines counted once.
        module = module.split("__", 1)[0]
        kind = kind[2:] if kind.startswith("v_") else kind
        if kind not in KINDS:
            continue
        # Instances differ only in the hierarchy: leave it out of the key.
        # (verilator_coverage's merge has already joined a generate loop's
        # iterations of one cover statement into one point.)
        key = (fields.get("f", ""), fields.get("l", ""), fields.get("n", ""), fields.get("o", ""))
        k = (module, kind, key)
        hit[k] = hit.get(k, False) or int(m.group(2)) > 0
    return hit


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("merged")
    ap.add_argument("--holes")
    ap.add_argument("--goal", type=float, default=95.0)
    a = ap.parse_args()
    hit = points(a.merged)
    total = collections.Counter()
    covered = collections.Counter()
    holes = collections.defaultdict(list)
    for (module, kind, key), h in hit.items():
        total[(module, kind)] += 1
        if h:
            covered[(module, kind)] += 1
        else:
            holes[module].append((kind, key))
    modules = sorted({m for m, _ in total})

    def cell(module, kind):
        t = total[(module, kind)]
        if t == 0:
            return "–"
        pct = 100.0 * covered[(module, kind)] / t
        # The goal holds lines and cover points; toggles are reported.
        mark = "" if pct >= a.goal else " ✗" if kind != "toggle" else " †"
        return f"{covered[(module, kind)]}/{t} ({pct:.1f} %){mark}"

    print(f"| module | lines | toggles | cover points (user) |")
    print("|---|---:|---:|---:|")
    for m in modules:
        print(f"| `{m}` | {cell(m, 'line')} | {cell(m, 'toggle')} | {cell(m, 'user')} |")
    all_t = {k: sum(total[(m, k)] for m in modules) for k in KINDS}
    all_c = {k: sum(covered[(m, k)] for m in modules) for k in KINDS}
    print("| all | " + " | ".join(f"{all_c[k]}/{all_t[k]} ({100.0 * all_c[k] / max(all_t[k], 1):.1f} %)" for k in KINDS)
          + " |")
    print()
    print(f"✗: below the goal of {a.goal:g} % (lines and cover points); †: toggles below {a.goal:g} % "
          "(reported, not part of the goal).")
    if a.holes:
        with open(a.holes, "w") as f:
            for m in modules:
                if not holes[m]:
                    continue
                f.write(f"## {m}\n\n")
                for kind, (file, line, col, comment) in sorted(holes[m]):
                    f.write(f"- {kind} {file}:{line}" + (f" `{comment}`" if comment else "") + "\n")
                f.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
