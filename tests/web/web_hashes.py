#!/usr/bin/env python3
"""The web edition gives the native bytes: for every scene, cache and order, the viewer page
in headless Chromium writes into #image-hash the SHA-256 that `raycache render --hash`
prints. Each scene's first render comes from the page's URL (?scene=...&run=end), the
others from its controls (Start over, Run to end). The page's cache and order menus must
offer what the CLI's registries hold, in their order. Exits 1 on any difference.
--scenes and --caches narrow the runs (the page built with the toy cache is checked so,
against the raycache built with it).

--bench instead times cube:5 at 256x256 in the page (its worker's time to the end) and
natively (`raycache render`'s), same cache and order, median of --repeat runs each.

Usage: web_hashes.py --cli build/src/raycache --page build-web/web/index.html
           --scenes-dir scenes [--width 20 --height 16] [--scenes a,b] [--caches a,b] [--bench]"""
import argparse
import json
import pathlib
import re
import statistics
import subprocess
import sys
import time
import urllib.parse

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from browser import Browser  # noqa: E402

BUILTINS = ["cube:3", "balls:2", "glass", "fill", "pair", "trio"]

HASH = "document.getElementById('image-hash').textContent"
CAPTION_ERROR = "document.getElementById('caption').className === 'error' && document.getElementById('caption').textContent"


def registered(cli, what):
    """The names in one of the core's registries, as `raycache list WHAT --json` gives them."""
    out = subprocess.run([cli, "list", what, "--json"], capture_output=True, text=True, check=True).stdout
    return [e["name"] for e in json.loads(out) if not e.get("comparison_only")]


def native(cli, scene, width, height, cache, order, extra=()):
    out = subprocess.run([cli, "render", scene, "--width", str(width), "--height", str(height), "--cache", cache,
                          "--order", order, *extra], capture_output=True, text=True, check=True).stdout
    return out


def page_url(page, scene, width, height, cache, order):
    query = urllib.parse.urlencode(dict(scene=scene, width=width, height=height, cache=cache, order=order, run="end"))
    return pathlib.Path(page).resolve().as_uri() + "?" + query


def web_hash(browser, timeout):
    value = browser.wait_for(f"({HASH}) || ({CAPTION_ERROR}) && ('error: ' + ({CAPTION_ERROR}))", timeout)
    return value or "timed out"


def run_with_controls(browser, cache, order):
    browser.evaluate(f"""(() => {{
        document.getElementById('cache').value = '{cache}';
        document.getElementById('order').value = '{order}';
        document.getElementById('open').click();
        document.getElementById('end').click(); }})()""")


def drop_file(browser, name, text):
    """Drops a file named `name` holding `text` on the page's picture, as a user would."""
    browser.evaluate(f"""(() => {{
        const files = new DataTransfer();
        files.items.add(new File([{json.dumps(text)}], {json.dumps(name)}));
        document.getElementById('canvas').dispatchEvent(
            new DragEvent('drop', {{ dataTransfer: files, bubbles: true, cancelable: true }})); }})()""")


def check_dropped(browser, a):
    """A dropped NFF file renders with the native hash; a bad one shows file:line:column."""
    wrong = []
    scene = pathlib.Path(a.scenes_dir) / "balls1.nff"
    browser.open(page_url(a.page, "cube:3", a.width, a.height, "blocker", "bfs"))
    web_hash(browser, a.timeout)
    drop_file(browser, "balls1.nff", scene.read_text())
    browser.wait_for("document.getElementById('image-hash').textContent === ''", a.timeout)
    browser.evaluate("document.getElementById('end').click()")
    expected = native(a.cli, str(scene), a.width, a.height, "blocker", "bfs", ["--hash", "-q"]).strip()
    got = web_hash(browser, a.timeout)
    if got != expected:
        wrong.append(f"dropped balls1.nff: web {got}, native {expected}")
    drop_file(browser, "bad.nff", "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\nresolution 8 8\ns 0 0 0 -1\n")
    error = browser.wait_for(CAPTION_ERROR, a.timeout) or ""
    if not error.startswith("/bad.nff:8:9: "):
        wrong.append(f"dropped bad.nff: caption {error!r}, not /bad.nff:8:9: ...")
    return wrong


def menu(browser, name):
    return browser.evaluate(f"[...document.getElementById('{name}').options].map((o) => o.value)")


def check_hashes(a):
    offered = {what: registered(a.cli, what) for what in ("caches", "orders")}
    caches = a.caches.split(",") if a.caches else offered["caches"]
    orders = offered["orders"]
    scenes = a.scenes.split(",") if a.scenes else \
        BUILTINS + ["scenes/" + p.name for p in sorted(pathlib.Path(a.scenes_dir).glob("*.nff"))]
    browser = Browser(a.chromium)
    matched, wrong, menus = 0, [], []
    try:
        # The menus hold the registries (a name only the URL gave would be added last)
        browser.open(page_url(a.page, scenes[0], a.width, a.height, offered["caches"][0], orders[0]))
        web_hash(browser, a.timeout)  # the menus are filled once the module is in
        for what, names in offered.items():
            shown = menu(browser, what[:-1])
            if shown != names:
                menus.append(f"the page's {what[:-1]} menu offers {shown}, the registry {names}")
        for scene in scenes:
            native_scene = str(pathlib.Path(a.scenes_dir) / scene[len("scenes/"):]) if scene.startswith("scenes/") else scene
            first = True
            for cache in caches:
                for order in orders:
                    expected = native(a.cli, native_scene, a.width, a.height, cache, order, ["--hash", "-q"]).strip()
                    if first:
                        browser.open(page_url(a.page, scene, a.width, a.height, cache, order))
                        first = False
                    else:
                        run_with_controls(browser, cache, order)
                    got = web_hash(browser, a.timeout)
                    if got == expected:
                        matched += 1
                    else:
                        wrong.append(f"{scene} {cache} {order}: web {got}, native {expected}")
        dropped = [] if a.scenes else check_dropped(browser, a)
    finally:
        browser.close()
    for w in menus + wrong + dropped:
        print("DIFFERENT", w)
    print(f"{matched} of {matched + len(wrong)} web hashes equal the native ones "
          f"({len(scenes)} scenes x {len(caches)} caches x {len(orders)} orders at {a.width}x{a.height})")
    print("menus: " + ("the registries'" if not menus else f"{len(menus)} differ"))
    if not a.scenes:
        print("dropped files: " + ("as native" if not dropped else f"{len(dropped)} wrong"))
    return 0 if not menus and not wrong and not dropped and matched == len(scenes) * len(caches) * len(orders) else 1


def web_seconds(browser):
    timing = browser.evaluate("document.getElementById('timing').textContent") or ""
    m = re.search(r"([\d.]+) ms", timing)
    return float(m.group(1)) / 1000 if m else None


def bench(a):
    """The page's first run (WebAssembly still in its baseline tier) and its best of --repeat
    runs after it (Start over, Run to end), against native's best of --repeat."""
    browser = Browser(a.chromium)
    try:
        for cache, order in [("none", "scanline"), ("blocker", "bfs"), ("blocker+", "bfs")]:
            browser.open(page_url(a.page, "cube:5", 256, 256, cache, order))
            if web_hash(browser, a.timeout) == "timed out":
                print("web render timed out")
                return 1
            first = web_seconds(browser)
            warm = []
            for _ in range(a.repeat):
                run_with_controls(browser, cache, order)
                if web_hash(browser, a.timeout) == "timed out":
                    print("web render timed out")
                    return 1
                warm.append(web_seconds(browser))
            cpu = [float(re.search(r": ([\d.]+) s,", native(a.cli, "cube:5", 256, 256, cache, order)).group(1))
                   for _ in range(a.repeat)]
            w, n = min(warm), min(cpu)
            print(f"cube:5 256x256 cache={cache} order={order}: web {w:.3f} s (first run {first:.3f} s), "
                  f"native {n:.3f} s, web/native {w / n:.2f} (best of {a.repeat})")
    finally:
        browser.close()
    return 0


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--cli", required=True)
    p.add_argument("--page", required=True)
    p.add_argument("--scenes-dir", required=True)
    p.add_argument("--chromium", default="chromium")
    p.add_argument("--width", type=int, default=20)
    p.add_argument("--height", type=int, default=16)
    p.add_argument("--scenes", help="comma-separated scenes (default: the built-in ones and every file of "
                   "--scenes-dir; the dropped-file check runs only then)")
    p.add_argument("--caches", help="comma-separated caches (default: every registered one)")
    p.add_argument("--timeout", type=float, default=60.0)
    p.add_argument("--bench", action="store_true")
    p.add_argument("--repeat", type=int, default=5)
    a = p.parse_args()
    start = time.monotonic()
    code = bench(a) if a.bench else check_hashes(a)
    print(f"({time.monotonic() - start:.1f} s)")
    return code


if __name__ == "__main__":
    sys.exit(main())
