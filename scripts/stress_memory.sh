#!/usr/bin/env bash
# Memory and time on degenerate scenes (issue 18): 34,000 coincident unit spheres seen
# along z and from the side, and 20,000 tiny spheres inside a huge box, rendered at 64x64
# with the linear scan, the grid and the BVH under a 3 GiB address-space limit. Prints
# the peak resident size and the wall time of each run; fails when a run fails.
# Usage: scripts/stress_memory.sh [path/to/raycache] (default build/src/raycache)
set -euo pipefail
cd "$(dirname "$0")/.."
cli=${1:-build/src/raycache}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

header() {  # $1: from, $2: at
  printf 'b 0.1 0.1 0.1\nv\nfrom %s\nat %s\nup 0 1 0\nangle 45\nhither 0.01\nresolution 64 64\n' "$1" "$2"
  printf 'l 5 5 5\nf 0.8 0.4 0.2 0.7 0.3 20 0 1\n'
}
{ header "0 0 10" "0 0 0"; awk 'BEGIN { for (i = 0; i < 34000; ++i) print "s 0 0 0 1" }'; } > "$dir/coincident_z.nff"
{ header "6 4 3" "0 0 0"; awk 'BEGIN { for (i = 0; i < 34000; ++i) print "s 0 0 0 1" }'; } > "$dir/coincident_side.nff"
{ header "0.5 0.5 3" "0.5 0.5 0.5"
  awk 'BEGIN { srand(18); for (i = 0; i < 20000; ++i) printf "s %.6f %.6f %.6f 0.001\n", rand(), rand(), rand()
               # a huge box around them: six squares 2e6 on a side
               l = "-1e6"; h = "1e6"
               print "p 4\n" l " " l " " l "\n" h " " l " " l "\n" h " " h " " l "\n" l " " h " " l
               print "p 4\n" l " " l " " h "\n" l " " h " " h "\n" h " " h " " h "\n" h " " l " " h
               print "p 4\n" l " " l " " l "\n" l " " l " " h "\n" h " " l " " h "\n" h " " l " " l
               print "p 4\n" l " " h " " l "\n" h " " h " " l "\n" h " " h " " h "\n" l " " h " " h
               print "p 4\n" l " " l " " l "\n" l " " h " " l "\n" l " " h " " h "\n" l " " l " " h
               print "p 4\n" h " " l " " l "\n" h " " l " " h "\n" h " " h " " h "\n" h " " h " " l }'
} > "$dir/tiny_in_huge_box.nff"

status=0
for scene in coincident_z coincident_side tiny_in_huge_box; do
  for accel in linear grid bvh; do
    if (ulimit -v $((3 * 1024 * 1024)); /usr/bin/time -v "$cli" render "$dir/$scene.nff" --accel "$accel" \
          --width 64 --height 64 -q -o "$dir/out.png") 2> "$dir/time.txt"; then
      result=ok
    else
      result="FAILED (exit $?)"; status=1
    fi
    rss=$(awk -F': ' '/Maximum resident/ { printf "%.0f MB", $2 / 1024 }' "$dir/time.txt")
    wall=$(awk -F': ' '/Elapsed \(wall/ { print $2 }' "$dir/time.txt")
    printf '%-18s %-7s %-10s peak %-9s wall %s\n' "$scene" "$accel" "$result" "$rss" "$wall"
    [ "$result" = ok ] || grep -v '^\s' "$dir/time.txt" | head -3
  done
done
exit $status
