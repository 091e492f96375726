#!/bin/bash
# What the live view costs a run (docs/viewing.md, "Live view"): REPS interleaved rounds of three runs of the same
# scenario — without --live, with --live and no client, with --live and a client that subscribes to every channel and
# then stops reading (live_stalled_client.py) — and per variant the median steps/s of the clock (clock_summary.yaml,
# from step 0 to the end: start-up excluded), the median CPU time per step of all the run's processes (user + system,
# /usr/bin/time; start-up included) and, for the stalled client, the frames it was sent and dropped.
# A benchmark, not a test: the figures depend on the machine and its load.
#   tools/bench/live_cost.sh [BUILD_DIR=build] [STEPS=20000] [REPS=5] [LAYOUT=composed] [SCENARIO=paper2] [TOPICS]
# TOPICS: --live-topics of the live runs (default: gdnav's default, every topic the run writes and the viewer channels).
set -euo pipefail
B=$(realpath "${1:-build}"); N=${2:-20000}; R=${3:-5}; LAYOUT=${4:-composed}; SCEN=${5:-paper2}; TOPICS=${6:-}
HERE=$(cd "$(dirname "$0")" && pwd)
case "$LAYOUT" in direct|composed|distributed) ;; *) echo "live_cost: LAYOUT must be direct, composed or distributed" >&2; exit 2;; esac
[ -x /usr/bin/time ] || { echo "live_cost: /usr/bin/time missing (apt-get install time)" >&2; exit 2; }
T=$(mktemp -d)
CLIENT=""
cleanup() { if [ -n "$CLIENT" ]; then kill "$CLIENT" 2>/dev/null || true; fi; rm -rf "$T"; }
trap cleanup EXIT
trap 'exit 130' INT TERM
port=$(/usr/bin/python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')
sps() { awk '/^steps_per_s:/ {print $2}' "$1/clock_summary.yaml"; }  # of a finished run directory
one() {  # $1 = off|idle|stalled, $2 = round
    local out=$T/$1-$2 args=()
    [ "$1" != off ] && args=(--live "$port")
    [ "$1" != off ] && [ -n "$TOPICS" ] && args+=(--live-topics "$TOPICS")
    if [ "$1" = stalled ]; then
        /usr/bin/python3 "$HERE/live_stalled_client.py" "$port" 600 > "$T/client.log" 2>&1 &
        CLIENT=$!
    fi
    /usr/bin/time -f "%U %S" -o "$out.time" "$B/bin/gdnav" run --scenario "$SCEN" --seed 1 --layout "$LAYOUT" \
        --steps "$N" "${args[@]}" --out "$out" > "$out.log" 2>&1 || { echo "live_cost: run $1 failed:"; tail -5 "$out.log"; exit 1; }
    awk -v n="$N" '{print 1e6 * ($1 + $2) / n}' "$out.time" >> "$T/$1.cpu"
    if [ "$1" = stalled ]; then
        kill "$CLIENT" 2>/dev/null || true; wait "$CLIENT" 2>/dev/null || true; CLIENT=""
        grep -q STALLED "$T/client.log" || { echo "live_cost: the client did not subscribe:"; cat "$T/client.log"; exit 1; }
        awk -F'[{},:]+' '/frames_sent/ {for (i = 1; i < NF; ++i) {if ($i ~ /frames_sent/) s = $(i+1); if ($i ~ /frames_dropped/) d = $(i+1)}}
            END {print s + 0, d + 0}' "$out/live_stats.yaml" >> "$T/stalled.frames"
    fi
    sps "$out" >> "$T/$1.sps"
}
echo "live_cost: scenario $SCEN, $LAYOUT layout, $N steps, $R rounds (port $port)${TOPICS:+, --live-topics $TOPICS}"
for r in $(seq 1 "$R"); do
    for v in off idle stalled; do one "$v" "$r"; done
    echo "  round $r: off $(tail -1 "$T/off.sps"), idle $(tail -1 "$T/idle.sps"), stalled $(tail -1 "$T/stalled.sps") steps/s;" \
         "stalled client: sent/dropped frames $(tail -1 "$T/stalled.frames")"
done
median() { sort -g "$1" | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
rel() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%+.1f%%", 100 * (a / b - 1)}'; }
printf "%-26s %10s %9s %16s %9s\n" "variant" "steps/s" "vs off" "CPU us per step" "vs off"
for v in off idle stalled; do
    s=$(median "$T/$v.sps"); c=$(median "$T/$v.cpu")
    case $v in off) name="without --live";; idle) name="--live, no client";; stalled) name="--live, stalled client";; esac
    if [ $v = off ]; then so=$s; co=$c; printf "%-26s %10.0f %9s %16.2f %9s\n" "$name" "$s" "-" "$c" "-"
    else printf "%-26s %10.0f %9s %16.2f %9s\n" "$name" "$s" "$(rel "$s" "$so")" "$c" "$(rel "$c" "$co")"; fi
done
