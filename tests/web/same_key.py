#!/usr/bin/env python3
"""The Qt window and the page draw the same key and the same shapes at every stop of the
shipped tours. The window's side comes from the GUI test "[same-key]" (tests/ui/
test_same_key.cpp), which writes, per stop, the roles of the shapes it drew and the core's
key entries it showed; the page's from the page opened at ?tour=NAME&stop=K in headless
Chromium at 1280x720 (the roles of the shapes its worker sent and its core key entries). At
stops that show the Ray tree panel, its rows must equal the page's ray tree list.
Exits 1 on any stop where they differ.

Usage: same_key.py --gui-tests build/ui/raycache_gui_tests --page build/web-edition/web/index.html"""
import argparse
import json
import os
import pathlib
import subprocess
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from browser import Browser  # noqa: E402

TEXT = "document.getElementById('{}').textContent"


def native(gui_tests):
    with tempfile.TemporaryDirectory() as d:
        out = pathlib.Path(d) / "keys.json"
        env = dict(os.environ, QT_QPA_PLATFORM="offscreen", RAYCACHE_KEYS_OUT=str(out))
        r = subprocess.run([gui_tests, "[same-key]"], capture_output=True, text=True, env=env)
        if r.returncode != 0 or not out.exists():
            print(r.stdout[-3000:], r.stderr[-2000:])
            raise SystemExit("the GUI test [same-key] failed")
        return json.loads(out.read_text())


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--gui-tests", required=True)
    p.add_argument("--page", required=True)
    p.add_argument("--chromium", default="chromium")
    p.add_argument("--timeout", type=float, default=120.0)
    a = p.parse_args()
    stops = native(a.gui_tests)
    browser = Browser(a.chromium)
    differ = 0
    try:
        browser.call("Emulation.setDeviceMetricsOverride", session=True, width=1280, height=720,
                     deviceScaleFactor=1, mobile=False)
        for s in stops:
            url = pathlib.Path(a.page).resolve().as_uri() + f"?tour={s['tour']}&stop={s['stop']}"
            browser.open(url)
            frame = browser.wait_for(f"{TEXT.format('caption')}.includes('  step ') && "
                                     f"{TEXT.format('stop-title')} !== '' && window.__viewer.frame() && "
                                     "JSON.stringify({roles: [...new Set(window.__viewer.frame().shapes.map("
                                     "(x) => x.role))].sort(), keys: window.__viewer.frame().keys.map((k) => k.text)})",
                                     a.timeout)
            where = f"{s['tour']} stop {s['stop']}"
            if not frame:
                print(f"{where}: the page did not show the stop")
                differ += 1
                continue
            page = json.loads(frame)
            same = sorted(s["roles"]) == page["roles"] and s["keys"] == page["keys"]
            if "rayTree" in s:
                # The page's ray tree list: the whole path is each row's first cell's tooltip
                rows = json.loads(browser.evaluate(
                    "JSON.stringify([...document.querySelectorAll('#ray-tree tr')].slice(1).map((r) => "
                    "[r.cells[0].title].concat([...r.cells].slice(1).map((c) => c.textContent))))"))
                tree_same = rows == s["rayTree"]
                print(f"{where}: ray tree {'same' if tree_same else 'DIFFERENT'}: {len(rows)} rows")
                if not tree_same:
                    print(f"  window: {s['rayTree']}\n  page:   {rows}")
                same = same and tree_same
            print(f"{where}: {'same' if same else 'DIFFERENT'}: {len(page['roles'])} roles, {len(page['keys'])} keys")
            if not same:
                print(f"  window: {sorted(s['roles'])} {s['keys']}\n  page:   {page['roles']} {page['keys']}")
                differ += 1
    finally:
        browser.close()
    print(f"{len(stops) - differ} of {len(stops)} stops: the window and the page draw the same key and shapes")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
