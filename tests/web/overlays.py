#!/usr/bin/env python3
"""The web viewer draws the core's overlays, and each stop's claims hold, at every stop of the
tours given: the page, opened at
?tour=NAME&stop=K (as the docs' live figures open it) in headless Chromium, must show what
the stop's settings ask for, read from #overlay-roles (the roles of rc::focusShapes drawn),
#overlay-count, #caption and #key:

- overlays "cylinder": a cylinder of safety (Cylinder, CachedCylinder or CylinderLeft);
- overlays "cone" with blocker lists and a ray in focus that hit an object: its hull, its
  origin and its target (Hull, Origin, Target); with blocker+ and an eye ray that hit
  nothing: the empty cone (EmptyCone);
- run next-miss with miss-reason R: the ray in focus is a miss of reason R (the caption),
  and a left_cylinder miss shows the cylinder left (CylinderLeft);
- neither cylinder nor cone: no shape at all;
- frontier: the key counts the queue; misses: the key names the path marked;
- compare C:O: the caption holds the second render and the ratio of their tests;
- the stop's selection and run are met (no note says otherwise);
- every claim of the stop holds on what the page draws, checked by the core's claim
  evaluation (rc::checkClaim, through the bindings: window.__viewer.claims), and its caption
  names no path, pane or count the stop does not draw (rc::captionSlips);
- with --wrong TOUR:K, stop K's claims with their panes swapped (left for right) fail: a
  claim that cannot fail checks nothing.
Exits 1 on any stop that breaks a rule.

Usage: overlays.py --page build/web-edition/web/index.html --tour tours/hanrahan86.json
           [--tour tours/debugging.json] [--wrong hanrahan86:8]"""
import argparse
import json
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from browser import Browser  # noqa: E402

TEXT = "document.getElementById('{}').textContent"


def check(stop, roles, count, caption, key, notes):
    s = stop
    overlays = s.get("overlays", [])
    overlays = overlays if isinstance(overlays, list) else overlays.split(",")
    cache = s.get("cache", "blocker")
    problems = []
    focus = caption.splitlines()[1] if len(caption.splitlines()) > 1 else ""
    if "cylinder" in overlays and not roles & {"Cylinder", "CachedCylinder", "CylinderLeft"}:
        problems.append("no cylinder of safety drawn")
    if "cone" in overlays and cache.startswith("blocker"):
        # A ray to a light has a point as its target (TargetPoint), a ray to an object the object
        if " hit #" in focus and not ({"Hull", "Origin"} <= roles and roles & {"Target", "TargetPoint"}):
            problems.append("the ray in focus hit an object, but its hull, origin and target are not all drawn")
        if cache.startswith("blocker+") and " hit nothing" in focus and "  eye  " in focus and "EmptyCone" not in roles:
            problems.append("an eye ray that hit nothing with blocker+, but no empty cone drawn")
    if s.get("run") == "next-miss":
        reason = s.get("miss-reason")
        if reason and f"miss ({reason})" not in focus:
            problems.append(f"the ray in focus is not a {reason} miss: {focus!r}")
        if reason == "left_cylinder" and "cylinder" in overlays and "CylinderLeft" not in roles:
            problems.append("a left_cylinder miss without the cylinder it left")
    if "cylinder" not in overlays and "cone" not in overlays and count != 0:
        problems.append(f"{count} shapes drawn, none asked for")
    if count < len(roles):
        problems.append(f"#overlay-count {count} is fewer than the roles drawn {sorted(roles)}")
    if "frontier" in overlays and "queued (" not in key:
        problems.append("frontier asked for, but the key has no queue")
    if "misses" in overlays and "misses marked at path" not in key:
        problems.append("misses asked for, but the key names no path")
    if s.get("compare") and not ("\nright: " in caption and "x the left's" in caption):
        problems.append(f"compare {s['compare']} asked for, but the caption has no second render: {caption!r}")
    if "select:" in notes or "no such miss" in notes:
        problems.append("the stop's selection or run was not met: " + notes)
    return problems


def claims(browser, tour, k, given, timeout):
    """The stop's claims (or `given` in their place) checked in the page: {results, slips} or
    {error}."""
    browser.evaluate(f"window.__viewer.claims({json.dumps(given)})")
    answer = browser.wait_for("window.__claims && JSON.stringify(window.__claims)", timeout)
    return json.loads(answer) if answer else {"error": "the page gave no answer"}


def claim_problems(answer):
    if "error" in answer:
        return ["claims: " + answer["error"]]
    problems = [f"claim {r['text']!r} does not hold: {r['reading']}" for r in answer["results"] if not r["holds"]]
    problems += ["caption: " + slip for slip in answer["slips"]]
    if not answer["results"]:
        problems.append("the stop states no claim")
    return problems


def swapped(texts):
    """The claims with their panes swapped: left. for right. and back (a bare name is left's)."""
    out = []
    for t in texts:
        words = []
        for w in t.split(" "):
            w = w.replace("right.", "\0").replace("left.", "right.").replace("\0", "left.")
            words.append(w)
        out.append(" ".join(words))
    return out


def show_stop(browser, a, tour_path, stop, k, wrong):
    """Opens stop k; its problems, or None when it was not shown."""
    url = pathlib.Path(a.page).resolve().as_uri() + f"?tour={tour_path.stem}&stop={k}"
    browser.open(url)
    # The stop is shown once the caption has its step and the stop's own line
    ready = browser.wait_for(f"{TEXT.format('caption')}.includes('  step ') && "
                             f"{TEXT.format('stop-title')} !== '' && "
                             f"document.getElementById('caption').className !== 'error'", a.timeout)
    caption = browser.evaluate(TEXT.format("caption")) or ""
    if not ready:
        print(f"{tour_path.stem} stop {k}: not shown in {a.timeout} s: {caption!r}")
        return None
    roles = set(filter(None, (browser.evaluate(TEXT.format("overlay-roles")) or "").split(",")))
    count = int(browser.evaluate(TEXT.format("overlay-count")) or 0)
    key = browser.evaluate("document.getElementById('key').innerText") or ""
    notes = browser.evaluate(TEXT.format("stop-notes")) or ""
    problems = check(stop, roles, count, caption, key, notes)
    answer = claims(browser, tour_path.stem, k, None, a.timeout)
    problems += claim_problems(answer)
    held = sum(r["holds"] for r in answer.get("results", []))
    focus = caption.splitlines()[1] if len(caption.splitlines()) > 1 else "no ray"
    print(f"{tour_path.stem} stop {k} ({stop.get('page', '')}): {count} shapes {sorted(roles)}; "
          f"{held} claims hold; {focus}")
    for r in answer.get("results", []):
        print(f"  {r['reading']}")
    if wrong:
        bad = claims(browser, tour_path.stem, k, swapped(stop["claims"]), a.timeout)
        failing = [r for r in bad.get("results", []) if not r["holds"]]
        print(f"  panes swapped: {len(failing)} of {len(bad.get('results', []))} claims fail"
              + "".join(f"\n    {r['text']}: {r['reading']}" for r in failing))
        if "error" in bad or not failing:
            problems.append("its claims with the panes swapped do not fail: " + json.dumps(bad))
    return problems


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--page", required=True)
    p.add_argument("--tour", required=True, action="append")
    p.add_argument("--wrong", action="append", default=[], help="TOUR:K, a stop whose swapped claims must fail")
    p.add_argument("--chromium", default="chromium")
    p.add_argument("--timeout", type=float, default=120.0)
    a = p.parse_args()
    browser = Browser(a.chromium)
    failed = total = 0
    try:
        for tour in a.tour:
            tour_path = pathlib.Path(tour)
            stops = json.loads(tour_path.read_text(encoding="utf-8"))["stops"]
            for k, stop in enumerate(stops, 1):
                total += 1
                problems = show_stop(browser, a, tour_path, stop, k, f"{tour_path.stem}:{k}" in a.wrong)
                for problem in problems or []:
                    print(f"  FAIL: {problem}")
                failed += problems is None or bool(problems)
    finally:
        browser.close()
    print(f"{total - failed} of {total} stops draw what they ask for, and their claims hold")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
