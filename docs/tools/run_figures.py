#!/usr/bin/env python3
"""The renders whose figures the pages quote in their prose, made during the docs build.

Each run below is one `raycache render ... --stats` (counts do not depend on the machine).
A page quotes a figure of it as \\run{EXPR} or \\run{EXPR|FORMAT}: EXPR is a Python
expression over the runs, each a name below whose statistics are read as attributes
(`cube4_blocker_scanline.cache.miss_reasons.flushed`); FORMAT is a Python format spec
(`,` for integers by default, `.2f`, `.0%`), or `M` for millions with one decimal.
\\runcommand{NAME} is the command that made the run. docs/tools/run_figures_filter.py
replaces both when Doxygen reads a page; typed_figures.py (a test) fails on a figure
about a run typed by hand.

usage: run_figures.py RAYCACHE OUT_JSON     (renders every run, writes their statistics)
       run_figures.py --list                (prints the names of the runs)
"""
import json
import os
import subprocess
import sys
import tempfile

# name: the scene and the options of `raycache render`
RUNS = {
    # The paper's blocker cache on cube:4 at 512 by 512 (blocker_lists, table1, safety_cylinder)
    "cube4_blocker_scanline": "cube:4 --cache blocker --order scanline --width 512 --height 512",
    "cube4_blocker_bfs": "cube:4 --cache blocker --order bfs --width 512 --height 512",
    "cube4_cylinder_scanline": "cube:4 --cache cylinder --order scanline --width 512 --height 512",
    # Cylinders measured only when a ray may fit (safety_cylinder, complete_search)
    "cube8_blocker_bfs": "cube:8 --cache blocker --order bfs --width 512 --height 512",
    # Direction lists against blocker+ (direction_lists)
    "cube5_blockerplus_bfs": "cube:5 --cache blocker+ --order bfs --width 512 --height 512",
    "cube5_blockerdir_bfs": "cube:5 --cache blocker+dir --order bfs --width 512 --height 512",
    # blocker+ in front of a hierarchy (fast: stepping aside, lists on second meeting)
    "balls4_bvh_blockerplus_bfs": "balls:4 --accel bvh --cache blocker+ --order bfs --width 512 --height 512",
    "balls4_bvh_none": "balls:4 --accel bvh --cache none --order scanline --width 512 --height 512",
    # Breadth-first's band in front of the linear scan (fast)
    "cube8_blocker_bfs_band1": "cube:8 --cache blocker --order bfs --band 1 --width 512 --height 512",
    "cube8_blocker_bfs_band16": "cube:8 --cache blocker --order bfs --band 16 --width 512 --height 512",
    "cube8_none": "cube:8 --cache none --width 512 --height 512",
    # RayCache and the paper: the paper's cache against blocker+ and blocker+dir, tiles,
    # stepping aside, the banded progressive order
    "cube4_blockerplus_bfs": "cube:4 --cache blocker+ --order bfs --width 512 --height 512",
    "cube4_blockerdir_bfs": "cube:4 --cache blocker+dir --order bfs --width 512 --height 512",
    "balls2_blocker_scanline": "balls:2 --cache blocker --order scanline --width 256 --height 256",
    "balls2_blockerplus_scanline": "balls:2 --cache blocker+ --order scanline --width 256 --height 256",
    "balls2_bvh_blocker_bfs": "balls:2 --accel bvh --cache blocker --order bfs --width 256 --height 256",
    "balls2_bvh_blockerplus_bfs": "balls:2 --accel bvh --cache blocker+ --order bfs --width 256 --height 256",
    "cube4_blocker_progressive": "cube:4 --cache blocker --order progressive --width 512 --height 512",
    "cube4_blocker_progressive_band0": "cube:4 --cache blocker --order progressive --band 0 --width 512 --height 512",
}
SPREAD = "cube:4 --width 96 --height 96 --spp 4 --light-radius 0.3 --shadow-samples 4 --gloss 5 --gloss-samples 2 --seed 7"
for entries in ("shared", "per-sample"):
    for cache, order in (("blocker", "scanline"), ("cylinder", "scanline"), ("blocker", "bfs")):
        RUNS[f"spread_{cache}_{order}_{entries.replace('-', '_')}"] = (
            f"{SPREAD} --sample-entries {entries} --cache {cache} --order {order}")


def command(name):
    return f"raycache render {RUNS[name]} --stats {name}.json"


def main(argv):
    if argv[:1] == ["--list"]:
        print("\n".join(RUNS))
        return 0
    raycache, out = argv
    tmp = tempfile.mkdtemp(prefix="raycache-runs-")
    runs = {}
    for name, args in RUNS.items():
        path = os.path.join(tmp, name + ".json")
        subprocess.run([raycache, "render", *args.split(), "--stats", path, "-q"], check=True)
        with open(path) as f:
            runs[name] = {"command": command(name), "stats": json.load(f)}
    with open(out, "w") as f:
        json.dump(runs, f, indent=1, sort_keys=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
