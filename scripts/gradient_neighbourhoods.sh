#!/usr/bin/env bash
# Towards-scalable Fig. 2 with our estimators: runs the GradientNeighbourhoods
# tests (mean angular error of the zero-order, 6-, 10-, 12- and
# 26-neighbourhood gradients and of the bilinearly re-aligned 3x3x3 block on
# the rotated volume-sampled sphere, fixed point and float; and tilted 20°
# first), prints their tables, writes them into the "gradient-neighbourhoods"
# section of docs/accuracy.md and plots the first into
# docs/images/gradient-neighbourhoods.{png,svg}.
#   scripts/gradient_neighbourhoods.sh   (CUBE4_BUILD: the build folder, default build/;
#                                         CUBE4_PYTHON: a python3 with matplotlib)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${CUBE4_BUILD:-$here/build}
[ -n "${CUBE4_BUILD:-}" ] || "$here/scripts/setup.sh" >/dev/null
python=${CUBE4_PYTHON:-python3}
cmake --build "$build" --target test_gradient_neighbourhoods >/dev/null
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "gradient_neighbourhoods: measuring..." >&2
"$build/tb/test_gradient_neighbourhoods" --gtest_filter='GradientNeighbourhoods.*' \
  >"$tmp/test.txt" || { cat "$tmp/test.txt" >&2; exit 1; }
grep '^G[NT] ' "$tmp/test.txt" >"$tmp/rows.txt"
mkdir -p "$here/docs/images"
"$python" - "$tmp/rows.txt" "$here/docs/images/gradient-neighbourhoods" >"$tmp/section.md" <<'PY'
import datetime, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

lines = [l.split() for l in open(sys.argv[1])]
names = lines[0][3:]
rows = {"GN": {}, "GT": {}}  # tag -> (rotation, model) -> errors
for l in lines[1:]:
    rows[l[0]][(int(l[1]), l[2])] = [float(v) for v in l[3:]]
label = {"zero-order": "zero-order CD", "26b": "3x3x3 bilinear (40)"}
label.update({n: f"{n}-neighbourhood" for n in names if n not in label})

def table(tag, mean):
    rs = sorted({r for r, _ in rows[tag]})
    print("| rotation | " + " | ".join(label[n] for n in names) + " |")
    print("|---:|" + "---:|" * len(names))
    for r in rs:
        print(f"| {r}° | " + " | ".join(f"{rows[tag][(r, 'fixed')][e]:.2f} / {rows[tag][(r, 'float')][e]:.2f}"
                                        for e in range(len(names))) + " |")
    if mean:
        m = {k: [sum(rows[tag][(r, k)][e] for r in rs) / len(rs) for e in range(len(names))]
             for k in ("fixed", "float")}
        print("| **mean** | " + " | ".join(f"**{m['fixed'][e]:.2f} / {m['float'][e]:.2f}**"
                                            for e in range(len(names))) + " |")
    print()

print(f"Measured {datetime.date.today()} by `scripts/gradient_neighbourhoods.sh` (the tests "
      "`GradientNeighbourhoods.*`): mean angle, in degrees, between the gradient and the analytic normal at "
      "the first sample at or above half density on each ray; 64³ sphere of radius 24, rotated about the "
      "vertical axis. Each cell: fixed point / float.")
print()
table("GN", True)
print("![Mean angular error against rotation, per estimator](images/gradient-neighbourhoods.png)")
print()
print("The same, tilted 20° about the horizontal axis first, so that the rays shear in both x and y:")
print()
table("GT", False)
rotations = sorted({r for r, _ in rows["GN"]})
rows = rows["GN"]
plt.rcParams["svg.hashsalt"] = "cube4"
fig, ax = plt.subplots(figsize=(9, 4.2))
# Markers of decreasing size, so that estimators that coincide (10 and 12
# about the vertical axis) stay visible.
for e, n in enumerate(names):
    line, = ax.plot(rotations, [rows[(r, "fixed")][e] for r in rotations], marker="osD^vx"[e % 6],
                    ms=7 - e, label=f"{label[n]}, fixed")
    ax.plot(rotations, [rows[(r, "float")][e] for r in rotations], ls="--", color=line.get_color(),
            label=f"{label[n]}, float")
ax.set_xlabel("rotation about the vertical axis (degrees)")
ax.set_ylabel("mean angular error (degrees)")
ax.set_xticks(range(0, 91, 15))
ax.set_ylim(bottom=0)
ax.grid(alpha=0.3)
ax.legend(fontsize=7, bbox_to_anchor=(1.02, 1), loc="upper left")
ax.set_title("Gradient estimators on a volume-sampled sphere (cf. Towards-scalable Fig. 2)", fontsize=9)
fig.tight_layout()
fig.savefig(sys.argv[2] + ".png", dpi=110, metadata={"Software": None})
fig.savefig(sys.argv[2] + ".svg", metadata={"Date": None})
PY
cat "$tmp/section.md"
"$python" "$here/scripts/update_doc_section.py" "$here/docs/accuracy.md" gradient-neighbourhoods <"$tmp/section.md"
echo "gradient_neighbourhoods: docs/accuracy.md and docs/images/gradient-neighbourhoods.{png,svg} updated" >&2
