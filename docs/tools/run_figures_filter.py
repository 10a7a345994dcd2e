#!/usr/bin/env python3
"""Doxygen's input filter for the pages: replaces \\run{EXPR|FORMAT} by the figure the
docs build measured and \\runcommand{NAME} by the command that measured it (see
run_figures.py). An expression that cannot be computed is left as \\runerror{...}, an
unknown command, so that Doxygen (warnings are errors) fails the build, and is reported
on stderr with its file and line.

usage: run_figures_filter.py RUNS_JSON PAGE   (the page, filtered, on stdout)
"""
import json
import re
import sys

runs_json, page = sys.argv[1:3]
text = open(page, encoding="utf-8").read()
if "\\run" not in text:
    sys.stdout.write(text)
    sys.exit(0)
runs = json.load(open(runs_json))


class Stats:
    def __init__(self, d):
        self.d = d

    def __getattr__(self, key):
        v = self.d[key]
        return Stats(v) if isinstance(v, dict) else v


names = {k: Stats(v["stats"]) for k, v in runs.items()}


def fmt(value, spec):
    if spec == "M":
        return f"{value / 1e6:.1f} million"
    if not spec:
        spec = "," if isinstance(value, int) else ".2f"
    return format(value, spec)


def where(m):
    return f"{page}:{text.count(chr(10), 0, m.start()) + 1}"


def run(m):
    expr, _, spec = m.group(1).partition("|")
    try:
        return fmt(eval(expr, {"__builtins__": {"min": min, "max": max, "abs": abs}}, names), spec.strip())
    except Exception as e:  # noqa: BLE001 (any failure must fail the docs build)
        print(f"{where(m)}: \\run{{{m.group(1)}}}: {e!r}", file=sys.stderr)
        return f"\\runerror{{{m.group(1)}}}"


def runcommand(m):
    name = m.group(1).strip()
    if name not in runs:
        print(f"{where(m)}: \\runcommand{{{name}}}: no such run", file=sys.stderr)
        return f"\\runerror{{{name}}}"
    return "`" + runs[name]["command"] + "`"


text = re.sub(r"\\runcommand\{([^{}]*)\}", runcommand, text)
text = re.sub(r"\\run\{([^{}]*)\}", run, text)
sys.stdout.write(text)
