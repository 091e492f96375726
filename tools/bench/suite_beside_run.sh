#!/usr/bin/env bash
# Isolation under load (docs/runtime.md, "DDS domains: a run owns its domain"): the CTest suite, run ROUNDS times in a
# row with `ctest -j2 -LE study`, while full-length distributed runs of scenario #2 loop beside it, each started
# without --domain (so each takes a free domain from 20 up, as a user's run would). Prints each round's CTest summary,
# one line per beside-run, and a total: suite failures, beside-runs completed, failed and interrupted at the end.
#   tools/bench/suite_beside_run.sh [BUILD_DIR=build] [ROUNDS=2] [OUT=out/suite_beside]
set -uo pipefail
build=$(cd "${1:-build}" && pwd) || { echo "suite_beside_run: no build folder '${1:-build}'" >&2; exit 2; }
rounds=${2:-2}
out=${3:-out/suite_beside}
exe="$build/bin/gdnav"
[ -x "$exe" ] || { echo "suite_beside_run: $exe is not built" >&2; exit 2; }
mkdir -p "$out"
out=$(cd "$out" && pwd)
work=$(mktemp -d /tmp/gdnav-suite-beside.XXXXXX)
loop_pid=
cleanup() { [ -n "$loop_pid" ] && kill -- -"$loop_pid" 2>/dev/null; wait 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT
: > "$out/beside.txt"
# The beside loop, in its own process group: one line per finished run (seed, exit code, seconds, last log line).
setsid bash -c "i=0; while true; do i=\$((i + 1)); start=\$(date +%s); \
  '$exe' run --scenario paper2 --layout distributed --seed \$i --out '$work/run' > '$work/run.log' 2>&1; code=\$?; \
  echo \"seed \$i: exit \$code, \$((\$(date +%s) - start)) s, \$(tail -n 1 '$work/run.log')\" >> '$out/beside.txt'; \
  [ \$code -ne 0 ] && cp '$work/run.log' \"$out/beside_seed\$i.log\"; rm -rf '$work/run'; done" &
loop_pid=$!
suite_failures=0
for r in $(seq 1 "$rounds"); do
  echo "round $r of $rounds: ctest -j2 -LE study ($(date +%T))"
  (cd "$build" && ctest -j2 -LE study --output-on-failure > "$out/ctest_round$r.log" 2>&1)
  code=$?
  grep -E 'tests passed|Total Test time' "$out/ctest_round$r.log"
  [ "$code" -ne 0 ] && { suite_failures=$((suite_failures + 1)); grep -A40 'The following tests FAILED' "$out/ctest_round$r.log"; }
done
kill -- -"$loop_pid" 2>/dev/null
wait "$loop_pid" 2>/dev/null
loop_pid=
cat "$out/beside.txt"
completed=$(grep -c ': exit 0,' "$out/beside.txt")
failed=$(grep -vc ': exit 0,' "$out/beside.txt")
echo "suite_beside_run: $rounds suite rounds, $suite_failures with a failure; beside-runs: $completed completed," \
  "$failed failed (the one running at the end was interrupted and is not listed)"
[ "$suite_failures" -eq 0 ] && [ "$failed" -eq 0 ]
