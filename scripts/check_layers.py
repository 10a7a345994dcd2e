#!/usr/bin/env python3
"""Layers run one way: geometry -> scene -> search -> trace -> order -> analysis -> render -> view
-> study -> cli. A file of src/ may include its own layer and the layers before it, never one after
it; src/ never includes Qt or ui/. Prints every include that runs upward and exits 1 if
there is one. Run by ctest ("layers run one way"); usage: check_layers.py SOURCE_DIR"""
import pathlib
import re
import sys

ORDER = ["geometry", "scene", "search", "trace", "order", "analysis", "render", "view", "study", "cli"]
RANK = {layer: i for i, layer in enumerate(ORDER)}
# analysis/ holds the paper's measures (the beam tree), below render/; the studies that
# render images (stability, stiff scenes, precise intersection, image error) are study/,
# above it. No exceptions.
KNOWN: dict = {}


def main() -> int:
    src = pathlib.Path(sys.argv[1]) / "src"
    wrong = []
    files = 0
    for path in sorted(src.rglob("*")):
        if path.suffix not in (".h", ".cpp"):
            continue
        files += 1
        layer = path.relative_to(src).parts[0]
        name = path.relative_to(src).as_posix()
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            m = re.match(r'\s*#\s*include\s*[<"]([^">]+)[">]', line)
            if not m:
                continue
            included = m.group(1)
            top = included.split("/")[0]
            if included.startswith("Q") or top in ("ui", "QtCore", "QtGui", "QtWidgets"):
                wrong.append(f"{name}:{number}: the Qt-free core includes {included}")
            elif top in RANK and layer in RANK and RANK[top] > RANK[layer] and KNOWN.get(name) != included:
                wrong.append(f"{name}:{number}: {layer}/ includes {included}, a layer above it")
    for w in wrong:
        print(w)
    if files == 0:
        print(f"no sources under {src}")
        return 1
    print(f"{files} files, {len(wrong)} upward includes")
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
