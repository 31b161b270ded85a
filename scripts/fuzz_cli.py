#!/usr/bin/env python3
"""Whole-program mutation fuzz of `cube4 render` (docs/reliability.md): takes
the scenes of scenes/ and small volume files of every format, mutates them
(bytes flipped, inserted, deleted or repeated; JSON values swapped for
extreme ones; headers' numbers changed), renders each with a time limit and
checks what the tool promises:

  - the exit code is 0 or 2 (never a crash, 1 or a signal), within the time limit;
  - on exit 2, an output that existed before is byte for byte unchanged and
    no new output or temporary file is left behind;
  - on exit 0, the outputs exist and are not empty.

  scripts/fuzz_cli.py [--minutes M] [--seed S] [--work DIR]

Every failing input is kept in DIR/findings with the command that ran it.
Prints a summary; exit 1 if anything was found.
"""
import argparse, copy, json, os, random, shutil, struct, subprocess, sys, time, zlib, gzip

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CUBE4 = os.path.join(HERE, "build", "tb", "cube4")
BIG = "__1e309__"  # written as the literal 1e309, which no double holds
EXTREMES = [0, -1, BIG, -1e308, 1e15, -1e15, 2**63, -(2**63), 1e-320, "x", None, [], {}, True, [1e9] * 3,
            [0, 0, 0], 3.5, 65536, -65536, [[0, 0]], [[0, 1], [1e308, 1]]]


def small_volumes(d):
    """Seed volume files: den, raw (with its scene), NIfTI, gzipped den/NIfTI."""
    vols = {}
    nx, ny, nz = 6, 5, 4
    data = bytes((x * 37 + y * 11 + z * 5) & 255 for z in range(nz) for y in range(ny) for x in range(nx))
    # den: VolPack's header (magic, version, sizes), then the voxels.
    den = struct.pack("<HHH", 0xA6F2, 1, 1) + struct.pack("<HHH", nx, ny, nz) * 8 + b"\0" * 8
    den = den[:62].ljust(62, b"\0") + data
    vols["v.den"] = den
    vols["v.den.gz"] = gzip.compress(den)
    hdr = bytearray(352)
    struct.pack_into("<i", hdr, 0, 348)
    struct.pack_into("<8h", hdr, 40, 3, nx, ny, nz, 1, 1, 1, 1)
    struct.pack_into("<hh", hdr, 70, 2, 8)      # uint8
    struct.pack_into("<8f", hdr, 76, 1, 1, 1, 1, 1, 1, 1, 1)
    struct.pack_into("<f", hdr, 108, 352.0)
    hdr[344:348] = b"n+1\0"
    vols["v.nii"] = bytes(hdr) + data
    vols["v.nii.gz"] = gzip.compress(bytes(hdr) + data)
    vols["v.raw"] = data
    for name, blob in vols.items():
        open(os.path.join(d, name), "wb").write(blob)
    return vols, (nx, ny, nz)


def mutate_bytes(rng, blob):
    b = bytearray(blob)
    for _ in range(rng.randint(1, 8)):
        op = rng.randrange(5)
        i = rng.randrange(max(1, len(b)))
        if op == 0 and b:
            b[i % len(b)] ^= 1 << rng.randrange(8)
        elif op == 1:
            b[i:i] = bytes(rng.randrange(256) for _ in range(rng.randint(1, 16)))
        elif op == 2 and b:
            del b[i:i + rng.randint(1, 32)]
        elif op == 3 and b:
            b[i:i] = b[i:i + rng.randint(1, 64)] * rng.randint(2, 50)
        elif op == 4 and len(b) >= 4:
            struct.pack_into("<i", b, min(i, len(b) - 4), rng.choice([0, -1, 2**31 - 1, -2**31, 65536, 348, 7]))
    return bytes(b)


def mutate_json(rng, obj):
    def paths(o, p=()):
        yield p
        if isinstance(o, dict):
            for k, v in o.items():
                yield from paths(v, p + (k,))
        elif isinstance(o, list):
            for i, v in enumerate(o):
                yield from paths(v, p + (i,))
    obj = json.loads(json.dumps(obj))
    for _ in range(rng.randint(1, 3)):
        ps = list(paths(obj))
        p = rng.choice(ps[1:]) if len(ps) > 1 else ()
        if not p:
            continue
        parent = obj
        for k in p[:-1]:
            parent = parent[k]
        r = rng.random()
        if r < 0.7:
            parent[p[-1]] = copy.deepcopy(rng.choice(EXTREMES))
        elif r < 0.85 and isinstance(parent, dict):
            parent["unknown_" + str(rng.randrange(99))] = 1
        elif isinstance(parent, dict):
            del parent[p[-1]]
    return obj


def snapshot(paths):
    return {p: open(p, "rb").read() if os.path.exists(p) else None for p in paths}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--minutes", type=float, default=30)
    ap.add_argument("--seed", type=int, default=9)
    ap.add_argument("--work", default="/tmp/cube4-fuzz-cli")
    ap.add_argument("--timeout", type=float, default=60)
    a = ap.parse_args()
    rng = random.Random(a.seed)
    shutil.rmtree(a.work, ignore_errors=True)
    seeds, found = os.path.join(a.work, "seeds"), os.path.join(a.work, "findings")
    os.makedirs(seeds)
    os.makedirs(found)
    # A copy of the binary, so that a rebuild during the run changes nothing.
    cube4 = os.path.join(a.work, "cube4")
    shutil.copy2(CUBE4, cube4)
    vols, dims = small_volumes(seeds)
    scenes = []
    for f in sorted(os.listdir(os.path.join(HERE, "scenes"))):
        if f.endswith(".json"):
            s = json.load(open(os.path.join(HERE, "scenes", f)))
            if s.get("volume", {}).get("synthetic") in ("sphere", "field", "noise"):
                s["volume"]["size"] = [12, 10, 8]  # keep each run short
                if "output" in s: s["output"] = {"width": 64, "height": 64}
                scenes.append(s)
    for name in vols:
        v = {"file": name} if not name.endswith(".raw") else {"file": name, "format": "raw", "dims": list(dims),
                                                              "type": "uint8"}
        scenes.append({"volume": v, "output": {"width": 48, "height": 48}})
    models = ["fixed", "float", "tlm", "rtl", "mixed:shade", "reference", "splat"]
    end = time.time() + a.minutes * 60
    runs, problems, codes = 0, [], {}
    while time.time() < end:
        case = os.path.join(a.work, "case")
        shutil.rmtree(case, ignore_errors=True)
        os.makedirs(case)
        scene = mutate_json(rng, rng.choice(scenes)) if rng.random() < 0.6 else rng.choice(scenes)
        for name, blob in vols.items():
            open(os.path.join(case, name), "wb").write(mutate_bytes(rng, blob) if rng.random() < 0.5 else blob)
        text = json.dumps(scene).replace('"' + BIG + '"', "1e309")
        if rng.random() < 0.15:
            text = mutate_bytes(rng, text.encode()).decode("latin-1")
        open(os.path.join(case, "scene.json"), "w", encoding="latin-1").write(text)
        outs = [os.path.join(case, n) for n in ("out.png", "bp.png", "report.json")]
        for o in outs:
            if rng.random() < 0.5:
                open(o, "wb").write(b"existing " + os.path.basename(o).encode())
        before = snapshot(outs)
        model = rng.choice(models)
        cmd = [cube4, "render", os.path.join(case, "scene.json"), "--model", model, "-q", "-o", outs[0],
               "--baseplane", outs[1], "--report", outs[2]]
        if model in ("reference", "splat"):  # no base plane
            cmd.remove("--baseplane"); cmd.remove(outs[1])
        try:
            r = subprocess.run(cmd, capture_output=True, timeout=a.timeout)
            code, err = r.returncode, r.stderr.decode(errors="replace")
        except subprocess.TimeoutExpired:
            code, err = "timeout", ""
        runs += 1
        codes[code] = codes.get(code, 0) + 1
        fault = None
        if code not in (0, 2):
            fault = f"exit {code}"
        elif code == 2:
            if snapshot(outs) != before:
                fault = "exit 2 changed an existing output or left a new one"
            leftovers = [f for f in os.listdir(case) if ".tmp" in f]
            if leftovers:
                fault = "exit 2 left temporaries " + ", ".join(leftovers)
        elif code == 0:
            written = [o for o in outs if model not in ("reference", "splat") or o != outs[1]]
            if any(not os.path.exists(o) or os.path.getsize(o) == 0 for o in written):
                fault = "exit 0 without every output"
        if fault:
            keep = os.path.join(found, f"{len(problems):03d}")
            shutil.copytree(case, keep)
            open(os.path.join(keep, "command.txt"), "w").write(" ".join(cmd) + "\n" + fault + "\n" + err)
            problems.append((fault, keep))
    print(f"fuzz_cli: {runs} runs in {a.minutes:g} min (seed {a.seed}); exit codes {codes}; {len(problems)} findings")
    for f, k in problems[:20]:
        print(f"  {f}: {k}")
    return 1 if problems else 0


sys.exit(main())
