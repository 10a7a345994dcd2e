#!/usr/bin/env python3
"""The test that no page of the docs holds a figure about a RayCache run typed by hand.

1. typed_figures.py finds no figure typed by hand in docs/mainpage.md and docs/pages/*.md
   (and does find one planted in a page made up here: the check can fail);
2. every \\run{...} and \\runcommand{...} names only runs that run_figures.py makes at
   docs build;
3. the Table 1 page's command and `raycache table1` render at the same size.

Prints how many generated figures the pages hold, and from which runs.

usage: check_run_figures.py SOURCE_ROOT RAYCACHE
"""
import glob
import os
import re
import subprocess
import sys
import tempfile

root, raycache = sys.argv[1:3]
tools = os.path.join(root, "docs", "tools")
sys.path.insert(0, tools)
import run_figures  # noqa: E402
import typed_figures  # noqa: E402

failures = []
pages = [os.path.join(root, "docs", "mainpage.md")] + sorted(glob.glob(os.path.join(root, "docs", "pages", "*.md")))

# 1. No figure typed by hand, and the finder finds one when there is one
for page in pages:
    for line, fig in typed_figures.figures(page):
        failures.append(f"{os.path.relpath(page, root)}:{line}: '{fig}' is a figure typed by hand: generate it "
                        "with \\run{...} (docs/tools/run_figures.py), or mark the paper's number \\paper{...} "
                        "or a setting \\setting{...}")
with tempfile.NamedTemporaryFile("w", suffix=".md", delete=False) as f:
    f.write("The cache made 12,345 misses and \\run{cube4_blocker_bfs.intersection_tests} tests; the paper "
            "says \"sped it up by another factor of 2-3\" (\\paper{.25, .15, .11}).\n")
planted = typed_figures.figures(f.name)
os.unlink(f.name)
if [fig for _, fig in planted] != ["12,345 misses"]:
    failures.append(f"typed_figures.py should find exactly '12,345 misses' in the planted page, found {planted}")

# 2. Every generated figure comes from a run the docs build makes
used = {}
for page in pages:
    text = open(page, encoding="utf-8").read()
    for m in re.finditer(r"\\run\{([^{}]*)\}", text):
        expr = m.group(1).partition("|")[0]
        names = set(re.findall(r"(?<![\w.])([A-Za-z_]\w*)\.", expr))
        for name in names:
            if name not in run_figures.RUNS:
                failures.append(f"{os.path.relpath(page, root)}: \\run{{{m.group(1)}}}: no run '{name}' in "
                                "docs/tools/run_figures.py")
            used.setdefault(name, 0)
            used[name] += 1
        if not names:
            failures.append(f"{os.path.relpath(page, root)}: \\run{{{m.group(1)}}} reads no run")
    for m in re.finditer(r"\\runcommand\{([^{}]*)\}", text):
        if m.group(1).strip() not in run_figures.RUNS:
            failures.append(f"{os.path.relpath(page, root)}: \\runcommand{{{m.group(1)}}}: no such run")
figures = sum(len(re.findall(r"\\run\{", open(p, encoding="utf-8").read())) for p in pages)

# 3. The Table 1 page and the command render at the same size
help_text = subprocess.run([raycache, "table1", "--help"], capture_output=True, text=True, check=True).stdout
m = re.search(r"--width[^\n]*\n\s*image width \(default: (\d+)", help_text)
cmake = open(os.path.join(root, "docs", "CMakeLists.txt"), encoding="utf-8").read()
args = re.search(r"set\(TABLE1_ARGS ([^)]*)\)", cmake)
if not m or not args:
    failures.append("cannot read table1's default width from its --help, or TABLE1_ARGS from docs/CMakeLists.txt")
else:
    page_width = re.search(r"--width (\d+)", args.group(1))
    if page_width and page_width.group(1) != m.group(1):
        failures.append(f"the Table 1 page renders at --width {page_width.group(1)}, table1's default is {m.group(1)}")
    if "512" not in m.group(1):
        # the page says 512 by 512 in its text
        failures.append(f"table1's default width is {m.group(1)}, the Table 1 page says 512 by 512")

print(f"{figures} figures generated at docs build (\\run) in {len(pages)} pages, from {len(used)} of the "
      f"{len(run_figures.RUNS)} runs of docs/tools/run_figures.py:")
for name, count in sorted(used.items()):
    print(f"  {count:3d}  {name}: raycache render {run_figures.RUNS.get(name, '?')}")
for f in failures:
    print(f, file=sys.stderr)
sys.exit(1 if failures else 0)
