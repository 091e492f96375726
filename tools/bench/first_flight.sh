#!/usr/bin/env bash
# Time to the first flight of a newcomer: a fresh clone of this repository at REV, then `deploy/setup.sh run`
# (packages already installed: GDNAV_SKIP_APT=1; no compiler cache), as the README's quick start does.
#   tools/bench/first_flight.sh [REV] [WORKDIR]     REV defaults to HEAD, WORKDIR to a new temporary folder
# Prints the build time, the number of build steps and the flight time; the clone is removed afterwards.
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
rev=${1:-HEAD}
work=${2:-$(mktemp -d /tmp/gdnav-first-flight.XXXXXX)}
trap 'rm -rf "$work"' EXIT
git clone -q "$repo" "$work/gdnav"
git -C "$work/gdnav" checkout -q "$rev"
cd "$work/gdnav"
start=$(date +%s.%N)
CCACHE_DISABLE=1 GDNAV_SKIP_APT=1 GDNAV_OUT="$work/out" deploy/setup.sh run > "$work/setup.log" 2>&1 || {
  tail -20 "$work/setup.log"; exit 1; }
end=$(date +%s.%N)
steps=$(grep -c '^\[[0-9]*/[0-9]*\]' "$work/setup.log" || true)
flight=$(grep -o 'run complete[^;]*' "$work/setup.log" | tail -1 || true)
built=$(grep -o '^\[[0-9]*/[0-9]*\]' "$work/setup.log" | tail -1 || true)
printf 'first flight of %s: %.0f s from clone to the end of the run (%s build steps %s)\n' \
  "$(git rev-parse --short "$rev")" "$(echo "$end - $start" | bc)" "$steps" "$built"
grep -E 'final horizontal error|run completed' "$work/setup.log" | tail -2
