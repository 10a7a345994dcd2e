#!/usr/bin/env python3
"""The page as a student meets it, in headless Chromium at 1280x720: each check below opens
the page as a student would and reads what it shows. Exits 1 on any failed check.

- first view: with no parameters, the lecture's first stop (hanrahan86, stop 1), its caption
  on screen and its ray in focus with overlays drawn;
- URL parameters: cache=blocker+ written unencoded (the '+' reads as a space) or as
  blocker%2B chooses blocker+, and the page's hash is the native one;
- every error is a sentence: ?cache=bogus names the cache and the choices; a width over
  the page's limit says the limit, and nothing is traced;
- Open file: the button's file input traces a file with zero-area triangles, names each
  skipped one (file:line:column), counts them in left out, and gives the native hash with
  every cache; a file that starts with a UTF-8 byte-order mark opens;
- a bad file clears the old picture and statistics, and Ray then says why nothing happens;
- compare: a click selects the same pixel in both panes;
- layout: at the tours' compare stops both pictures, and at every stop checked both
  captions, are on screen.

Usage: page_product.py --cli build/src/raycache --page build/web-edition/web/index.html
           --data tests/data"""
import argparse
import json
import pathlib
import re
import subprocess
import sys
import urllib.parse

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from browser import Browser  # noqa: E402

TEXT = "document.getElementById('{}').textContent"
HASH = TEXT.format("image-hash")
ERROR = "document.getElementById('caption').className === 'error' && " + TEXT.format("caption")


def url(page, query=""):
    return pathlib.Path(page).resolve().as_uri() + (("?" + query) if query else "")


def native_hash(cli, scene, width, height, cache, order):
    out = subprocess.run([cli, "render", scene, "--width", str(width), "--height", str(height), "--cache", cache,
                          "--order", order, "--hash", "-q"], capture_output=True, text=True, check=True).stdout
    return out.strip().splitlines()[-1]


def open_file(browser, name, data):
    """Chooses a file with the Open file button's input, as a user would (bytes kept)."""
    browser.evaluate(f"""(() => {{
        const bytes = new Uint8Array({json.dumps(list(data))});
        const files = new DataTransfer();
        files.items.add(new File([bytes], {json.dumps(name)}));
        const input = document.getElementById('file');
        input.files = files.files;
        input.dispatchEvent(new Event('change')); }})()""")


def run_to_end(browser, cache, order, timeout):
    browser.evaluate(f"""(() => {{
        document.getElementById('cache').value = '{cache}';
        document.getElementById('order').value = '{order}';
        document.getElementById('open').click();
        document.getElementById('end').click(); }})()""")
    return browser.wait_for(f"({HASH}) || ({ERROR}) && ('error: ' + ({ERROR}))", timeout) or "timed out"


class Checks:
    def __init__(self):
        self.failed = 0

    def expect(self, ok, what, detail=""):
        print(("ok    " if ok else "FAIL  ") + what + ("" if ok else f": {detail}"))
        self.failed += not ok


def first_view(browser, a, c):
    browser.open(url(a.page))
    shown = browser.wait_for(f"{TEXT.format('caption')}.includes('  step ') && {TEXT.format('stop-title')} !== ''",
                             a.timeout)
    c.expect(bool(shown), "the first view opens a tour stop", browser.evaluate(TEXT.format("caption")))
    c.expect(browser.evaluate("location.search") == "?tour=hanrahan86&stop=1", "it is the lecture's first stop",
             browser.evaluate("location.search"))
    caption = browser.evaluate(TEXT.format("stop-caption")) or ""
    c.expect(caption.startswith("In a ray tree"), "with the stop's caption", caption)
    box = browser.evaluate("JSON.stringify(document.getElementById('stop-caption').getBoundingClientRect())")
    r = json.loads(box)
    c.expect(r["bottom"] <= 720 and r["top"] >= 0 and r["width"] > 0, "the caption is on screen at 1280x720", box)
    count = int(browser.evaluate(TEXT.format("overlay-count")) or 0)
    c.expect(count > 0, "and its ray in focus with overlays drawn", f"{count} shapes")


def url_parameters(browser, a, c):
    expected = native_hash(a.cli, "cube:3", 12, 10, "blocker+", "bfs")
    for raw in ["blocker+", "blocker%2B"]:
        browser.open(url(a.page, f"scene=cube:3&width=12&height=10&order=bfs&run=end&cache={raw}"))
        got = browser.wait_for(f"({HASH}) || ({ERROR})", a.timeout)
        chosen = browser.evaluate("document.getElementById('cache').value")
        c.expect(chosen == "blocker+" and got == expected, f"cache={raw} renders blocker+ with the native hash",
                 f"chose {chosen!r}, hash {got!r}, native {expected}")


def errors_are_sentences(browser, a, c):
    browser.open(url(a.page, "scene=cube:3&width=8&height=8&cache=bogus"))
    error = browser.wait_for(ERROR, a.timeout) or ""
    c.expect("unknown cache 'bogus'" in error and "blocker+" in error and not re.fullmatch(r"\d+", error.strip()),
             "?cache=bogus says so in a sentence with the choices", error)
    browser.open(url(a.page, "scene=cube:3&width=4096&height=8"))
    error = browser.wait_for(ERROR, a.timeout) or ""
    c.expect("2048" in error and "4096" in error, "a width of 4096 is refused with the limit", error)
    c.expect(browser.evaluate(TEXT.format("stats")) == "", "and nothing is traced")


def open_files(browser, a, c):
    data = pathlib.Path(a.data)
    teapot = (data / "skipped" / "teapot_zero_area.nff").read_bytes()
    marked = [i + 2 for i, line in enumerate(teapot.decode().splitlines()) if line.startswith("# zero area")]
    browser.open(url(a.page, "scene=cube:3&width=16&height=16"))
    browser.wait_for(f"{TEXT.format('caption')}.includes('  step ')", a.timeout)
    open_file(browser, "teapot_zero_area.nff", teapot)
    notes = browser.wait_for(f"{TEXT.format('stop-notes')}.includes('zero area') && {TEXT.format('stop-notes')}",
                             a.timeout) or ""
    named = all(f"/teapot_zero_area.nff:{line}:1: polygon patch of zero area skipped" in notes for line in marked)
    c.expect(len(marked) == 8 and named, "Open file traces the teapot and names each skipped triangle", notes)
    left = browser.evaluate(TEXT.format("left-out")) or ""
    c.expect("polygons of zero area: 8 skipped" in left, "left out counts them", left)
    native_file = str(data / "skipped" / "teapot_zero_area.nff")
    caches = json.loads(subprocess.run([a.cli, "list", "caches", "--json"], capture_output=True, text=True,
                                       check=True).stdout)
    wrong = []
    for cache in [e["name"] for e in caches]:
        got = run_to_end(browser, cache, "bfs", a.timeout)
        expected = native_hash(a.cli, native_file, 16, 16, cache, "bfs")
        if got != expected:
            wrong.append(f"{cache}: web {got}, native {expected}")
    c.expect(not wrong, f"every cache ({len(caches)}) gives the native hash on it", "; ".join(wrong))
    bom = (data / "good" / "utf8_bom.nff").read_bytes()
    open_file(browser, "utf8_bom.nff", bom)
    browser.wait_for(f"{TEXT.format('caption')}.startsWith('utf8_bom')", a.timeout)
    got = run_to_end(browser, "blocker", "bfs", a.timeout)
    c.expect(got == native_hash(a.cli, str(data / "good" / "utf8_bom.nff"), 16, 16, "blocker", "bfs"),
             "a file with a UTF-8 byte-order mark opens, as natively", got)
    # A bad file: the old picture and statistics go, and Ray says why it does nothing
    open_file(browser, "bad.nff", b"v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\nresolution 8 8\ns 0 0 0 -1\n")
    error = browser.wait_for(ERROR, a.timeout) or ""
    c.expect(error.startswith("/bad.nff:8:9: "), "a bad file shows file:line:column", error)
    stats, digest = browser.evaluate(TEXT.format("stats")), browser.evaluate(HASH)
    c.expect(stats == "" and digest == "", "and clears the old picture's statistics and hash", f"{stats!r} {digest!r}")
    browser.evaluate("document.getElementById('step-ray').click()")
    said = browser.wait_for(f"({ERROR}) && ({ERROR}).startsWith('There is no picture') && ({ERROR})", a.timeout)
    c.expect(bool(said), "Ray then says there is no picture to trace", browser.evaluate(TEXT.format("caption")))


def compare_selects(browser, a, c):
    browser.open(url(a.page, "scene=cube:3&width=32&height=32&cache=blocker&order=bfs"))
    browser.wait_for(f"{TEXT.format('caption')}.includes('  step ')", a.timeout)
    browser.evaluate("""(() => { const s = document.getElementById('compare');
        s.value = 'none:scanline'; s.onchange(); })()""")
    browser.wait_for(f"{TEXT.format('caption')}.includes('right: ')", a.timeout)
    browser.evaluate("document.getElementById('end').click()")
    browser.wait_for(HASH, a.timeout)
    # A click in the right pane, a quarter of the way across and down it
    browser.evaluate("""(() => { const c = document.getElementById('canvas'), r = c.getBoundingClientRect();
        c.dispatchEvent(new MouseEvent('click', { clientX: r.left + r.width * 0.625, clientY: r.top + r.height / 4,
                                                  bubbles: true })); })()""")
    both = browser.wait_for("window.__viewer.frame() && window.__viewer.frame().selectedPixel >= 0 && "
                            "JSON.stringify([window.__viewer.frame().selectedPixel, "
                            "window.__viewer.frame().compare.selectedPixel])", a.timeout)
    pixels = json.loads(both) if both else None
    c.expect(bool(pixels) and pixels[0] == pixels[1] and pixels[0] >= 0,
             "compare: a click selects the same pixel in both panes", both)


def rect(browser, id):
    return json.loads(browser.evaluate(f"JSON.stringify(document.getElementById('{id}').getBoundingClientRect())"))


def layout(browser, a, c):
    """The stops with two pictures, and the one with the longest caption: everything on screen."""
    for tour, stop in [("hanrahan86", 3), ("hanrahan86", 8), ("hanrahan86", 12), ("debugging", 5)]:
        browser.open(url(a.page, f"tour={tour}&stop={stop}"))
        browser.wait_for(f"{TEXT.format('caption')}.includes('  step ') && {TEXT.format('stop-title')} !== ''",
                         a.timeout)
        canvas, caption, stop_caption = rect(browser, "canvas"), rect(browser, "caption"), rect(browser, "stop-caption")
        fits = lambda r: r["top"] >= 0 and r["left"] >= 0 and r["bottom"] <= 720 and r["right"] <= 1280  # noqa: E731
        c.expect(fits(canvas) and canvas["width"] > 200, f"{tour} stop {stop}: the picture(s) on screen at 1280x720",
                 canvas)
        c.expect(fits(caption) and fits(stop_caption), f"{tour} stop {stop}: both captions on screen",
                 f"caption {caption}, stop caption {stop_caption}")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--cli", required=True)
    p.add_argument("--page", required=True)
    p.add_argument("--data", required=True)
    p.add_argument("--chromium", default="chromium")
    p.add_argument("--timeout", type=float, default=120.0)
    a = p.parse_args()
    browser = Browser(a.chromium)
    c = Checks()
    try:
        browser.call("Emulation.setDeviceMetricsOverride", session=True, width=1280, height=720,
                     deviceScaleFactor=1, mobile=False)
        for check in (first_view, url_parameters, errors_are_sentences, open_files, compare_selects, layout):
            check(browser, a, c)
    finally:
        browser.close()
    print("all checks pass" if not c.failed else f"{c.failed} checks failed")
    return 1 if c.failed else 0


if __name__ == "__main__":
    sys.exit(main())
