#!/usr/bin/env python3
"""Measures, during the docs build, the figures of the pages that explain RayCache against
the paper, and writes them as HTML-table fragments for \\includedoc:

  paper_readings_measured.md   what each of RayCache's readings of the paper changes (cube:4)
  bfs_gain_measured.md         breadth-first's gain against depth and resolution, beam sizes
  trio_measured.md             the worked example: the three-sphere scene, cache by cache
  lesson_plan_measured.md      the lesson plan, its numbers filled in from this build

Every figure comes from `raycache render ... --stats` (counts do not depend on the machine;
the few times are medians of three renders on whatever machine builds the docs).

usage: measured_pages.py RAYCACHE BEAM_SIZES TEMPLATE_DIR OUT_DIR
"""
import csv
import io
import json
import os
import statistics
import subprocess
import sys
import tempfile

raycache, beam_sizes, template_dir, out_dir = sys.argv[1:5]
tmp = tempfile.mkdtemp(prefix="raycache-docs-")


def render(scene, *args):
    """The statistics of one render (a dict of the --stats JSON)."""
    path = os.path.join(tmp, "s.json")
    subprocess.run([raycache, "render", scene, *args, "--stats", path, "-q"], check=True)
    with open(path) as f:
        return json.load(f)


def n(x):
    return f"{x:,}"


def table(head, rows, note=None):
    # HTML, not Markdown: inside \includedoc a Markdown table floats beside the text
    out = ['<div><table class="markdownTable">',
           "<tr class=\"markdownTableHead\">" + "".join(f"<th>{h}</th>" for h in head) + "</tr>"]
    for r in rows:
        cells = [f"<td>{r[0]}</td>"] + [f'<td align="right">{c}</td>' for c in r[1:]]
        out.append("<tr class=\"markdownTableBody\">" + "".join(cells) + "</tr>")
    out.append("</table></div>")
    if note:
        out.append(f"<div>{note}</div>")
    out.append("")
    return "\n".join(out)


def command(scene, *args):
    # (\--: Doxygen would print -- as a dash)
    text = "raycache render " + " ".join([scene, *args]) + " --stats s.json"
    return "<tt>" + text.replace("--", "\\--") + "</tt>"


def write(name, text):
    with open(os.path.join(out_dir, name), "w") as f:
        f.write(text)


# ---- RayCache and the paper: cube:4 at 512x512, blocker ---------------------------------
SIZE = ["--width", "512", "--height", "512"]
cube4 = 64
runs = {order: render("cube:4", "--cache", "blocker", "--order", order, *SIZE) for order in ("scanline", "bfs")}
none = render("cube:4", "--cache", "none", *SIZE)
md = []
rows = []
for order, s in runs.items():
    c = s["cache"]
    listed = c["misses"] - s["complete_searches"]
    rows.append([f"blocker, {order}", n(s["rays"]["total"]), n(s["rays"]["shadow"]), n(c["misses"]),
                 n(c["miss_reasons"]["blocker_hit"]), n(s["complete_searches"]), n(listed),
                 n(s["intersection_tests"]), n(s["intersection_tests"] + listed * (cube4 - 1)),
                 f"{s['intersection_tests'] / none['intersection_tests']:.3f}",
                 f"{(s['intersection_tests'] + listed * (cube4 - 1)) / none['intersection_tests']:.3f}"])
md.append("<div><b>Misses answered from a list</b> (" + command("cube:4", "--cache blocker --order ORDER", *SIZE) +
          "; no cache: " + n(none["intersection_tests"]) + " tests)</div>\n")
md.append(table(["configuration", "rays", "shadow rays", "misses", "of which <tt>blocker_hit</tt>",
                 "complete searches", "misses answered from a list", "tests",
                 "tests if those misses searched", "tests / no cache", "if they searched"], rows,
                "<i>Misses answered from a list</i> = misses &minus; complete searches: the "
                "<tt>blocker_hit</tt> misses of every kind of ray and the misses of shadow rays, "
                "which RayCache answers without a search. <i>Tests if those misses searched</i> adds "
                f"{cube4 - 1} tests for each (a search from a sphere skips that sphere): computed from "
                "the counts, not rendered."))
rows = []
for scene in ("cube:3", "cube:4", "cube:5", "cube:10"):
    s = render(scene, "--cache", "blocker", "--order", "scanline", *SIZE)
    objects = int(scene.split(":")[1]) ** 3
    b = s["blocker_lists"]
    rows.append([scene, n(objects), n(b["built"]), f"{b['mean_length']:.2f}", n(b["hull_tests"]),
                 n(b["built"] * objects), n(s["complete_searches"]), n(s["cache"]["misses"])])
md.append("<div style=\"margin-top: 1em\"><b>Lists shared per pair, found through a hierarchy</b> (" +
          command("cube:N", "--cache blocker --order scanline", *SIZE) + ")</div>\n")
md.append(table(["scene", "objects", "lists built", "mean length", "hull tests (hierarchy)",
                 "hull tests a scan would make (lists &times; objects)", "complete searches", "misses"], rows,
                "A list is built once per (origin, target) pair met; a cache that built its list at "
                "every reload would build one at each miss that loads an object, up to the "
                "<i>misses</i> column."))
rows = []
for order, s in runs.items():
    r = s["cache"]["miss_reasons"]
    rows.append([f"blocker, {order}", n(r["flushed"]), n(r["origin_changed"]), n(r["target_missed"]),
                 n(r["left_cylinder"]), n(s["complete_searches"])])
md.append("<div style=\"margin-top: 1em\"><b>Flushing the cache tree</b> (the same renders)</div>\n")
md.append(table(["configuration", "<tt>flushed</tt>", "<tt>origin_changed</tt>", "<tt>target_missed</tt>",
                 "<tt>left_cylinder</tt>", "complete searches"], rows))
rows = []
for band in ("1", "8", "0"):
    s = render("cube:4", "--cache", "blocker", "--order", "bfs", "--band", band, *SIZE)
    rows.append([f"<tt>\\--band {band}</tt>" + (" (whole image)" if band == "0" else " (default)" if band == "8" else ""),
                 n(s["complete_searches"]), f"{s['complete_searches_per_beam']:.3f}", n(s["regions"]),
                 n(s["cache"]["deferrals"]), n(s["queue_peak"]), n(s["intersection_tests"])])
md.append("<div style=\"margin-top: 1em\"><b>Deferral and bands</b> (" +
          command("cube:4", "--cache blocker --order bfs --band B", *SIZE) + ")</div>\n")
md.append(table(["band", "complete searches", "per beam", "regions", "deferrals", "queue peak", "tests"], rows))
write("paper_readings_measured.md", "\n".join(md))

# ---- Breadth-first's gain: against depth, against resolution, and the beams ----------------
md = []


def timed_pair(scene, extra, repeat=3):
    """Blocker in scanline and in bfs order, their runs alternated (so that a machine's drift
    weighs on both alike): each order's first statistics with its median seconds."""
    runs = {"scanline": [], "bfs": []}
    for _ in range(repeat):
        for order in runs:
            runs[order].append(render(scene, "--cache", "blocker", "--order", order, *extra))
    out = []
    for order in ("scanline", "bfs"):
        s = runs[order][0]
        s["median_seconds"] = statistics.median(r["seconds"] for r in runs[order])
        out.append(s)
    return out


pairs = {}


def gain_rows(label, scene, extra):
    # One measurement per configuration: depth 5 at 512 by 512 appears in both tables, and
    # two separate timings of one render would differ by the machine's noise alone
    args = dict(zip(extra[::2], extra[1::2]))
    key = (scene, args.get("--depth", "5"), args.get("--width", "512"), args.get("--height", "512"))
    if key not in pairs:
        pairs[key] = timed_pair(scene, extra)
    scan, bfs = pairs[key]
    beams = scan["beam_tree"]["nodes"]
    return [label, n(scan["rays"]["total"]), n(beams), n(scan["complete_searches"]), n(bfs["complete_searches"]),
            f"{scan['complete_searches'] / beams:.2f}", f"{bfs['complete_searches'] / beams:.2f}",
            f"{scan['complete_searches'] / bfs['complete_searches']:.2f}",
            f"{scan['intersection_tests'] / bfs['intersection_tests']:.2f}",
            f"{scan['median_seconds'] / bfs['median_seconds']:.2f}"]


HEAD = ["", "rays", "beams", "searches, scanline", "searches, bfs", "per beam, scanline", "per beam, bfs",
        "bfs gain in searches", "bfs gain in tests", "bfs gain in time"]
rows = [gain_rows(f"depth {d}", "cube:4", ["--depth", str(d), *SIZE]) for d in range(1, 6)]
md.append("<div><b>Against the maximum depth</b> (cube:4 at 512 by 512; " +
          command("cube:4", "--cache blocker --order scanline|bfs --depth D", *SIZE) + ")</div>\n")
md.append(table(HEAD, rows))
rows = [gain_rows(f"{w} by {w}", "cube:4", ["--width", str(w), "--height", str(w)]) for w in (128, 256, 512, 1024)]
md.append("<div style=\"margin-top: 1em\"><b>Against resolution</b> (cube:4, depth 5; " +
          command("cube:4", "--cache blocker --order scanline|bfs --width W --height W") + ")</div>\n")
md.append(table(HEAD, rows,
                "<i>Gain</i> = scanline's figure divided by breadth-first's (above 1: breadth-first does "
                "better). Scanline's searches per beam is also the most a fill could gain in searches if it "
                "made exactly one complete search per beam. Times are "
                "medians of three renders each, scanline's and breadth-first's alternated, with "
                "<tt>\\--stats</tt>, on the machine that built these pages (depth 5 at 512 by 512 is one "
                "measurement, in both tables): on a shared machine they vary from build to build, the counts "
                "do not."))
out = subprocess.run([beam_sizes, "cube:4", "512", "512", "5"], check=True, capture_output=True, text=True).stdout
sizes = list(csv.DictReader(io.StringIO(out)))
classes = ["1", "2-3", "4-15", "16-63", "64-255", "256+"]
rows = []
for r in sizes:
    rays = int(r["rays"])
    rows.append([f"depth {r['depth']}", n(int(r["beams"])), n(rays), f"{rays / int(r['beams']):.1f}"] +
                [f"{n(int(r['beams ' + c]))} ({100.0 * int(r['rays ' + c]) / rays:.0f}%)" for c in classes])
md.append("<div style=\"margin-top: 1em\"><b>Beam sizes</b> (cube:4 at 512 by 512, depth 5: the beams of every "
          "ray-tree path of each depth, by the rays they hold; a path's depth counts its shadow rays one below the "
          "ray whose hit spawned them, so depth 1 is the eye rays alone and depth 6 the shadow rays of depth-5 "
          "hits; <tt>docs/tools/beam_sizes.cpp</tt>)</div>\n")
md.append(table(["", "beams", "rays", "rays per beam"] + [f"beams of {c} rays (their share of the rays)" for c in classes],
                rows))
write("bfs_gain_measured.md", "\n".join(md))

# ---- The worked example: trio, cache by cache -----------------------------------------------
md = []
configs = [("none", "scanline"), ("cylinder", "scanline"), ("blocker", "scanline"), ("blocker", "bfs")]
trio = {cfg: render("trio", "--cache", cfg[0], "--order", cfg[1]) for cfg in configs}
s0 = trio[("none", "scanline")]
r = s0["rays"]
md.append(table(["rays (256 by 256, depth 5)", "eye", "eye rays that hit", "shadow", "reflection", "total",
                 "beam-tree nodes", "average ray-tree size", "coherence"],
                [["trio", n(r["primary"]), n(r["primary_hits"]), n(r["shadow"]), n(r["reflection"]), n(r["total"]),
                  n(s0["beam_tree"]["nodes"]), f"{s0['beam_tree']['average_ray_tree_size']:.3f}",
                  f"{s0['beam_tree']['coherence']:.2e}"]]))
reasons = ["target_missed", "blocker_hit", "flushed", "origin_changed", "left_cylinder", "cold"]
rows = []
for (cache, order), s in trio.items():
    c = s["cache"]
    rows.append([f"{cache}, {order}", n(s["intersection_tests"]), n(s["complete_searches"]),
                 f"{s['complete_searches_per_beam']:.2f}", n(c["hits"]), n(c["misses"])] +
                [n(c["miss_reasons"][k]) for k in reasons] +
                [n(s["blocker_lists"]["built"]), f"{s['blocker_lists']['mean_length']:.2f}",
                 n(c["deferrals"]), n(s["regions"])])
md.append(table(["configuration", "tests", "complete searches", "per beam", "hits", "misses"] +
                [f"<tt>{k}</tt>" for k in reasons] + ["lists built", "mean length", "deferrals", "regions"], rows,
                "Measured during this docs build by " + command("trio", "--cache C --order O") + "."))
write("trio_measured.md", "\n".join(md))

# ---- The lesson plan, its numbers from this build ----------------------------------------------
L = {}
s = render("cube:4", "--cache", "none", *SIZE)
L["none_searches"] = n(s["complete_searches"])
L["none_rays"] = n(s["rays"]["total"])
s = render("cube:4", "--cache", "cylinder", "--order", "scanline", *SIZE)
for k in ("flushed", "left_cylinder", "target_missed"):
    L["cyl_" + k] = n(s["cache"]["miss_reasons"][k])
L["cyl_searches"] = n(s["complete_searches"])
L["cyl_per_beam"] = f"{s['complete_searches_per_beam']:.2f}"
s = runs["scanline"]
L["blk_searches"] = n(s["complete_searches"])
L["blk_per_beam"] = f"{s['complete_searches_per_beam']:.2f}"
s = runs["bfs"]
L["bfs_searches"] = n(s["complete_searches"])
L["bfs_per_beam"] = f"{s['complete_searches_per_beam']:.2f}"
L["bfs_queue"] = n(s["queue_peak"])
s = render("cube:4", "--cache", "blocker", "--order", "bfs", "--band", "0", *SIZE)
L["bfs_queue_whole"] = n(s["queue_peak"])
with open(os.path.join(template_dir, "lesson_plan_table.md.in")) as f:
    text = f.read()
for k, v in L.items():
    text = text.replace("@" + k + "@", v)
if "@" in text:
    sys.exit("lesson_plan_table.md.in: a placeholder was left unfilled")
write("lesson_plan_measured.md", text)

