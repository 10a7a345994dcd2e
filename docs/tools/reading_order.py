#!/usr/bin/env python3
"""Writes the start-here page's reading order (docs/tools/reading_order.txt) as an HTML table
for \\includedoc, with the length of each page counted from its source.

usage: reading_order.py SOURCE_ROOT READING_ORDER_TXT OUT_MD
"""
import os
import sys

root, order_file, out_md = sys.argv[1:4]


def n(x):
    return f"{x:,}"


def table(head, rows, note):
    out = ['<div><table class="markdownTable">',
           "<tr class=\"markdownTableHead\">" + "".join(f"<th>{h}</th>" for h in head) + "</tr>"]
    for r in rows:
        cells = [f"<td>{r[0]}</td>", f"<td>{r[1]}</td>"] + [f'<td align="right">{c}</td>' for c in r[2:]]
        out.append("<tr class=\"markdownTableBody\">" + "".join(cells) + "</tr>")
    out.append("</table></div>")
    out.append(f"<div>{note}</div>")
    return "\n".join(out) + "\n"


WORDS_PER_MINUTE = 120
rows = []
total = 0
for line in open(order_file):
    if line.startswith("#") or not line.strip():
        continue
    page, source, objective = line.rstrip("\n").split("|")
    words = 0
    for text in open(os.path.join(root, source)):
        # Prose only: commands (\snippet, \image, ...) and table rows are not read word by word
        if text.lstrip().startswith(("\\", "|", "<")):
            continue
        words += len(text.split())
    minutes = max(1, round(words / WORDS_PER_MINUTE))
    total += minutes
    rows.append([f"\\ref {page} \"The main page\"" if page == "mainpage" else f"\\ref {page}", objective, n(words), str(minutes)])
open(out_md, "w").write(
      table(["page", "after it you can", "words of prose", "minutes"], rows,
            f"Minutes: the page's words of prose (counted during this docs build, without code, tables and "
            f"commands) at {WORDS_PER_MINUTE} words a minute, rounded; {total} minutes in all. Running a page's "
            "commands takes longer, and a tutorial longer still: its exercise is not counted here."))
