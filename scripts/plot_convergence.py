#!/usr/bin/env python3
"""The chart of `raycache convergence SCENE --plot out.png`: progress and supersampling error
against rays and run time, from the CSV the command writes.
Usage: plot_convergence.py data.csv out.png "title"  (needs python3-matplotlib)"""
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

path, out, title = sys.argv[1], sys.argv[2], sys.argv[3]
rows = list(csv.DictReader(open(path)))
colors = {"scanline": "tab:blue", "progressive": "tab:orange", "bfs": "tab:green"}
styles = {"none": ":", "cylinder": "--", "blocker": "-.", "blocker+": "-"}
fig, axes = plt.subplots(1, 3, figsize=(17, 5.2))
def series(kind):
    out = {}
    for r in rows:
        if r["kind"] == kind:
            out.setdefault((r["cache"], r["order"]), []).append(r)
    return out
for (cache, order), pts in series("progress").items():
    steps = [int(p["steps"]) for p in pts]
    secs = [float(p["seconds"]) for p in pts]
    err = [float(p["rmse"]) for p in pts]
    label = cache + ", " + order
    axes[0].plot(steps, err, styles[cache], color=colors[order], label=label, linewidth=1.4)
    axes[1].plot(secs, err, styles[cache], color=colors[order], label=label, linewidth=1.4)
for (cache, order), pts in series("supersample").items():
    secs = [float(p["seconds"]) for p in pts]
    err = [float(p["rmse"]) for p in pts]
    spp = [int(p["spp"]) for p in pts]
    axes[2].loglog(secs, err, styles[cache], marker="o", markersize=3.5, color=colors[order],
                   label=cache + ", " + order, linewidth=1.2)
    if cache == "blocker+" and order == "bfs":
        for s, e, n in zip(secs, err, spp):
            axes[2].annotate(str(n), (s, e), textcoords="offset points", xytext=(4, 4), fontsize=7)
axes[0].set_xlabel("rays traced")
axes[0].set_ylabel("RMSE of the partial image against the final one")
axes[0].set_title("progress against rays traced")
axes[1].set_xlabel("seconds")
axes[1].set_title("progress against run time")
axes[2].set_xlabel("seconds (all samples so far)")
axes[2].set_ylabel("RMSE against the high-sample reference")
axes[2].set_title("jittered supersampling, 1 to N samples per pixel")
for ax in axes:
    ax.grid(True, which="both", alpha=0.3)
axes[1].legend(fontsize=7, ncol=1, title="cache, order", title_fontsize=7)
axes[2].legend(fontsize=7, ncol=1, title="cache, order", title_fontsize=7)
fig.suptitle(title)
fig.tight_layout()
fig.savefig(out, dpi=110)
