#!/usr/bin/env python3
"""Finds figures about RayCache runs typed by hand into the docs' pages.

Every figure a page gives about a run must be written at docs build from a run: as
\\run{EXPR} (a value computed from a render's statistics, docs/tools/run_figures.py) or
inside a fragment the build generates and \\includedoc's. The paper's own numbers are
exempt when they are quoted ("...", or a > quotation) or marked \\paper{...}.

A *figure* here is a number written the way a measurement is: with a decimal point, a
thousands separator or a percent sign, with a magnitude (million, thousand, G) or a unit
of time or memory, or followed by what a render counts (tests, rays, misses, searches,
lists, ...). Settings (512 by 512, depth 5, cube:4, 8 scanlines) are not figures.

usage: typed_figures.py PAGE... (exit 1 and one `file:line: figure` per figure found)
       typed_figures.py --count PAGE...   (also print how many \\run figures there are)
"""
import re
import sys

COUNTED = (r"(?:tests?|rays?|misses|miss|searches|search|lists?|cylinders?|cones?|regions?|deferrals?|"
           r"beams?|nodes|hits?|instructions|spheres? each|times? as many)")
UNIT = r"(?:%|x\b|×|million|thousand|G\b|ns\b|ms\b|s\b|MB\b|KB\b|times\b)"
FIGURE = re.compile(
    r"(?<![\w.@:#/-])(?P<num>\d{1,3}(?:,\d{3})+(?:\.\d+)?|\d*\.\d+|\d+)"
    r"(?P<after>(?:-\d+(?:\.\d+)?)?\s*" + UNIT + r"|\s+" + COUNTED + r"\b)?")


def blank(m):
    return "\n" * m.group(0).count("\n")


def strip(text):
    """The page's prose: code, formulas, quotations, marked and generated spans removed
    (each replaced by its line breaks, so that line numbers stay right)."""
    text = re.sub(r"\\(verbatim|code)\b.*?\\end\1", blank, text, flags=re.S)
    text = re.sub(r"\\f\[.*?\\f\]", blank, text, flags=re.S)
    text = re.sub(r"\\f\$.*?\\f\$", blank, text, flags=re.S)
    text = re.sub(r"```.*?```", blank, text, flags=re.S)
    text = re.sub(r"`[^`]*`", blank, text)
    # generated and marked spans (one level of nested braces)
    text = re.sub(r"\\(run|runcommand|paper|setting)\{(?:[^{}]|\{[^{}]*\})*\}", blank, text)
    text = re.sub(r"<[^>]*>", blank, text)
    text = re.sub(r"\{#[\w-]+\}", blank, text)
    text = re.sub(r"\\(snippet|includedoc|verbinclude|ref|page|subpage|anchor)\s+\S+(\s+\S+)?", blank, text)
    text = re.sub(r"\brc::[\w:()]+", blank, text)
    text = re.sub(r"“[^”]*”", blank, text)
    text = re.sub(r'"[^"]*"', blank, text)
    return text


def figures(path):
    lines = open(path, encoding="utf-8").read().split("\n")
    # indented code blocks and > quotations of the paper
    kept, in_code, prev_blank = [], False, True
    for line in lines:
        if line.startswith("    ") and (prev_blank or in_code) and not line.lstrip().startswith(("-", "*")):
            in_code = True
            kept.append("")
        elif line.startswith(">"):
            kept.append("")
        else:
            in_code = in_code and not line.strip() == "" and line.startswith("    ")
            kept.append(line)
        prev_blank = line.strip() == ""
    text = strip("\n".join(kept))
    found = []
    for number, line in enumerate(text.split("\n"), 1):
        for m in FIGURE.finditer(line):
            num, after = m.group("num"), m.group("after") or ""
            if re.match(r"\d{4}$", num) and 1900 <= int(num) <= 2099:
                continue  # a year
            if re.search(r"(section|chapter|Figure|Table|stop|tutorial|item)\s+$", line[:m.start()]):
                continue  # a citation
            measured = ("," in num or "." in num or after.strip() != "")
            if measured:
                found.append((number, (num + after).strip()))
    return found


def main(argv):
    count = argv[:1] == ["--count"]
    pages = argv[1:] if count else argv
    total, runs = 0, 0
    for page in pages:
        for line, fig in figures(page):
            print(f"{page}:{line}: {fig}: a figure typed by hand (generate it with \\run{{...}}, or mark the "
                  f"paper's with \\paper{{...}})")
            total += 1
        runs += len(re.findall(r"\\run\{", open(page, encoding="utf-8").read()))
    if count:
        print(f"{runs} figures generated at docs build (\\run) in {len(pages)} pages; {total} typed by hand")
    return 1 if total else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
