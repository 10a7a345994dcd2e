#!/usr/bin/env bash
# Fuzz the NFF reader (fuzz_nff) and the tracer on the scenes it accepts (fuzz_render)
# with libFuzzer, under ASan and UBSan, for a bounded time.
# Usage: scripts/fuzz.sh [seconds] [target...]
#   seconds   the whole run's budget, split evenly over the targets (default 600)
#   target    fuzz_nff and/or fuzz_render (default: both)
# The seed corpus is copied at run time from tests/data (every .nff) and the SPD scenes
# (RAYCACHE_SCENES_DIR, default scenes); what the fuzzer learns is kept in
# build-fuzz/corpus/<target>. A finding stops the run with a non-zero exit and leaves
# the input in build-fuzz/artifacts/: reproduce it with `build-fuzz/fuzz/<target> FILE`,
# then add it to tests/data/regressions/ (see tests/test_robustness.cpp).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
if (($# > 0)); then shift; fi
targets=("$@")
if ((${#targets[@]} == 0)); then targets=(fuzz_nff fuzz_render); fi
scenes=${RAYCACHE_SCENES_DIR:-scenes}
jobs=${RAYCACHE_JOBS:-$(nproc)}

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$jobs"

out=build-fuzz
seeds=$out/seeds
rm -rf "$seeds"
mkdir -p "$seeds" "$out/artifacts"
while IFS= read -r -d '' f; do
  rel=${f#tests/data/}
  cp "$f" "$seeds/${rel//\//_}"
done < <(find tests/data -type f -name '*.nff' -print0)
if [[ -d "$scenes" ]]; then
  for f in "$scenes"/*.nff; do [[ -e "$f" ]] && cp "$f" "$seeds/spd_$(basename "$f")"; done
else
  echo "fuzz: no SPD scenes at $scenes; seeding from tests/data only" >&2
fi

per=$((seconds / ${#targets[@]}))
((per >= 1)) || per=1
status=0
for t in "${targets[@]}"; do
  mkdir -p "$out/corpus/$t"
  log=$out/$t.log
  echo "fuzz: $t for ${per} s ($(ls "$seeds" | wc -l) seeds, corpus $out/corpus/$t, log $log)"
  # -timeout: one input taking longer is a hang; -malloc_limit_mb: one allocation
  # larger than this is a runaway allocation; -rss_limit_mb: the whole process.
  if "$out/fuzz/$t" "$out/corpus/$t" "$seeds" -dict=fuzz/nff.dict \
       -max_total_time="$per" -max_len=32768 -timeout=10 -malloc_limit_mb=512 -rss_limit_mb=2048 \
       -artifact_prefix="$out/artifacts/$t-" -print_final_stats=1 >"$log" 2>&1; then
    grep -E '^stat::(number_of_executed_units|average_exec_per_sec|new_units_added|peak_rss_mb)' "$log" | sed "s/^/fuzz: $t /"
    grep -E '^#[0-9]+ +DONE' "$log" | tail -1 | sed "s/^/fuzz: $t /" || true
  else
    status=1
    echo "fuzz: $t FOUND A PROBLEM; the end of $log:" >&2
    tail -60 "$log" >&2
    ls -l "$out/artifacts" >&2
  fi
done
exit $status
