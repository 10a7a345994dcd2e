#!/usr/bin/env python3
"""Writes the measured part of the Table 1 page from `raycache table1 --csv`: one Markdown
table per scene with every configuration the CSV holds (no list of caches is assumed), a
summary set against the paper's claim, and a bar chart (PNG, matplotlib).

usage: table1_page.py CSV COMMAND_TEXT OUT_MD OUT_PNG
"""
import csv
import sys
from collections import OrderedDict

csv_path, command, out_md, out_png = sys.argv[1:5]
rows = list(csv.DictReader(open(csv_path, newline="")))
if not rows:
    sys.exit(f"{csv_path}: no rows")
scenes = OrderedDict()
for r in rows:
    scenes.setdefault(r["scene"], []).append(r)


def num(x):
    try:
        return float(x)
    except ValueError:
        return None


def config(r):
    return f'{r["cache"]}, {r["order"]}'


md = ["Measured during this docs build with", "", "\\verbatim", command, "\\endverbatim", ""]
md.append("<div>Times are medians of interleaved repeats; <i>time</i> and <i>tests</i> are relative to "
          "<tt>none, scanline</tt> (the paper's \"Not cached\"); <i>paper</i> is the paper's Table 1 "
          "figure for the same cell, <tt>-</tt> where it has none.</div>")
md.append("")


def cell(rs, cache, order, key):
    for r in rs:
        if r["cache"] == cache and r["order"] == order:
            return num(r[key])
    return None


# The paper's own layout: rows Not cached / Cached / Cached, breadth-first, a column per scene,
# each cell "measured (the paper's)", time then tests
PAPER_ROWS = [("Not cached", "none", "scanline"), ("Cached", "blocker", "scanline"),
              ("Cached, breadth-first", "blocker", "bfs")]
md.append("<div style=\"margin-top: 1em\"><b>In the paper's layout</b> (its <i>Table 1 - Timing results</i>): time relative to "
          "not cached, measured in this build, the paper's figure in brackets; below, the same for "
          "intersection tests, which the paper does not report. \"Cached\" is read as <tt>blocker, "
          "scanline</tt> and \"Cached, breadth-first\" as <tt>blocker, bfs</tt>.</div>")
md.append("")
md.append('<div><table class="markdownTable">')
md.append("<tr class=\"markdownTableHead\"><th>Number of spheres</th>" +
          "".join(f"<th>{s.replace('cube:', '')}<sup>3</sup></th>" if s.startswith("cube:") else f"<th>{s}</th>"
                  for s in scenes) + "</tr>")
for label, cache, order in PAPER_ROWS:
    cells = []
    for scene, rs in scenes.items():
        t = cell(rs, cache, order, "time_ratio")
        p = next((r["paper_time_ratio"] for r in rs if r["cache"] == cache and r["order"] == order), "-")
        cells.append("-" if t is None else f"{t:.2f}" + ("" if p in ("-", "") else f" ({p})"))
    md.append(f"<tr class=\"markdownTableBody\"><td>{label}</td>" +
              "".join(f"<td align=\"right\">{c}</td>" for c in cells) + "</tr>")
for label, cache, order in PAPER_ROWS[1:]:
    cells = []
    for scene, rs in scenes.items():
        k = cell(rs, cache, order, "tests_ratio")
        cells.append("-" if k is None else f"{k:.3f}")
    md.append(f"<tr class=\"markdownTableBody\"><td>{label}: tests</td>" +
              "".join(f"<td align=\"right\">{c}</td>" for c in cells) + "</tr>")
md.append("</table></div>")
md.append("")
md.append("<div style=\"margin-top: 1em\"><b>Every configuration</b>, scene by scene:</div>")
md.append("")
for scene, rs in scenes.items():
    # (an HTML paragraph: inside \\includedoc a Markdown paragraph runs into the table)
    md.append(f"<div style=\"margin-top: 1em\"><b>{scene}</b> ({rs[0]['beam_nodes']} beam-tree nodes)</div>")
    md.append("")
    # HTML, not Markdown: inside \\includedoc a Markdown table floats beside the text
    md.append('<div><table class="markdownTable">')
    md.append("<tr class=\"markdownTableHead\"><th>configuration</th><th>seconds</th><th>time</th><th>paper</th>"
              "<th>tests</th><th>complete searches</th><th>searches per beam</th></tr>")
    for r in rs:
        md.append(f"<tr class=\"markdownTableBody\"><td>{config(r)}</td><td align=\"right\">{float(r['seconds']):.3f}</td>"
                  f"<td align=\"right\">{float(r['time_ratio']):.2f}</td><td align=\"right\">{r['paper_time_ratio']}</td>"
                  f"<td align=\"right\">{float(r['tests_ratio']):.3f}</td><td align=\"right\">{r['complete_searches']}</td>"
                  f"<td align=\"right\">{float(r['searches_per_beam']):.2f}</td></tr>")
    md.append("</table></div>")
    md.append("")


# The paper's claim, in this build's numbers: caching alone, then breadth-first on top

alone, bfs_gain, searches = [], [], []
for scene, rs in scenes.items():
    none = cell(rs, "none", "scanline", "time_ratio")
    scan = cell(rs, "blocker", "scanline", "time_ratio")
    bfs = cell(rs, "blocker", "bfs", "time_ratio")
    if none and scan and bfs:
        alone.append((scene, none / scan))
        bfs_gain.append((scene, scan / bfs))
    # (blocker+dir answers its misses from direction lists: it makes next to no complete search)
    spb = [(config(r), num(r["searches_per_beam"])) for r in rs if r["cache"] not in ("none", "blocker+dir")]
    if spb:
        searches.append((scene, min(spb, key=lambda c: c[1])))
if alone:
    md.append("<div><b>This build against the paper's claim.</b> Speed-up of caching alone (`blocker, "
              "scanline` against `none, scanline`): " +
              ", ".join(f"{s} {x:.2f}x" for s, x in alone) +
              " (the paper: 2-5 times). Further speed-up of breadth-first search (`blocker, bfs` "
              "against `blocker, scanline`): " + ", ".join(f"{s} {x:.2f}x" for s, x in bfs_gain) +
              " (the paper: another 2-3 times). A speed-up below 1 is a slow-down. Caching alone is " +
              ", ".join(f"{s} {'within' if 2 <= x <= 5 else 'below' if x < 2 else 'above'}" for s, x in alone) +
              " the paper's range.</div>")
    md.append("")
# The fastest cached configuration of each scene
fastest = []
for scene, rs in scenes.items():
    cached = [(num(r["time_ratio"]), num(r["tests_ratio"]), config(r)) for r in rs if r["cache"] != "none"]
    if cached:
        fastest.append((scene, min(cached)))
if fastest:
    md.append("<div style=\"margin-top: 1em\"><b>The fastest cache of each scene</b> in this build: " +
              ", ".join(f"{s} {c[2]} at {c[0]:.2f} of the uncached time ({c[1]:.3f} of its tests)"
                        for s, c in fastest) + ".</div>")
    md.append("")
if searches:
    md.append("<div style=\"margin-top: 1em\"><b>Complete searches per beam</b>, the fewest of any cache in this build: " +
              ", ".join(f"{s} {c[1]:.2f} ({c[0]})" for s, c in searches) +
              ". <i>RayCache's reading</i> of the paper's \"theoretical maximum\" is about 1 for a cache with one "
              "entry per ray-tree path; blocker+dir, which answers its misses from direction lists, is left out.</div>")
    md.append("")
    # Under the paper's rule, "Each cache miss causes all the objects to be searched": every
    # miss a complete search (RayCache answers some misses from a list, without one)
    rule = []
    for scene, rs in scenes.items():
        for r in rs:
            if (r["cache"], r["order"]) == ("blocker", "bfs") and num(r["beam_nodes"]):
                rule.append((scene, num(r["searches_per_beam"]), num(r["misses"]) / num(r["beam_nodes"])))
    if rule:
        md.append("<div style=\"margin-top: 1em\"><b>The blocker cache under the paper's rule</b>: \"Each cache miss "
                  "causes all the objects to be searched\". RayCache answers some misses from a list without a "
                  "complete search (\\ref paper_and_raycache); counted the paper's way, every miss a complete search, "
                  "<tt>blocker, bfs</tt> makes " +
                  ", ".join(f"{s} {m:.2f} (RayCache's count {c:.2f})" for s, c, m in rule) +
                  " complete searches per beam.</div>")
        md.append("")
# The trend with N, time against time and tests against tests: the paper reports time only
trend = []
for cache, order, paper in (("blocker", "scanline", ".53, .29, .20"), ("blocker", "bfs", ".25, .15, .11")):
    ts = [(s, cell(rs, cache, order, "time_ratio"), cell(rs, cache, order, "tests_ratio")) for s, rs in scenes.items()]
    ts = [t for t in ts if t[1] is not None and t[2] is not None]
    if len(ts) < 2 or not all(s.startswith("cube:") for s, _, _ in ts):
        continue

    def way(xs):
        return "falls" if all(b < a for a, b in zip(xs, xs[1:])) else "rises" if all(
            b > a for a, b in zip(xs, xs[1:])) else "neither falls nor rises throughout"
    times = [t for _, t, _ in ts]
    tests = [k for _, _, k in ts]
    trend.append(f"<tt>{cache}, {order}</tt>: its time {way(times)} with N (" +
                 ", ".join(f"{t:.2f}" for t in times) + f"; the paper's {paper}), its tests ratio {way(tests)} (" +
                 ", ".join(f"{k:.3f}" for k in tests) + ")")
if trend:
    md.append("<div style=\"margin-top: 1em\"><b>The trend with N</b> (" + ", ".join(scenes) + "), relative to no "
              "cache: " + "; ".join(trend) + ".</div>")
    md.append("")
# What differs from 1986: the costs this build measured, and what the counts predict from them
cost = [("<div style=\"margin-top: 1em\"><b>Costs measured in this build</b> (the same run): what one "
         "object test costs, what a ray costs besides searching (making it, stepping the order, shading, "
         "adding to its pixel; measured by answering every search from a table of recorded answers), "
         "and, per configuration, the time its counts predict if the cache's own work were free, against "
         "the time measured. The difference, per miss, is that work: looking up, building lists and "
         "cylinders, testing list entries one by one instead of in the scan's tight loop.</div>"), ""]
for scene, rs in scenes.items():
    if "test_ns" not in rs[0] or not rs[0]["test_ns"]:
        continue
    rays = num(rs[0]["rays"])
    by_order = {r["order"]: num(r["besides_search_seconds"]) for r in rs}
    cost.append(f"<div style=\"margin-top: 0.5em\"><b>{scene}</b>: an object test "
                f"{num(rs[0]['test_ns']):.2f} ns; a ray besides searching " +
                ", ".join(f"{1e9 * t / rays:.0f} ns ({o})" for o, t in by_order.items()) + "</div>")
    cost.append("")
    cost.append('<div><table class="markdownTable">')
    cost.append("<tr class=\"markdownTableHead\"><th>configuration</th><th>time</th>"
                "<th>predicted by the counts</th><th>time / predicted</th><th>cache's own work per miss</th></tr>")
    for r in rs:
        if r["cache"] == "none":
            continue
        cost.append(f"<tr class=\"markdownTableBody\"><td>{config(r)}</td><td align=\"right\">"
                    f"{float(r['time_ratio']):.3f}</td><td align=\"right\">{float(r['predicted_time_ratio']):.3f}</td>"
                    f"<td align=\"right\">{float(r['time_ratio']) / float(r['predicted_time_ratio']):.2f}</td>"
                    f"<td align=\"right\">{float(r['own_ns_per_miss']):.0f} ns</td></tr>")
    cost.append("</table></div>")
    cost.append("")
    # Breadth-first against scanline with the same cache, in seconds
    pairs = [(c, cell(rs, c, "bfs", "seconds"), cell(rs, c, "scanline", "seconds"))
             for c in OrderedDict((r["cache"], None) for r in rs) if c != "none"]
    pairs = [(c, b / s) for c, b, s in pairs if b and s]
    if pairs:
        cost.append(f"<div style=\"margin-top: 0.5em\">{scene}, breadth-first against scanline with the same "
                    "cache, in seconds: " + ", ".join(f"<tt>{c}</tt> {x:.2f}" for c, x in pairs) +
                    " (below 1: breadth-first is faster).</div>")
        cost.append("")
md.extend(cost)
md.append("\\image html table1_chart.png \"Time and intersection tests relative to no cache, "
          "per configuration and scene; black ticks: the paper's time\"")
md.append("")
open(out_md, "w").write("\n".join(md))

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

configs = list(OrderedDict((config(r), None) for r in rows))
# Read from the back row: one x scale for every scene, text at projector size, and the
# legend (the paper's ticks too) above the panels, where it covers no bar
fig, axes = plt.subplots(1, len(scenes), figsize=(4.2 * len(scenes), 4.6), sharex=True, sharey=True,
                         squeeze=False)
for ax, (scene, rs) in zip(axes[0], scenes.items()):
    by = {config(r): r for r in rs}
    ys = range(len(configs))
    t = [num(by[c]["time_ratio"]) if c in by else 0 for c in configs]
    k = [num(by[c]["tests_ratio"]) if c in by else 0 for c in configs]
    ax.barh([y - 0.2 for y in ys], t, height=0.38, color="#3b6fb6", label="time")
    ax.barh([y + 0.2 for y in ys], k, height=0.38, color="#e08a2c", label="tests")
    ticked = False
    for y, c in zip(ys, configs):
        p = num(by[c]["paper_time_ratio"]) if c in by else None
        if p is not None:
            ax.plot([p, p], [y - 0.45, y + 0.05], color="black", linewidth=2.5,
                    label=None if ticked else "the paper's time")
            ticked = True
    ax.axvline(1.0, color="#888", linewidth=0.8, linestyle=":")
    ax.set_title(scene, fontsize=13)
    ax.set_yticks(list(ys))
    ax.set_yticklabels(configs, fontsize=11)
    ax.invert_yaxis()
    ax.tick_params(axis="x", labelsize=11)
    ax.set_xlabel("relative to none, scanline", fontsize=11)
handles, labels = axes[0][0].get_legend_handles_labels()
fig.legend(handles, labels, loc="upper center", ncol=len(labels), fontsize=12, frameon=False)
fig.tight_layout(rect=(0, 0, 1, 0.92))
fig.savefig(out_png, dpi=90)
