#!/usr/bin/env bash
# Fast DDS aborts at shutdown (docs/runtime.md, "Shutdown"): N distributed runs of scenario #2, each of STEPS steps,
# one after the other, while a Monte Carlo batch in the direct layout loads the machine beside them. Counts the runs
# in which a process died of a signal (the 2.9.1 abort is signal 6, `PDP.cpp:1140 check_remote_participant_liveliness`)
# and the runs that failed otherwise.
#   tools/bench/shutdown_aborts.sh GDNAV_EXE [N=20] [STEPS=3000] [FIRST_DOMAIN=12]
# DDS domains FIRST_DOMAIN .. FIRST_DOMAIN+7 in turn (no test uses 8-19). Prints one line per run and a total.
set -uo pipefail
exe=${1:?usage: shutdown_aborts.sh GDNAV_EXE [N] [STEPS] [FIRST_DOMAIN]}
n=${2:-20}
steps=${3:-3000}
first=${4:-12}
work=$(mktemp -d /tmp/gdnav-shutdown-aborts.XXXXXX)
load_pid=
cleanup() { [ -n "$load_pid" ] && kill -- -"$load_pid" 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT
# The load: a direct-layout batch (no DDS), restarted whenever it ends, in its own process group.
setsid bash -c "while true; do '$exe' montecarlo --scenario 2 --runs 4 --jobs 1 --layout direct --steps 20000 \
  --out '$work/load' --log-level warn >/dev/null 2>&1; rm -rf '$work/load'; done" &
load_pid=$!
aborts=0 failed=0
for i in $(seq 1 "$n"); do
  domain=$((first + (i - 1) % 8))
  log="$work/run$i.log"
  "$exe" run --scenario paper2 --seed "$i" --layout distributed --domain "$domain" --steps "$steps" \
    --out "$work/run$i" > "$log" 2>&1
  code=$?
  sig=$(grep -c 'killed by signal' "$log")
  assert=$(grep -c 'check_remote_participant_liveliness' "$log")
  [ "$sig" -gt 0 ] && aborts=$((aborts + 1))
  [ "$code" -ne 0 ] && [ "$sig" -eq 0 ] && failed=$((failed + 1))
  echo "run $i (domain $domain): exit $code, processes killed by a signal: $sig, PDP assertions: $assert"
  [ "$sig" -gt 0 ] && grep -E 'killed by signal|Assertion' "$log" | head -3
  rm -rf "$work/run$i"
done
echo "shutdown_aborts: $n runs of $steps steps under load: $aborts with a process killed by a signal, $failed failed otherwise"
