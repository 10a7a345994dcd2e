#!/usr/bin/env bash
# scripts/student_edition.sh OUT [--open 01,03,...]
# Writes the student edition of RayCache to OUT: a copy of the project (git ls-files) with
# every open tutorial's solution regions replaced by their stubs, without
# tutorials/instructor/ and without the pages that quote solutions. By default every
# tutorial is open; a tutorial not named keeps its reference solution. See
# scripts/student_edition.py for the markers and for the checks CI makes of the edition.
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: scripts/student_edition.sh OUT [--open 01,03,...]" >&2; exit 2; }
exec python3 "$(dirname "$0")/student_edition.py" export "$@"
