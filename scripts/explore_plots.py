#!/usr/bin/env python3
"""Plots of a `cube4 explore` run (docs/explore.md): accuracy against each
cost (modelled cycles per image, chip NAND2-equivalents, simulation time),
one colour per scene, the Pareto front of each joined by a line. The upper
row gives PSNR against the reference renderer, the lower row the mean RGB
error with bela's line: RGB errors under 2 % are hard to see.

  scripts/explore_plots.py OUT     (reads OUT/results.json, writes OUT/plots/fronts.{png,svg})
"""
import json, math, os, sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = sys.argv[1]
doc = json.load(open(os.path.join(out, "results.json")))
ok = [p for p in doc["points"] if p.get("status") == "ok"]
if not ok:
    sys.exit("explore_plots: no point finished, nothing to plot")

costs = [("cycles", lambda p: p.get("cycles_per_image"), "modelled cycles per image"),
         ("gates", lambda p: p.get("gates", {}).get("nand2_chip"), "chip logic (NAND2-eq)"),
         ("sim_time", lambda p: p.get("sim_seconds"), f"simulation time per image (s, {doc['model']})")]
groups = sorted({json.dumps(p["scene_group"]) for p in ok})
fig, axes = plt.subplots(2, len(costs), figsize=(5 * len(costs), 8), squeeze=False)
for col, (name, cost_of, label) in enumerate(costs):
    for g_i, g in enumerate(groups):
        pts = [p for p in ok if json.dumps(p["scene_group"]) == g and cost_of(p) is not None]
        if not pts:
            continue
        colour = f"C{g_i}"
        tag = json.loads(g)
        for row, (metric, ylabel) in enumerate([("psnr", "PSNR against the reference (dB)"),
                                                ("mean", "mean RGB error (%)")]):
            ax = axes[row][col]
            def y(p):
                e = p["error"]
                if metric == "psnr":
                    return e["psnr_db"] if e["psnr_db"] is not None else math.nan
                return 100 * e["mean"]
            ax.scatter([cost_of(p) for p in pts], [y(p) for p in pts], color=colour, s=18, alpha=0.6,
                       label=str(tag) if row == 0 else None)
            front = sorted((p for p in pts if p.get("pareto", {}).get(name)), key=cost_of)
            if front:
                ax.plot([cost_of(p) for p in front], [y(p) for p in front], color=colour, lw=1.5)
                ax.scatter([cost_of(p) for p in front], [y(p) for p in front], s=70, facecolors="none",
                           edgecolors=colour, linewidths=1.5)
            ax.set_xlabel(label)
            ax.set_ylabel(ylabel)
            ax.grid(True, alpha=0.3)
    if max((cost_of(p) or 0) for p in ok) > 0:
        for row in range(2):
            ax = axes[row][col]
            xs = [cost_of(p) for p in ok if cost_of(p)]
            if xs and max(xs) / min(xs) > 20:
                ax.set_xscale("log")
    axes[1][col].axhline(2.0, color="grey", ls="--", lw=1)
    axes[1][col].text(axes[1][col].get_xlim()[0], 2.0, " 2 %: hard to see (bela §III.A)", va="bottom",
                      fontsize=8, color="grey")
axes[0][0].legend(fontsize=8, title="scene")
fig.suptitle(f"cube4 explore: {os.path.basename(doc['sweep'])} ({len(ok)} points; lines: Pareto fronts)")
fig.tight_layout()
os.makedirs(os.path.join(out, "plots"), exist_ok=True)
for ext in ("png", "svg"):
    fig.savefig(os.path.join(out, "plots", f"fronts.{ext}"), dpi=110)
