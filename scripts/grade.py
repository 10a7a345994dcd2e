#!/usr/bin/env python3
"""Grades the tutorials: runs each tutorial's check and writes the JSON that Gradescope's
autograder reads (results.json: `tests[]` with name, score, max_score, output).

  grade.py [--build BUILD] [--program exercise] [--tutorials 01,03] [-o results.json]

Each test case of a check is one test worth one point: full marks when it passes, none
when it fails, and its output is the failing checks' messages (Catch2's JUnit report, at
full precision). A check that does not run (not built, crashed) scores nothing. In the
instructor's build `--program solution`, `stub` or `rejected_1` grades those programs
instead of the student's exercise; `grade.py --selftest` does so and asserts the scores
(the stubs all zero, the solutions full marks, a wrong answer partial).

The test cases and their points are those of the check's source in this tree
(tutorials/NN-*/check.cpp, the grader's copy), not whatever the report lists: a report that
names other cases, or more, earns nothing for them. The student's code still runs inside the
check's process, so code that takes the process over (writes the report itself, exits early)
can forge a pass; look at submissions that reach for files, processes or exit().
"""
import glob
import json
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET


SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'tutorials')


def check_cases(nn):
    """The names of the test cases tutorial `nn`'s check defines, from its source."""
    for path in glob.glob(os.path.join(SOURCE, f'{nn}-*', 'check.cpp')):
        with open(path) as f:
            return [re.sub(r'\\(.)', r'\1', m) for m in re.findall(r'TEST_CASE\(\s*"((?:[^"\\]|\\.)*)"', f.read())]
    return []


def grade_one(build, nn, program):
    exe = os.path.abspath(os.path.join(build, 'tutorials', f'tutorial_{nn}_{program}'))
    if not os.path.exists(exe):
        return [{'name': f'tutorial {nn}', 'score': 0, 'max_score': 1,
                 'output': f'{exe} is not built'}]
    with tempfile.TemporaryDirectory() as tmp:
        report = os.path.join(tmp, 'junit.xml')
        run = subprocess.run([exe, '-r', 'junit', '-o', report], cwd=tmp, capture_output=True, text=True,
                             env=dict(os.environ, TUTORIAL_PICTURE_DIR=tmp), timeout=600)
        try:
            cases = ET.parse(report).getroot().iter('testcase')
        except (ET.ParseError, FileNotFoundError):
            return [{'name': f'tutorial {nn}', 'score': 0, 'max_score': 1,
                     'output': f'the check did not run to its end (exit {run.returncode}):\n'
                               + (run.stdout + run.stderr)[-4000:]}]
        reported = {}
        for case in cases:
            failures = list(case.iter('failure')) + list(case.iter('error'))
            output = '\n\n'.join((f.get('message', '') + '\n' + (f.text or '')).strip() for f in failures)
            # A name reported twice counts as failed if either says so
            if reported.get(case.get('name'), (1, ''))[0]:
                reported[case.get('name')] = (0 if failures else 1, output or 'passed')
        # One point for each of the check's own test cases, by its source: a case the report
        # does not name earns nothing, a name the check does not define is not counted
        tests = []
        for name in check_cases(nn) or list(reported):
            score, output = reported.get(name, (0, "not in the check's report: it did not run"))
            tests.append({'name': f'tutorial {nn}: {name}', 'score': score, 'max_score': 1, 'output': output})
        if 'still the stub as shipped' in run.stdout:  # the check's main says so (rc::notYet)
            for t in tests:
                t['score'] = 0
                t['output'] = 'the function is still the stub as shipped' + (
                    '' if t['output'] == 'passed' else '\n\n' + t['output'])
        if run.returncode != 0 and not any(t['score'] == 0 for t in tests):
            tests.append({'name': f'tutorial {nn}: the check ran to its end', 'score': 0, 'max_score': 1,
                          'output': f'exit {run.returncode}'})
        return tests


def grade(build, program, tutorials):
    tests = []
    for nn in tutorials:
        tests += grade_one(build, nn, program)
    return {'score': sum(t['score'] for t in tests), 'tests': tests}


def all_tutorials(build):
    names = os.listdir(os.path.join(build, 'tutorials'))
    return sorted({n[9:11] for n in names if n.startswith('tutorial_') and n[9:11].isdigit()})


def selftest(build):
    tutorials = all_tutorials(build)
    ok = True
    for program, want in (('stub', 'zero'), ('solution', 'full')):
        for nn in tutorials:
            r = grade(build, program, [nn])
            total = sum(t['max_score'] for t in r['tests'])
            good = r['score'] == 0 if want == 'zero' else r['score'] == total
            print(f'tutorial {nn} {program}: {r["score"]} of {total} ({"as expected" if good else "expected " + want})')
            ok &= good and total >= 1
    # A wrong answer that fails some test cases and passes others: partial marks, with the
    # failing case's message in its output
    r = grade(build, 'rejected_1', ['06'])
    total = sum(t['max_score'] for t in r['tests'])
    failing = [t for t in r['tests'] if t['score'] == 0]
    good = 0 < r['score'] < total and all(t['output'] for t in failing)
    print(f'tutorial 06 rejected_1: {r["score"]} of {total} ({"partial, as expected" if good else "expected partial"})')
    return ok and good


def main(argv):
    build, program, tutorials, out = 'build', 'exercise', None, 'results.json'
    args = list(argv)
    while args:
        a = args.pop(0)
        if a == '--build':
            build = args.pop(0)
        elif a == '--program':
            program = args.pop(0)
        elif a == '--tutorials':
            tutorials = [t.strip() for t in args.pop(0).split(',')]
        elif a == '-o':
            out = args.pop(0)
        elif a == '--selftest':
            return 0 if selftest(build) else 1
        else:
            print(__doc__)
            return 2
    result = grade(build, program, tutorials or all_tutorials(build))
    with open(out, 'w') as f:
        json.dump(result, f, indent=2)
    print(f'{out}: {result["score"]} of {sum(t["max_score"] for t in result["tests"])} points')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
