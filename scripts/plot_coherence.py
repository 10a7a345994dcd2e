#!/usr/bin/env python3
"""The chart of `raycache coherence SCENE --sweep P --plot out.png`: for each value of the swept
parameter, every cache's hit rate, complete searches per ray, and intersection tests and time
against no cache (scanline order). Where a ratio line crosses 1, that cache stops paying.
Usage: plot_coherence.py data.csv out.png "title"  (needs python3-matplotlib)"""
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

path, out, title = sys.argv[1], sys.argv[2], sys.argv[3]
rows = list(csv.DictReader(open(path)))
sweep = rows[0]["sweep"]
x = [float(r["value"]) for r in rows]
colors = {"scanline": "tab:blue", "progressive": "tab:orange", "bfs": "tab:green"}
styles = {"none": ":", "cylinder": "--", "blocker": "-.", "blocker+": "-"}
panels = [("hit_rate", "hit rate (rays answered from the cache)"),
          ("searches_per_ray", "complete searches per ray"),
          ("tests_ratio", "intersection tests / no cache, scanline"),
          ("time_ratio", "time (thread CPU) / no cache, scanline")]
fig, axes = plt.subplots(1, 4, figsize=(20, 5.8))
for ax, (measure, label) in zip(axes, panels):
    for cache in styles:
        for order in colors:
            key = f"{cache}_{order}_{measure}"
            if key not in rows[0] or (cache == "none" and measure == "hit_rate"):
                continue
            ax.plot(x, [float(r[key]) for r in rows], styles[cache], color=colors[order], marker="o",
                    markersize=3, linewidth=1.3, label=f"{cache}, {order}")
    if measure.endswith("ratio"):
        ax.axhline(1.0, color="black", linewidth=0.8)
        ax.text(x[0], 1.0, " = no cache, scanline: above, the cache costs more", fontsize=7, va="bottom")
    ax.set_xlabel(sweep + (" (degrees)" if sweep == "gloss" else ""))
    ax.set_ylabel(label)
    ax.grid(True, alpha=0.3)
    if min(x) > 0 and max(x) / min(x) >= 8:
        ax.set_xscale("log", base=2 if sweep == "spp" else 10)
handles, labels = axes[1].get_legend_handles_labels()
fig.legend(handles, labels, loc="lower center", ncol=6, fontsize=8, title="cache (line style), order (colour)",
           title_fontsize=8)
fig.suptitle(title)
fig.tight_layout(rect=(0, 0.14, 1, 1))
fig.savefig(out, dpi=100)
