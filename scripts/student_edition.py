#!/usr/bin/env python3
"""The student edition of RayCache, and the checks CI makes of it.

  student_edition.py export OUT [--open 01,03]   write the edition (default: every tutorial open)
  student_edition.py stub FILE NN                 print FILE with tutorial NN's solution regions stubbed
  student_edition.py leaks EDITION [--site HTML]   fail when a line of a solution region occurs in EDITION
                                                  (and in the docs site HTML, the instructor's, less the
                                                  pages the edition replaces)
  student_edition.py inject EDITION               put the instructor's solutions back into EDITION's holes
  student_edition.py splice HOLE ANSWER OUT       write OUT: the hole file HOLE with each solution region
                                                  replaced by ANSWER's block for it (a recorded wrong or
                                                  alternative answer of a hole tutorial)

Solution regions (nbgrader's convention, in C++ comments):
    // BEGIN SOLUTION NN
    ...the reference code...
    // END SOLUTION
    // BEGIN STUB
    // ...the stub, each line commented out once...
    // END STUB
An open tutorial's region becomes its stub; a closed one keeps its solution (as a course
releases it after the deadline).

A recorded answer of a hole tutorial (tutorials/instructor/wrong/NN-*.cpp and
alternative/NN-*.cpp for the holes) holds only its answer to each region, in order:
    // BEGIN ANSWER
    ...the code in place of the region...
    // END ANSWER
or, for a region the answer leaves as the reference solution has it, the one line
    // KEEP SOLUTION
and, only when the answer needs an #include or a helper outside the regions, one
`// BEGIN PREAMBLE` ... `// END PREAMBLE` block before them, put after HOLE's last #include.
Outside the blocks, comments and blank lines only. `splice` writes the program the
instructor's build compiles: HOLE with each region (solution and stub) replaced by its answer. The edition leaves out tutorials/instructor/ (the reference answers, wrong answers and
the checks' oracles: the checks read their answers as data, tutorials/NN-*/oracle_data.txt),
tests/instructor/ (tests that compute a tutorial's answer apart from the library) and replaces
each file under scripts/student_edition/replace/ (pages written anew for it). In every other page
of docs/pages, a \\snippet that quotes lines of an open tutorial's solution region becomes a
sentence saying the instructor's edition quotes it there.
"""
import html
import os
import re
import shutil
import subprocess
import sys

BEGIN = re.compile(r'^\s*// BEGIN SOLUTION (\d\d)\s*$')
END = re.compile(r'^\s*// END SOLUTION\s*$')
STUB_BEGIN = re.compile(r'^\s*// BEGIN STUB\s*$')
STUB_END = re.compile(r'^\s*// END STUB\s*$')
BLOCK = re.compile(r'^\s*// (BEGIN|END) (ANSWER|PREAMBLE)\s*$')
KEEP = re.compile(r'^\s*// KEEP SOLUTION\s*$')
INCLUDE = re.compile(r'^\s*#\s*include\b')
LEFT_OUT = ('tutorials/instructor/', 'tests/instructor/', 'scripts/student_edition/')
REPLACE = 'scripts/student_edition/replace/'
ALL = ['01', '02', '03', '04', '05', '06', '07']


def regions(text):
    """(tutorial, solution lines, stub lines, start, end) of each region: lines [start, end)."""
    lines = text.split('\n')
    out, i = [], 0
    while i < len(lines):
        m = BEGIN.match(lines[i])
        if not m:
            i += 1
            continue
        start, sol = i, []
        i += 1
        while not END.match(lines[i]):
            sol.append(lines[i])
            i += 1
        i += 1
        if not STUB_BEGIN.match(lines[i]):
            raise SystemExit(f'solution region of tutorial {m.group(1)} without a stub after it')
        i += 1
        stub = []
        while not STUB_END.match(lines[i]):
            stub.append(re.sub(r'^(\s*)// ?', r'\1', lines[i], count=1))
            i += 1
        i += 1
        out.append((m.group(1), sol, stub, start, i))
    return lines, out


def stubbed(text, open_tutorials):
    lines, found = regions(text)
    result, at = [], 0
    for nn, sol, stub, start, end in found:
        result += lines[at:start]
        result += stub if nn in open_tutorials else sol
        at = end
    return '\n'.join(result + lines[at:])


def answer_blocks(text, name):
    """(preamble lines, [answer lines of each block]) of a recorded answer; SystemExit with
    name:line on a malformed file."""
    preamble, answers, block, kind, opened = [], [], None, None, 0
    for k, line in enumerate(text.split('\n'), 1):
        m = BLOCK.match(line)
        if KEEP.match(line) and block is None:
            answers.append(None)  # this region's reference solution, as it is
        elif m and m.group(1) == 'BEGIN':
            if block is not None:
                raise SystemExit(f'{name}:{k}: BEGIN {m.group(2)} inside the {kind} block opened on line {opened}')
            if m.group(2) == 'PREAMBLE' and (answers or preamble):
                raise SystemExit(f'{name}:{k}: one PREAMBLE block, before the first ANSWER block')
            block, kind, opened = [], m.group(2), k
        elif m:
            if block is None or m.group(2) != kind:
                raise SystemExit(f'{name}:{k}: END {m.group(2)} without its BEGIN')
            if kind == 'PREAMBLE':
                preamble = block or ['']
            else:
                answers.append(block)
            block = None
        elif block is not None:
            block.append(line)
        elif line.strip() and not line.strip().startswith('//'):
            raise SystemExit(f'{name}:{k}: code outside the ANSWER blocks (only comments may be outside)')
    if block is not None:
        raise SystemExit(f'{name}:{opened}: BEGIN {kind} without its END')
    return preamble, answers


def spliced(hole, hole_name, answer, answer_name):
    """The hole file as the instructor's build compiles it, with the answer's block in place of
    each solution region (its stub dropped, the markers removed)."""
    lines, found = regions(hole)
    preamble, answers = answer_blocks(answer, answer_name)
    if len(answers) != len(found):
        at = ', '.join(f'{hole_name}:{start + 1}' for _, _, _, start, _ in found)
        raise SystemExit(f'{answer_name}:1: {len(answers)} ANSWER blocks (or KEEP SOLUTION lines), but '
                         f'{hole_name} has {len(found)} solution regions ({at}): one per region, in order')
    result, at = [], 0
    for (_, sol, _, start, end), block in zip(found, answers):
        result += lines[at:start] + (sol if block is None else block)
        at = end
    result += lines[at:]
    if preamble:
        includes = [k for k, line in enumerate(result) if INCLUDE.match(line)]
        if not includes:
            raise SystemExit(f'{hole_name}:1: no #include to put the PREAMBLE of {answer_name} after')
        result[includes[-1] + 1:includes[-1] + 1] = preamble
    return '\n'.join(result)


def tracked(root):
    files = subprocess.run(['git', '-C', root, 'ls-files', '-z'], check=True, capture_output=True).stdout
    return [f for f in files.decode().split('\0') if f]


SNIPPET = re.compile(r'^\s*\\snippet\s+(\S+)\s+(\S+)\s*$')
TAG = re.compile(r'^\s*//\s*\[([\w-]+)\]\s*$')
EXAMPLE_PATH = ('src/', 'tutorials/', 'tests/toy/')  # docs/Doxyfile.in's, where \snippet finds its files


def region_snippets(root, open_tutorials):
    """{(file as a \\snippet names it, tag): tutorial} of each snippet whose lines overlap a
    solution region of an open tutorial: what a page may not quote in the edition."""
    out = {}
    for f, text in hole_files(root).items():
        lines, found = regions(text)
        spans = [(start, end, nn) for nn, _, _, start, end in found if nn in open_tutorials]
        opened = {}
        for k, line in enumerate(lines):
            m = TAG.match(line)
            if not m:
                continue
            tag = m.group(1)
            if tag not in opened:
                opened[tag] = k
                continue
            first = opened.pop(tag)
            for start, end, nn in spans:
                if first < end and start <= k:
                    name = next((f[len(d):] for d in EXAMPLE_PATH if f.startswith(d)), f)
                    out[(name, tag)] = nn
    return out


def unquoted(text, hidden):
    """Page text with each \\snippet of `hidden` (region_snippets) replaced by a sentence."""
    def line(l):
        m = SNIPPET.match(l)
        if not m or (m.group(1), m.group(2)) not in hidden:
            return l
        return (f'(This code is part of tutorial {hidden[(m.group(1), m.group(2))]}\'s answer: the student '
                'edition leaves it out, the instructor\'s edition quotes it here.)')
    return '\n'.join(line(l) for l in text.split('\n'))


def export(root, out, open_tutorials):
    if os.path.exists(out):
        raise SystemExit(f'{out} exists: the edition is written to a new directory')
    replaced = {f[len(REPLACE):] for f in tracked(root) if f.startswith(REPLACE)}
    hidden = region_snippets(root, open_tutorials)
    for f in tracked(root):
        if f.startswith(LEFT_OUT) or not os.path.isfile(os.path.join(root, f)):
            continue
        src = os.path.join(root, REPLACE + f) if f in replaced else os.path.join(root, f)
        dst = os.path.join(out, f)
        os.makedirs(os.path.dirname(dst), exist_ok=True)
        try:
            text = open(src, encoding='utf-8').read()
        except UnicodeDecodeError:
            shutil.copy2(src, dst)
            continue
        if BEGIN.search(text) or '// BEGIN SOLUTION' in text:
            text = stubbed(text, open_tutorials)
        if f.startswith('docs/pages/') and f.endswith('.md'):
            text = unquoted(text, hidden)
        with open(dst, 'w', encoding='utf-8') as o:
            o.write(text)
        shutil.copymode(src, dst)
    with open(os.path.join(out, 'tutorials/student_edition.cmake'), 'w') as o:
        o.write('# Written by scripts/student_edition.sh: this is the student edition. Each open\n'
                '# tutorial\'s exercise.cpp is compiled in place of the function it is a hole in.\n'
                'set(RAYCACHE_STUDENT ON CACHE BOOL "Student build")\n'
                'set(RAYCACHE_STUDENT_OPEN "%s" CACHE STRING "The open tutorials")\n'
                'set(RAYCACHE_DOCS OFF CACHE BOOL "The docs site is the instructor\'s")\n' % ';'.join(open_tutorials))


def hole_files(root):
    """The files in root that hold solution regions: {path: text}."""
    out = {}
    for f in tracked(root):
        if f.startswith(LEFT_OUT) or not f.endswith(('.cpp', '.h')):
            continue
        text = open(os.path.join(root, f), encoding='utf-8').read()
        if '// BEGIN SOLUTION' in text:
            out[f] = text
    return out


def holes(root):
    """(tutorial, file under src/) of each hole, as src/CMakeLists.txt lists them
    (RAYCACHE_HOLES): the file a student build replaces with the tutorial's exercise.cpp."""
    text = open(os.path.join(root, 'src/CMakeLists.txt'), encoding='utf-8').read()
    return re.findall(r'"(\d\d)\|([^|"]+)\|[^"]*"', text)


def norm(line):
    return ' '.join(line.split())


def leaks(root, edition, open_tutorials, site=None):
    """Every whitespace-normalised line of 25 characters or more of an open tutorial's
    solution region, looked for in every text file of the edition. A line that the
    instructor's project also holds outside the regions and outside tutorials/ (library
    code both editions ship, such as a loop header) is not the edition's leak: it is
    counted apart."""
    needles = {}
    for f, text in hole_files(root).items():
        for nn, sol, _, _, _ in regions(text)[1]:
            if nn in open_tutorials:
                for line in sol:
                    n = norm(line)
                    if len(n) >= 25 and not n.startswith('// ['):
                        needles[n] = f'{f} (tutorial {nn})'
    shared = set()
    for f in tracked(root):
        if f.startswith('tutorials/') or not f.endswith(('.cpp', '.h', '.md', '.js', '.py', '.txt', '.cmake')):
            continue
        text = open(os.path.join(root, f), encoding='utf-8').read()
        lines, found = regions(text) if '// BEGIN SOLUTION' in text else (text.split('\n'), [])
        inside = set()
        for _, _, _, start, end in found:
            inside.update(range(start, end))
        for k, line in enumerate(lines):
            if k not in inside and norm(line) in needles:
                shared.add(norm(line))
    for n in shared:
        del needles[n]
    found = 0
    if site:
        found += site_leaks(root, site, needles)
    for dirpath, _, names in os.walk(edition):
        rel = os.path.relpath(dirpath, edition)
        if rel.split(os.sep)[0] in ('build', '.git'):
            continue
        for name in names:
            found += file_leaks(os.path.join(dirpath, name), needles, norm)
    print(f'leak check: {len(needles)} lines of solution regions (25 characters or more; {len(shared)} more '
          f'shared with library code outside the regions) looked for in {edition}: {found} found')
    return found == 0


def file_leaks(path, needles, normalise):
    """How many lines of the text file `path`, each normalised, are needles (each printed as
    path:line); 0 for a file that is not text."""
    try:
        lines = open(path, encoding='utf-8').read().split('\n')
    except (UnicodeDecodeError, OSError):
        return 0
    found = 0
    for k, line in enumerate(lines):
        n = normalise(line)
        if n in needles:
            print(f'{path}:{k + 1}: a line of {needles[n]}: {n}')
            found += 1
    return found


def dropped_pages(root):
    """The docs site's pages the edition does not have as the instructor's site shows them:
    each page under scripts/student_edition/replace/docs/pages/ (replaced) and each page that
    quotes a solution region (its snippets unquoted); its HTML file is named after the page's
    id (the first `{#id}` of the instructor's page)."""
    out = set()
    hidden = region_snippets(root, ALL)
    for f in tracked(root):
        page = None
        if f.startswith(REPLACE + 'docs/pages/') and f.endswith('.md'):
            page = open(os.path.join(root, f[len(REPLACE):]), encoding='utf-8').read()
        elif f.startswith('docs/pages/') and f.endswith('.md'):
            text = open(os.path.join(root, f), encoding='utf-8').read()
            page = text if unquoted(text, hidden) != text else None
        m = re.search(r'\{#(\w+)\}', page) if page else None
        if m:
            out.add(m.group(1) + '.html')
    return out


def site_leaks(root, site, needles):
    """The needles looked for in the built docs site `site` (HTML, its tags stripped line by
    line: Doxygen writes a code line per line), except the pages the edition replaces. The
    site is the instructor's (the edition builds no docs), so this is what the edition's site
    would show of it."""
    dropped = dropped_pages(root)
    found = pages = 0
    for dirpath, _, names in os.walk(site):
        for name in sorted(names):
            if not name.endswith(('.html', '.js')) or name in dropped:
                continue
            pages += 1
            found += file_leaks(os.path.join(dirpath, name), needles,
                                lambda line: norm(html.unescape(re.sub(r'<[^>]*>', '', line))))
    print(f'leak check of the docs site {site}: {pages} pages and scripts ({len(dropped)} replaced in the edition '
          f'left out: {", ".join(sorted(dropped))}): {found} lines of solution regions found')
    return found


def inject(root, edition):
    """Put the instructor's solutions into the edition's holes: each open hole's exercise.cpp
    becomes the solution, as a student who solved it would have written it."""
    for nn, f in holes(root):
        text = open(os.path.join(root, 'src', f), encoding='utf-8').read()
        tut = [d for d in os.listdir(os.path.join(edition, 'tutorials')) if d.startswith(nn + '-')][0]
        with open(os.path.join(edition, 'tutorials', tut, 'exercise.cpp'), 'w', encoding='utf-8') as o:
            o.write(stubbed(text, []))
    # The tutorials that are not holes: the instructor's solution file is the exercise
    sol = os.path.join(root, 'tutorials/instructor/solutions')
    for name in sorted(os.listdir(sol)):
        shutil.copy(os.path.join(sol, name), os.path.join(edition, 'tutorials', name[:-4], 'exercise.cpp'))


def main(argv):
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    opened = ALL
    if '--open' in argv:
        k = argv.index('--open')
        opened = [s.strip() for s in argv[k + 1].split(',') if s.strip()]
        del argv[k:k + 2]
    if len(argv) >= 2 and argv[0] == 'export':
        export(root, argv[1], opened)
    elif len(argv) == 3 and argv[0] == 'stub':
        sys.stdout.write(stubbed(open(argv[1], encoding='utf-8').read(), [argv[2]]))
    elif len(argv) in (2, 4) and argv[0] == 'leaks':
        site = argv[3] if len(argv) == 4 and argv[2] == '--site' else None
        if len(argv) == 4 and site is None:
            print(__doc__)
            return 2
        return 0 if leaks(root, argv[1], opened, site) else 1
    elif len(argv) == 2 and argv[0] == 'inject':
        inject(root, argv[1])
    elif len(argv) == 4 and argv[0] == 'splice':
        hole = open(argv[1], encoding='utf-8').read()
        answer = open(argv[2], encoding='utf-8').read()
        text = spliced(hole, argv[1], answer, argv[2])
        with open(argv[3], 'w', encoding='utf-8') as o:
            o.write(text)
    else:
        print(__doc__)
        return 2
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
