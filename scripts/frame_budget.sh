#!/usr/bin/env bash
# The window never freezes: runs raycache-gui in a real window (under Xvfb, 1280x720) on
# the heaviest views and on every stop of both tours, each with --walk and --frame-log,
# and prints the slowest UI-thread task of each run and first-frame. The budget is 100 ms
# a task and 1 s to the first frame (a benchmark: its times depend on the machine).
# Usage: scripts/frame_budget.sh [BUILD_DIR] (default build). Needs xvfb-run (setup.sh).
# With RAYCACHE_FRAME_CLOCK=cpu the log counts the window thread's CPU time instead of
# wall time: on a machine busy with other work, that is the window's own share.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
gui=$build/ui/raycache-gui
out=$(mktemp -d)
run() {
  local name=$1
  shift
  local log=$out/$name.txt
  xvfb-run -a -s "-screen 0 1280x720x24" "$gui" "$@" --walk --frame-log "$log" >"$out/$name.out" 2>&1
  # The slowest task (named), first-frame, and how many tasks were logged
  python3 - "$name" "$log" <<'PY'
import sys
name, path = sys.argv[1], sys.argv[2]
tasks = [l.rsplit(" ", 1) for l in open(path) if l.strip()]
first = [float(ms) for n, ms in tasks if n == "first-frame"]
# Every task but first-frame: events, and the phases run outside the event loop (apply, stop-K)
events = [(float(ms), n) for n, ms in tasks if n != "first-frame" and not n.startswith("paint:")]
worst = max(events) if events else (0.0, "none")
over = sum(1 for ms, _ in events if ms > 100.0)
print(f"{name:28s} tasks {len(events):7d}  slowest {worst[0]:8.1f} ms ({worst[1]})  over 100 ms: {over}"
      f"  first-frame {first[0] if first else float('nan'):7.1f} ms")
# A tour: the slowest task of each stop (start-up counts to stop 1; a stop's tasks run
# from its stop-K line to the next)
stop, per = 1, {}
for n, ms in tasks:
    if n.startswith("stop-"):
        stop = int(n[5:])
    if n == "first-frame" or n.startswith("paint:"):
        continue
    per[stop] = max(per.get(stop, (0.0, "")), (float(ms), n))
if any(n.startswith("stop-") for n, _ in tasks):
    for k in sorted(per):
        print(f"    stop {k:2d}  slowest {per[k][0]:7.1f} ms ({per[k][1]})")
PY
}
echo "raycache-gui frame log, $(date -u +%Y-%m-%d), $(nproc) cores, clock ${RAYCACHE_FRAME_CLOCK:-wall}, load $(cut -d' ' -f1 /proc/loadavg); budget: 100 ms a task, 1000 ms to the first frame"
run "balls:4 blocker, all views" balls:4 --width 512 --height 512 --cache blocker --steps 2000000 \
    --select 256,500 --overlays all --scene-view side --compare none:scanline --window 1280x720 --large-fonts
run "tour hanrahan86" --tour tours/hanrahan86.json --window 1280x720 --large-fonts
run "tour debugging" --tour tours/debugging.json --window 1280x720 --large-fonts
echo "logs: $out"
