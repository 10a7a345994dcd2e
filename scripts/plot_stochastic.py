#!/usr/bin/env python3
"""The chart of `raycache convergence SCENE --stochastic --plot out.png`: RMSE against a
high-sample reference (y) against the seconds a render took (x), one curve per cache and
order, one point per sample count. Every configuration makes the same image at a given
count, so the curves differ in time only: at any error, the leftmost curve gets there first.
Usage: plot_stochastic.py data.csv out.png "title"  (needs python3-matplotlib)"""
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

path, out, title = sys.argv[1], sys.argv[2], sys.argv[3]
rows = [r for r in csv.DictReader(open(path)) if r["kind"] == "stochastic"]
colors = {"scanline": "tab:blue", "progressive": "tab:orange", "bfs": "tab:green"}
styles = {"none": ":", "cylinder": "--", "blocker": "-.", "blocker+": "-"}
curves = {}
for r in rows:
    curves.setdefault((r["cache"], r["order"]), []).append(r)
fig, ax = plt.subplots(figsize=(9, 6))
for (cache, order), pts in curves.items():
    secs = [float(p["seconds"]) for p in pts]
    err = [float(p["rmse"]) for p in pts]
    ax.loglog(secs, err, styles[cache], marker="o", markersize=3.5, color=colors[order], linewidth=1.3,
              label=f"{cache}, {order}")
    if cache == "none" and order == "scanline":
        for s, e, p in zip(secs, err, pts):
            ax.annotate(p["spp"] + " spp", (s, e), textcoords="offset points", xytext=(5, 3), fontsize=7)
ax.set_xlabel("seconds of CPU for the render (log)")
ax.set_ylabel("RMSE against the high-sample reference (log)")
ax.grid(True, which="both", alpha=0.3)
ax.legend(fontsize=7, title="cache (line style), order (colour)", title_fontsize=7)
ax.set_title(title)
fig.tight_layout()
fig.savefig(out, dpi=100)
