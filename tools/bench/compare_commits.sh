#!/usr/bin/env bash
# The speed of two commits, measured interleaved on this machine: every speed claim in the docs quotes this
# (docs/runtime.md, "gdnav bench").
#   tools/bench/compare_commits.sh A B [N] [-- BENCH_ARGS...]
# Builds the gdnav program of commits A and B in worktrees of their own (WORK, default /tmp/gdnav-compare-<A>-<B>;
# kept, so a second call rebuilds nothing), then runs `gdnav bench` of A, of B, of A, ... N times each (default 5),
# alternating so that a drift of the machine's speed hits both, and prints per layout the median steps/s of each and
# the median of the pairwise ratios B/A (> 1: B faster), with their min and max. BENCH_ARGS default to
# `--scenario default --steps 20000 --mc-runs 0`. Environment: WORK, JOBS (build jobs, default nproc).
# Quiet machine wanted: nothing else building or running.
set -euo pipefail
usage() { echo "usage: tools/bench/compare_commits.sh A B [N] [-- BENCH_ARGS...]" >&2; exit 2; }
[ $# -ge 2 ] || usage
repo=$(cd "$(dirname "$0")/../.." && pwd)
a=$(git -C "$repo" rev-parse --short "$1" 2>/dev/null) || { echo "compare_commits: '$1' is not a commit" >&2; exit 2; }
b=$(git -C "$repo" rev-parse --short "$2" 2>/dev/null) || { echo "compare_commits: '$2' is not a commit" >&2; exit 2; }
shift 2
n=5
if [ $# -gt 0 ] && [ "$1" != "--" ]; then n=$1; shift; fi
[[ "$n" =~ ^[1-9][0-9]*$ ]] || { echo "compare_commits: N must be a whole number >= 1, not '$n'" >&2; exit 2; }
[ $# -gt 0 ] && { [ "$1" = "--" ] || usage; shift; }
bench_args=("$@")
[ ${#bench_args[@]} -gt 0 ] || bench_args=(--scenario default --steps 20000 --mc-runs 0)
work=${WORK:-/tmp/gdnav-compare-$a-$b}
mkdir -p "$work"

build() {  # commit -> path of its gdnav
  local rev=$1 tree="$work/$1"
  if [ ! -d "$tree" ]; then git -C "$repo" worktree add -q --detach "$tree" "$rev"; fi
  echo "compare_commits: building $rev in $tree (log $tree.build.log)" >&2
  { cmake -S "$tree" -B "$tree/build" -G Ninja -DCMAKE_BUILD_TYPE=Release &&
    cmake --build "$tree/build" -j "${JOBS:-$(nproc)}" --target gdnav; } > "$tree.build.log" 2>&1 || {
    tail -20 "$tree.build.log" >&2; echo "compare_commits: the build of $rev failed" >&2; exit 1; }
}
build "$a"
build "$b"

for i in $(seq 1 "$n"); do
  for rev in "$a" "$b"; do
    echo "compare_commits: round $i/$n, $rev" >&2
    (cd "$work/$rev" && build/bin/gdnav bench "${bench_args[@]}" --json "$work/bench_${rev}_$i.json" > /dev/null) || {
      echo "compare_commits: gdnav bench of $rev failed (round $i)" >&2; exit 1; }
  done
done

/usr/bin/python3 - "$work" "$a" "$b" "$n" <<'PY'
import json, statistics, sys
work, a, b, n = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
load = lambda rev, i: json.load(open(f"{work}/bench_{rev}_{i}.json"))
runs = [(load(a, i), load(b, i)) for i in range(1, n + 1)]
print(f"gdnav bench, {n} interleaved pairs, {runs[0][0]['scenario']}, {runs[0][0]['steps']} steps; "
      f"{runs[0][0]['machine']['cpu_model']}, {runs[0][0]['machine']['cores']} cores")
print(f"{'layout':<20}{'A ' + a + ' steps/s':>22}{'B ' + b + ' steps/s':>22}{'B/A median [min, max]':>28}")
for layout in runs[0][0]['layouts']:
    sa = [ra['layouts'][layout]['steps_per_s'] for ra, _ in runs]
    sb = [rb['layouts'][layout]['steps_per_s'] for _, rb in runs]
    r = [y / x for x, y in zip(sa, sb)]
    print(f"{layout:<20}{statistics.median(sa):>22.0f}{statistics.median(sb):>22.0f}"
          f"{statistics.median(r):>12.3f} [{min(r):.3f}, {max(r):.3f}]")
PY
