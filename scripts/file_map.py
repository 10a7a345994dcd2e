#!/usr/bin/env python3
"""The file map: one line per file under src/, each with its header's one-line \\brief (its first sentence) (a
.cpp without a \\file of its own is the implementation of the header of its name).
usage: file_map.py SOURCE_DIR [--markdown]. Exits 1 if a header has no \\brief."""
import pathlib
import re
import sys


def brief(path: pathlib.Path) -> str:
    lines = path.read_text(encoding="utf-8").splitlines()
    for i, line in enumerate(lines):
        m = re.match(r"\s*///?\s*\\brief\s+(.*)", line)
        if not m:
            continue
        text = m.group(1).strip()
        # the brief runs on until a blank comment line or code
        for more in lines[i + 1:]:
            c = re.match(r"\s*///?\s?(.*)", more)
            if not c or not c.group(1).strip() or c.group(1).lstrip().startswith("\\"):
                break
            text += " " + c.group(1).strip()
        # the map keeps its first sentence
        return re.split(r"(?<=[.])\s", text, maxsplit=1)[0].rstrip(".")
    return ""


def main() -> int:
    src = pathlib.Path(sys.argv[1]) / "src"
    markdown = "--markdown" in sys.argv
    missing = []
    for path in sorted(src.rglob("*")):
        if path.suffix not in (".h", ".cpp"):
            continue
        name = path.relative_to(src).as_posix()
        text = brief(path)
        if not text and path.suffix == ".cpp" and path.with_suffix(".h").exists():
            text = "implements " + path.with_suffix(".h").name
        if not text and path.suffix == ".h":
            missing.append(name)
        print(f"- `{name}`: {text}" if markdown else f"{name}: {text}")
    for name in missing:
        print(f"{name}: no \\brief", file=sys.stderr)
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
