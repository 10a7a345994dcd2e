#!/usr/bin/env python3
"""Measures the page's memory against native's for one render run to the end: the page in
headless Chromium, the Qt GUI rendering the same headless to a screenshot (its peak resident
memory) and, with --cli, `raycache render` (the same). The page's figures,
after the run:
- all: the resident memory of every renderer process of the browser (the page's, the blank
  page it started from, the spare one), Chromium's shared code counted once per process;
- own: the anonymous resident memory (RssAnon) of the page's renderer, the one holding the
  page and its worker: what the page itself holds, without the file-backed code pages;
- heap: the worker's WebAssembly memory (the core's heap; it never shrinks).
With --limit R and --cli, exits 1 when the page's own memory is over R times the CLI's.

Usage: page_memory.py --page build/web-edition/web/index.html --gui build/ui/raycache-gui
           [--cli build/src/raycache] [--scene cube:4 --sizes 1024,2048 --cache blocker+ --order bfs]
           [--limit 3]"""
import argparse
import os
import pathlib
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from browser import Browser  # noqa: E402

HASH = "document.getElementById('image-hash').textContent"


def renderer_memory_mb(browser):
    """The resident memory of this browser's renderer processes (found by its profile folder:
    Chromium starts them through its zygote, not as the browser's own children): all of it,
    and the largest one's anonymous memory (the page's renderer)."""
    total = own = 0
    profile = ("--user-data-dir=" + browser.profile.name).encode()
    for entry in pathlib.Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            cmd = (entry / "cmdline").read_bytes()  # Chromium rewrites it: arguments may be joined by spaces
            status = (entry / "status").read_text()
        except OSError:
            continue
        if b"--type=renderer" in cmd and profile in cmd:
            total += int(re.search(r"VmRSS:\s+(\d+) kB", status).group(1))
            own = max(own, int(re.search(r"RssAnon:\s+(\d+) kB", status).group(1)))
    return total / 1024, own / 1024


def page(a, size):
    """{all, own, heap} in MB, or None when the run did not end."""
    browser = Browser(a.chromium)
    try:
        query = f"scene={a.scene}&width={size}&height={size}&cache={a.cache}&order={a.order}&run=end"
        browser.open(pathlib.Path(a.page).resolve().as_uri() + "?" + query)
        if not browser.wait_for(HASH, a.timeout):
            return None
        total, own = renderer_memory_mb(browser)
        heap = browser.evaluate("window.__viewer.frame().heapBytes") or 0
        return {"all": total, "own": own, "heap": heap / 2 ** 20}
    finally:
        browser.close()


def peak_rss_mb(cmd, env=None):
    """The peak resident memory of the process `cmd` runs, in MB (its own rusage, read by
    os.wait4: no /usr/bin/time needed); None when it failed."""
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    return usage.ru_maxrss / 1024 if proc.returncode == 0 else None


def native(a, size):
    """The Qt GUI's peak resident memory rendering the same, headless, to a screenshot."""
    with tempfile.TemporaryDirectory() as d:
        env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
        return peak_rss_mb([a.gui, a.scene, "--width", str(size), "--height", str(size), "--cache", a.cache,
                            "--order", a.order, "--steps", str(10 ** 12),
                            "--screenshot", str(pathlib.Path(d) / "shot.png")], env)


def cli_rss_mb(a, size):
    """`raycache render`'s peak resident memory for the same render (no viewer's records)."""
    return peak_rss_mb([a.cli, "render", a.scene, "--width", str(size), "--height", str(size),
                        "--cache", a.cache, "--order", a.order, "-q", "--hash"])


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--page", required=True)
    p.add_argument("--gui", required=True)
    p.add_argument("--cli", help="also raycache render's peak resident memory")
    p.add_argument("--chromium", default="chromium")
    p.add_argument("--scene", default="cube:4")
    p.add_argument("--sizes", default="1024,2048")
    p.add_argument("--cache", default="blocker+")
    p.add_argument("--order", default="bfs")
    p.add_argument("--timeout", type=float, default=900.0)
    p.add_argument("--limit", type=float, help="with --cli: exit 1 when the page's own memory is over this many "
                                                 "times raycache render's")
    a = p.parse_args()
    over = False
    for size in [int(s) for s in a.sizes.split(",")]:
        web, gui = page(a, size), native(a, size)
        cli = cli_rss_mb(a, size) if a.cli else None
        mb = lambda v: f"{round(v):,} MB" if v else "-"  # noqa: E731
        print(f"{a.scene} {size}x{size} {a.cache} {a.order}:")
        if web:
            print(f"  page: all renderers {mb(web['all'])}, its own {mb(web['own'])} "
                  f"(WebAssembly heap {mb(web['heap'])})")
        print(f"  native GUI {mb(gui)} (peak resident)" + (f", raycache render {mb(cli)}" if cli else ""))
        if a.limit and not (web and cli):
            print("  not measured: the page's run did not end or raycache render failed")
            over = True
        if web and cli:
            ratio = web["own"] / cli
            print(f"  page's own / raycache render: {ratio:.1f}x" + (f" (limit {a.limit}x)" if a.limit else ""))
            over |= bool(a.limit) and ratio > a.limit
        if web and gui:
            print(f"  page's own / native GUI: {web['own'] / gui:.2f}x")
    return 1 if over else 0


if __name__ == "__main__":
    sys.exit(main())
