#!/usr/bin/env python3
"""Measures the page's memory against native's for one render run to the end: the page in
headless Chromium (the resident memory of its renderer processes, which hold the page and its
worker, after the run; and the worker's WebAssembly heap) and the Qt GUI rendering the same
headless to a screenshot (its peak resident memory, /usr/bin/time's). Prints the figures; a
measurement, not a test.

Usage: page_memory.py --page build/web-edition/web/index.html --gui build/ui/raycache-gui
           [--cli build/src/raycache] [--scene cube:4 --sizes 1024,2048 --cache blocker+ --order bfs]"""
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


def renderer_rss_mb(browser):
    """The resident memory of this browser's renderer processes (found by its profile folder:
    Chromium starts them through its zygote, not as the browser's own children)."""
    total = 0
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
    return total / 1024


def page(a, size):
    browser = Browser(a.chromium)
    try:
        query = f"scene={a.scene}&width={size}&height={size}&cache={a.cache}&order={a.order}&run=end"
        browser.open(pathlib.Path(a.page).resolve().as_uri() + "?" + query)
        if not browser.wait_for(HASH, a.timeout):
            return None
        return renderer_rss_mb(browser)
    finally:
        browser.close()


def native(a, size):
    with tempfile.TemporaryDirectory() as d:
        env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
        r = subprocess.run(["/usr/bin/time", "-v", a.gui, a.scene, "--width", str(size), "--height", str(size),
                            "--cache", a.cache, "--order", a.order, "--steps", str(10 ** 12),
                            "--screenshot", str(pathlib.Path(d) / "shot.png")],
                           capture_output=True, text=True, env=env)
        m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", r.stderr)
        return int(m.group(1)) / 1024 if m else None


def cli_rss_mb(a, size):
    """`raycache render`'s peak resident memory for the same render (no viewer's records)."""
    r = subprocess.run(["/usr/bin/time", "-v", a.cli, "render", a.scene, "--width", str(size), "--height", str(size),
                        "--cache", a.cache, "--order", a.order, "-q", "--hash"], capture_output=True, text=True)
    m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", r.stderr)
    return int(m.group(1)) / 1024 if m else None


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
    a = p.parse_args()
    for size in [int(s) for s in a.sizes.split(",")]:
        web, nat = page(a, size), native(a, size)
        ratio = f"{web / nat:.1f}x" if web and nat else "-"
        cli = f", raycache render {round(cli_rss_mb(a, size))} MB" if a.cli else ""
        print(f"{a.scene} {size}x{size} {a.cache} {a.order}: page {web and round(web)} MB (renderer processes' "
              f"resident memory after the run), native GUI {nat and round(nat)} MB (peak resident), "
              f"page/GUI {ratio}{cli}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
