#!/usr/bin/env python3
"""Mutation score of the RTL tests: plants one single-operator fault at a time
in rtl/*.sv, rebuilds the RTL test executables incrementally, runs the ones the
mutant changed, and reports each mutant as killed (a test failed), survived
(every test passed) or stillborn (Verilator's lint or the build refused it).

The mutants live in a copy of the repository (default /tmp/cube4-mutants), so
an interrupted run never leaves a fault in the working tree; that copy's
build (the system's RTL for p = 4 only, no formal proofs: only the RTL unit
tests run) is kept between runs.

  scripts/mutate_rtl.py [--max N] [--seed S] [--units a,b] [--report FILE]

Operators, on code lines (not comments, declarations or parameters) of the
unit files: == <-> !=, && <-> ||, < -> <=, > -> >=, <= (compare) -> <,
>= -> >, + -> -, - -> +, << <-> >>, 1'b1 <-> 1'b0, dropping a ! or ~.
Sites are sampled at random (seeded) across units, at most --max in all.
Each verdict is kept in the copy (results.jsonl): a run interrupted and
started again with the same arguments resumes where it stopped (a mutant
whose unit changed since is judged again).
The report (Markdown) goes to stdout and, with --doc, into the "mutation"
section of docs/verification.md.
"""
import argparse, json, os, random, re, shutil, subprocess, sys, time, zlib

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OPS = [
    (r"==", "!="), (r"!=", "=="), (r"&&", "||"), (r"\|\|", "&&"),
    (r"(?<![<>=!])<(?![<=])", "<="), (r"(?<![<>=!-])>(?![>=])", ">="),
    (r">=", ">"), (r"(?<![+\-*/<>=!]) \+ ", " - "), (r"(?<![+\-*/<>=!]) - ", " + "),
    (r"<<", ">>"), (r">>", "<<"), (r"1'b1", "1'b0"), (r"1'b0", "1'b1"),
    (r"!(?=[a-z(])", ""), (r"~(?=[a-z(])", ""),
]
SKIP = re.compile(r"^\s*(//|input|output|parameter|localparam|logic|module|function|endfunction|typedef|`)")
# Every RTL test executable, as rtl/groups/*.cmake declare them.
RTL_TESTS = sorted({m for g in os.listdir(os.path.join(HERE, "rtl", "groups")) if g.endswith(".cmake")
                    for m in re.findall(r"cube4_rtl_test\((test_rtl_\w+)", open(os.path.join(HERE, "rtl", "groups", g)).read())})


def code_part(line):
    return line.split("//", 1)[0]


def sites(path):
    out = []
    for n, line in enumerate(open(path).read().split("\n")):
        if SKIP.match(line):
            continue
        code = code_part(line)
        # A non-blocking assignment's "<=" is not a comparison: only mutate
        # comparisons on lines without one, or after it.
        nba = not code.lstrip().startswith("assign") and re.search(r"\w\s*(\[[^\]]*\])?\s*<=", code)
        start = code.index("<=") + 2 if nba else 0
        for pat, rep in OPS:
            for m in re.finditer(pat, code):
                if m.start() < start:
                    continue
                out.append((n, m.start(), m.end(), m.group(0), rep))
    return out


def run(cmd, log, timeout=None, env=None):
    with open(log, "a") as f:
        f.write("$ " + " ".join(cmd) + "\n")
        f.flush()
        try:
            return subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT, timeout=timeout, env=env).returncode
        except subprocess.TimeoutExpired:
            return 124


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--max", type=int, default=30)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--units", default="")
    ap.add_argument("--work", default="/tmp/cube4-mutants")
    ap.add_argument("--vectors", default="100000", help="CUBE4_RTL_VECTORS for the runs")
    ap.add_argument("--doc", action="store_true", help="write docs/verification.md's mutation section")
    a = ap.parse_args()

    work, build, log = a.work, os.path.join(a.work, "build"), os.path.join(a.work, "mutate.log")
    os.makedirs(work, exist_ok=True)
    files = subprocess.run(["git", "-C", HERE, "ls-files"], capture_output=True, text=True, check=True).stdout.split()
    for f in files:  # the repository as committed and as edited, without build trees
        dst = os.path.join(work, f)
        os.makedirs(os.path.dirname(dst), exist_ok=True)
        if not os.path.exists(dst) or open(os.path.join(HERE, f), "rb").read() != open(dst, "rb").read():
            shutil.copy2(os.path.join(HERE, f), dst)
    if not os.path.exists(os.path.join(build, "build.ninja")):
        if run(["cmake", "-S", work, "-B", build, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                "-DCUBE4_SYSTEM_PIPES=4",
                "-DCUBE4_SYSTEM_TAG_PIPES=4", "-DCUBE4_SYSTEM_POLYGON_PIPES=4", "-DCUBE4_FORMAL=OFF"], log):
            sys.exit("mutate_rtl: configure failed, see " + log)
    if run(["ninja", "-C", build] + RTL_TESTS, log):
        sys.exit("mutate_rtl: the unmutated build failed, see " + log)

    units = [u for u in a.units.split(",") if u] or sorted(
        os.path.basename(p)[:-3] for p in os.listdir(os.path.join(work, "rtl")) if p.endswith(".sv"))
    pool = [(u, s) for u in units for s in sites(os.path.join(work, "rtl", u + ".sv"))]
    random.Random(a.seed).shuffle(pool)
    pool = pool[: a.max]
    env = dict(os.environ, CUBE4_RTL_VECTORS=a.vectors)

    done_path = os.path.join(work, "results.jsonl")
    done = {}
    if os.path.exists(done_path):
        for row in open(done_path):
            r = json.loads(row)
            done[r["key"]] = r["result"]
    results = []
    for i, (unit, (line, c0, c1, old, new)) in enumerate(pool, 1):
        path = os.path.join(work, "rtl", unit + ".sv")
        original = open(path).read()
        key = f"{unit}:{line}:{c0}:{old}:{new}:{zlib.crc32(original.encode())}"
        if key in done:
            results.append(tuple(done[key]))
            print(f"mutate_rtl: {i}/{len(pool)} {unit}:{line + 1}: {done[key][4]} (earlier run)", file=sys.stderr)
            continue
        lines = original.split("\n")
        lines[line] = lines[line][:c0] + new + lines[line][c1:]
        stamp = time.time()
        try:
            open(path, "w").write("\n".join(lines))
            if run(["ninja", "-C", build] + RTL_TESTS, log):
                verdict, by = "stillborn", ""
            else:
                changed = [t for t in RTL_TESTS
                           if os.path.getmtime(os.path.join(build, "rtl", t)) >= stamp]
                verdict, by = "survived", ""
                for t in changed:
                    if run([os.path.join(build, "rtl", t)], log, timeout=900, env=env):
                        verdict, by = "killed", t
                        break
                if not changed:
                    verdict = "survived"
                    by = "(no test executable uses the unit)"
        finally:
            open(path, "w").write(original)
        results.append((unit, line + 1, old, new or "(dropped)", verdict, by))
        with open(done_path, "a") as f:
            f.write(json.dumps({"key": key, "result": results[-1]}) + "\n")
        print(f"mutate_rtl: {i}/{len(pool)} {unit}:{line + 1} {old} -> {new or '(dropped)'}: {verdict} {by}",
              file=sys.stderr)
    run(["ninja", "-C", build] + RTL_TESTS, log)  # leave the copy's build unmutated

    counts = {k: sum(1 for r in results if r[4] == k) for k in ("killed", "survived", "stillborn")}
    live = counts["killed"] + counts["survived"]
    # The table's line numbers are those of this RTL: named, so that a
    # reader can tell when the files have moved on since.
    rev = subprocess.run(["git", "-C", HERE, "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
    edited = subprocess.run(["git", "-C", HERE, "status", "--porcelain", "--", "rtl"], capture_output=True,
                            text=True).stdout.strip()
    on = f"the RTL of commit {rev}" + (" with uncommitted changes" if edited else "")
    out = [f"Generated by `scripts/mutate_rtl.py --max {a.max} --seed {a.seed}` on {on} "
           f"(CUBE4_RTL_VECTORS={a.vectors}): {len(results)} mutants, {counts['killed']} killed, "
           f"{counts['survived']} survived, {counts['stillborn']} stillborn; "
           f"score {100.0 * counts['killed'] / live if live else 0:.1f} % of the mutants that build.", "",
           "| unit | line | mutation | result | killed by |", "|---|---|---|---|---|"]
    for unit, line, old, new, verdict, by in results:
        out.append(f"| {unit} | {line} | `{old}` → `{new}` | {verdict} | {by} |")
    text = "\n".join(out) + "\n"
    sys.stdout.write(text)
    if a.doc:
        subprocess.run([sys.executable, os.path.join(HERE, "scripts", "update_doc_section.py"),
                        os.path.join(HERE, "docs", "verification.md"), "mutation"], input=text, text=True, check=True)


main()
