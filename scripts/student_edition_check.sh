#!/usr/bin/env bash
# CI's proof of the student edition (scripts/student_edition.sh), on the core and the
# tutorial targets only (no GUI, web or docs):
#  1. export the edition (every tutorial open) and look for leaks: no whitespace-normalised
#     line of 25 characters or more of a solution region (or of tutorials/instructor/)
#     occurs anywhere in it, sources, pages and tests, nor in the built docs site (SITE,
#     default build/docs/html when it is built: the instructor's site, which scripts/test.sh
#     builds before this stage, less the pages the edition replaces; the edition itself
#     builds no docs);
#  2. build it with the README's commands: every tutorial says NOT YET, and the CLI says in
#     one sentence that it cannot draw before tutorial 01;
#  3. put the instructor's solutions into the holes: every tutorial says SOLVED, and every
#     built-in scene renders at 64x48 byte for byte as the main build (MAIN, default
#     build/src/raycache) renders it, uncached and with the caches that use the holes (and
#     in breadth-first order, tutorial 04's fill);
#  4. put each recorded wrong answer of a hole tutorial (its answers to the regions, spliced
#     into the hole file) into its exercise.cpp: NOT YET.
# Usage: scripts/student_edition_check.sh [MAIN_RAYCACHE] [WORK_DIR] [SITE]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
main="${1:-$root/build/src/raycache}"
work="${2:-$(mktemp -d)}"
[ -x "$main" ] || { echo "student edition: no main build at $main" >&2; exit 2; }
# Both may be given relative to where the script was called from; it changes folder below
main="$(realpath "$main")"
mkdir -p "$work"
work="$(cd "$work" && pwd)"
edition="$work/edition"
jobs=$(nproc)
rm -rf "$edition"
"$root/scripts/student_edition.sh" "$edition"
site="${3:-$root/build/docs/html}"
if [ -d "$site" ]; then
  python3 "$root/scripts/student_edition.py" leaks "$edition" --site "$(realpath "$site")"
else
  echo "student edition: no docs site at $site (not built): the site is not checked"
  python3 "$root/scripts/student_edition.py" leaks "$edition"
fi

launcher=()
if command -v ccache >/dev/null; then
  # Paths relative to the project's root: the edition's objects that equal the main build's
  # (scripts/test.sh builds it with ccache too) come from the cache
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}"
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
cd "$edition"
# No -DRAYCACHE_DOCS=OFF: the edition's own tutorials/student_edition.cmake must leave the
# instructor's docs site out of a student build
cmake --preset default -DRAYCACHE_GUI=OFF -DRAYCACHE_WEB=OFF "${launcher[@]}" >/dev/null
grep -q '^RAYCACHE_DOCS:BOOL=OFF$' build/CMakeCache.txt ||
  { echo "student edition: a student build would build the docs site (RAYCACHE_DOCS is not OFF)" >&2; exit 1; }
grep -q '^RAYCACHE_STUDENT:BOOL=ON$' build/CMakeCache.txt ||
  { echo "student edition: the edition's default build is not a student build" >&2; exit 1; }
tutorials=$(ls -d tutorials/0*-* | sed 's|tutorials/||')
targets=(raycache)
for t in $tutorials; do targets+=("tutorial_${t:0:2}_exercise"); done
build() {
  cmake --build build -j "$jobs" --target "$@" >"$work/build.log" 2>&1 || { tail -40 "$work/build.log" >&2; return 1; }
}

# Runs tutorial NN's check; prints SOLVED or NOT YET and exits 0 when it says `want`
verdict() {
  local nn=$1 want=$2 out
  out=$(cd build/tutorials && "./tutorial_${nn}_exercise" 2>&1 || true)
  if grep -q "^$want" <<<"$out"; then return 0; fi
  echo "student edition: tutorial $nn does not say $want:" >&2
  tail -30 <<<"$out" >&2
  return 1
}

build "${targets[@]}"
for t in $tutorials; do verdict "${t:0:2}" "NOT YET"; done
if out=$(build/src/raycache render cube:2 --width 64 --height 48 -q --hash 2>&1); then
  echo "student edition: raycache drew with tutorial 01's stub: $out" >&2
  exit 1
fi
grep -q "do tutorial 01" <<<"$out" || { echo "student edition: raycache said: $out" >&2; exit 1; }
echo "student edition: every tutorial NOT YET; raycache says: $out"

python3 "$root/scripts/student_edition.py" inject "$edition"
build "${targets[@]}"
for t in $tutorials; do verdict "${t:0:2}" "SOLVED"; done
scenes=$("$main" scenes | awk '{print $1}' | sed 's/:N$/:3/')
renders=0
for scene in $scenes; do
  for cache in none blocker blocker+ cylinder; do
    a=$("$main" render "$scene" --width 64 --height 48 --cache "$cache" --threads 1 -q --hash)
    b=$(build/src/raycache render "$scene" --width 64 --height 48 --cache "$cache" --threads 1 -q --hash)
    [ "$a" = "$b" ] || { echo "student edition: $scene --cache $cache: $b, main build $a" >&2; exit 1; }
    renders=$((renders + 1))
  done
  # Breadth-first order runs tutorial 04's fill (with a cache that defers its misses)
  a=$("$main" render "$scene" --width 64 --height 48 --cache cylinder --order bfs --threads 1 -q --hash)
  b=$(build/src/raycache render "$scene" --width 64 --height 48 --cache cylinder --order bfs --threads 1 -q --hash)
  [ "$a" = "$b" ] || { echo "student edition: $scene --cache cylinder --order bfs: $b, main build $a" >&2; exit 1; }
  renders=$((renders + 1))
done
echo "student edition: every tutorial SOLVED with the instructor's solutions; $renders renders equal the main build's"

rejected=0
for wrong in "$root"/tutorials/instructor/wrong/*.cpp; do
  nn=$(basename "$wrong" | cut -c1-2)
  dir=$(ls -d tutorials/"$nn"-*)
  # Only the holes: the other tutorials' checks are the main build's, which rejects them
  hole=$(sed -n "s/^ *\"$nn|\([^|]*\)|.*/\1/p" "$root/src/CMakeLists.txt")
  [ -n "$hole" ] || continue
  cp "$dir/exercise.cpp" "$work/solved.cpp"
  # The wrong answer holds its answer to each region: spliced into the hole file as the
  # main build does (the edition's copy has no regions left)
  python3 "$root/scripts/student_edition.py" splice "$root/src/$hole" "$wrong" "$dir/exercise.cpp"
  build "tutorial_${nn}_exercise"
  verdict "$nn" "NOT YET"
  cp "$work/solved.cpp" "$dir/exercise.cpp"
  rejected=$((rejected + 1))
done
echo "student edition: $rejected recorded wrong answers of the holes rejected"
