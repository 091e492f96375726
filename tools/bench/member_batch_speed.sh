#!/bin/bash
# What a swapped-in member costs a Monte Carlo batch (docs/runtime.md, "Members: what a step costs"; the measured
# sets in docs/notes/member-batch-speed.md). On one machine and in the same minutes: the plain two-process DDS
# ping-pong of an attitude member's messages (bench_dds_ping_pong), alone and two at once (the batches run two jobs),
# on Fast DDS's default transports (shared memory on one host) and on gdnav's own (config/dds/gdnav_profiles.xml, UDP),
# the built-in nav_att's cost per step (gdnav bench), then five batches of RUNS runs of scenario #2 with --jobs 2 and seed 1:
#   base       the built-in filters, direct layout
#   py_in      examples/python/complementary_attitude.py's class as nav_att inside gdnav, direct
#   base_comp  the built-in filters, composed layout (the floor of the process members' rows)
#   cxx_proc   examples/attitude_filter (gdnav-example-attitude) as a process member, composed
#   py_proc    the Python example as a process member, composed
# Per batch: its wall time; the median over its runs of the run's wall time per step (clock_summary.yaml, from step
# 0); the member's CPU per step: its step callback (Python: the callback's CPU mean from its log line; the class's own
# step timed inside Python for py_in) and, for process members, the whole member process (user + sys from
# /usr/bin/time, divided by the steps). What gdnav adds per step beyond the member's own step:
#   in process    the callback's CPU as gdnav calls it minus the class's own step (both CPU times)
#   process       run wall/step - base_comp's run wall/step - (member callback CPU - built-in nav_att CPU): the
#                 hop the member adds; the C++ example's callback is not timed and counted as 0, so its figure is an
#                 upper bound. Compared with the ping-pong's median round trip.
# The batch folders stay in OUT (they are the tables of docs/results.md when RUNS is 100).
#   tools/bench/member_batch_speed.sh [BUILD_DIR=build] [RUNS=100] [OUT=out/member_speed] [DOMAIN=200]
# PY_PROC_RUNS=N (environment) flies the slowest batch, py_proc, with N runs instead of RUNS.
set -euo pipefail
B=$(realpath "${1:-build}"); R=${2:-100}; OUT=$(realpath -m "${3:-out/member_speed}"); D=${4:-200}
RP=${PY_PROC_RUNS:-$R}
SRC=$(cd "$(dirname "$0")/../.." && pwd)
G=$B/bin/gdnav
CPP=$B/examples-build/bin/gdnav-example-attitude
PY=$SRC/examples/python/complementary_attitude.py
[ -x "$CPP" ] || { echo "member_batch_speed: $CPP missing: run ctest -R ExamplesPackage first" >&2; exit 2; }
[ -x "$B/tests/bench_dds_ping_pong" ] || { echo "member_batch_speed: $B/tests/bench_dds_ping_pong missing (build it)" >&2; exit 2; }
[ -d "$B/python" ] || { echo "member_batch_speed: $B/python missing (Python bindings not built)" >&2; exit 2; }
[ -x /usr/bin/time ] || { echo "member_batch_speed: /usr/bin/time missing (apt-get install time)" >&2; exit 2; }
mkdir -p "$OUT"
median() { sort -g | awk '{a[NR]=$1} END {if (NR == 0) print "nan"; else print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }
batch() {  # $1 = name, $2 = layout, $3 = runs, then extra montecarlo arguments; prints the batch's wall time [s]
    local name=$1 layout=$2 runs=$3; shift 3
    local t0; t0=$(date +%s.%N)
    "$G" montecarlo --scenario 2 --runs "$runs" --jobs 2 --seed 1 --layout "$layout" --domain "$D" --no-figures \
        --out "$OUT/$name" "$@" > "$OUT/$name.log" 2>&1 || { echo "member_batch_speed: batch $name failed (see $OUT/$name.log)" >&2; exit 1; }
    echo "$(date +%s.%N) - $t0" | bc -l
}
wall_per_step() {  # median over the runs of $1 of wall_s / steps, in us
    for r in "$OUT/$1"/runs/run_*; do
        awk '/^wall_s:/ {w=$2} /^steps_done:/ {s=$2} END {if (s > 0) printf "%.6f\n", 1e6 * w / s}' "$r/clock_summary.yaml"
    done | median
}
callback_cpu() {  # median over the runs of $1 of the Python callback's CPU mean [us]; $2 = the log file in the run
    for r in "$OUT/$1"/runs/run_*; do grep -o 'steps: CPU mean [0-9.]*' "$r/$2" | tail -1 | awk '{print $4}'; done | median
}
process_cpu() {  # median over the runs of $1 of the member process's (user + sys) / steps [us]
    for r in "$OUT/$1"/runs/run_*; do
        awk -v s="$(awk '/^steps_done:/ {print $2}' "$r/clock_summary.yaml")" '{printf "%.6f\n", 1e6 * ($1 + $2) / s}' "$r/member_cpu.txt"
    done | median
}

ping_pong() {  # $1 = output name, then bench_dds_ping_pong's extra arguments; sets pp_alone and pp_two (medians)
    local name=$1; shift
    "$B/tests/bench_dds_ping_pong" --domain "$D" --rounds 20000 --warmup 1000 "$@" | tee "$OUT/$name.txt"
    "$B/tests/bench_dds_ping_pong" --domain "$((D + 1))" --rounds 20000 --warmup 1000 "$@" > "$OUT/${name}_a.txt" &
    "$B/tests/bench_dds_ping_pong" --domain "$((D + 2))" --rounds 20000 --warmup 1000 "$@" > "$OUT/${name}_b.txt"
    wait
    cat "$OUT/${name}_a.txt" "$OUT/${name}_b.txt"
    pp_alone=$(grep -o 'median [0-9.]*' "$OUT/$name.txt" | awk '{print $2}')
    pp_two=$(grep -ho 'median [0-9.]*' "$OUT/${name}_a.txt" "$OUT/${name}_b.txt" | awk '{s += $2} END {print s / NR}')
}

echo "member_batch_speed: $(nproc) cores, $(uname -n), commit $(git -C "$SRC" rev-parse --short HEAD 2>/dev/null || echo '?'), $(date -u +%FT%TZ)"
echo "1/7 plain DDS ping-pong, alone and two at once (as the batches' two jobs); default transports, then gdnav's"
ping_pong ping_pong
pp=$pp_alone; pp2=$pp_two
# The same on the transport a gdnav run uses (gdnav_profiles.xml: UDP only, no data sharing; the default transports
# above take shared memory between two processes of one host).
UDP_PROFILES=$SRC/config/dds/gdnav_profiles.xml
ping_pong ping_pong_udp --profiles "$UDP_PROFILES"
ppu=$pp_alone; ppu2=$pp_two
echo "2/7 built-in nav_att per step (gdnav bench, direct)"
"$G" bench --scenario paper2 --steps 20000 --layouts direct --mc-runs 0 > "$OUT/bench.txt" 2>&1
nav_att=$(awk '$1 == "nav_att" {print $2}' "$OUT/bench.txt")
echo "3/7 batch base";      w_base=$(batch base direct "$R")
echo "4/7 batch py_in";     w_py_in=$(batch py_in direct "$R" --member "nav_att=python:$SRC/tools/bench/timed_member.py:Timed")
echo "5/7 batch base_comp"; w_base_comp=$(batch base_comp composed "$R")
echo "6/7 batch cxx_proc";  w_cxx=$(batch cxx_proc composed "$R" --member "nav_att=/usr/bin/time -f '%U %S' -o {out}/member_cpu.txt $CPP")
echo "7/7 batch py_proc"
w_py_proc=$(PYTHONPATH=$B/python batch py_proc composed "$RP" --member "nav_att=/usr/bin/time -f '%U %S' -o {out}/member_cpu.txt /usr/bin/python3 $PY")

s_base=$(wall_per_step base); s_py_in=$(wall_per_step py_in); s_comp=$(wall_per_step base_comp)
s_cxx=$(wall_per_step cxx_proc); s_py_proc=$(wall_per_step py_proc)
body=$(for r in "$OUT"/py_in/runs/run_*; do grep -o 'body [0-9.]*' "$r/log.txt" | awk '{print $2}'; done | median)
cb_in=$(callback_cpu py_in log.txt); cb_proc=$(callback_cpu py_proc logs/nav_att.log)
p_cxx=$(process_cpu cxx_proc); p_py=$(process_cpu py_proc)
add_in=$(echo "$cb_in - $body" | bc -l)
add_cxx=$(echo "$s_cxx - $s_comp + $nav_att" | bc -l)
add_py=$(echo "$s_py_proc - $s_comp - ($cb_proc - $nav_att)" | bc -l)
echo
echo "scenario #2, $R runs per batch ($RP for py_proc), --jobs 2, seed 1 (us per step unless stated; medians over the runs)"
printf "%-10s %-9s %9s %11s %12s %12s %12s\n" batch layout "batch [s]" "run wall" "member step" "member proc" "gdnav adds"
printf "%-10s %-9s %9.0f %11.2f %12.2f %12s %12s\n" base direct "$w_base" "$s_base" "$nav_att" - -
printf "%-10s %-9s %9.0f %11.2f %12.2f %12s %12.2f\n" py_in direct "$w_py_in" "$s_py_in" "$body" - "$add_in"
printf "%-10s %-9s %9.0f %11.2f %12.2f %12s %12s\n" base_comp composed "$w_base_comp" "$s_comp" "$nav_att" - -
printf "%-10s %-9s %9.0f %11.2f %12s %12.2f %12.2f\n" cxx_proc composed "$w_cxx" "$s_cxx" "not timed" "$p_cxx" "$add_cxx"
printf "%-10s %-9s %9.0f %11.2f %12.2f %12.2f %12.2f\n" py_proc composed "$w_py_proc" "$s_py_proc" "$cb_proc" "$p_py" "$add_py"
echo "in process: the callback as gdnav calls it $cb_in us CPU, the class's own step $body us: gdnav adds $(printf %.2f "$add_in") us (target <= 5)"
echo "process members: plain ping-pong round trip $pp us alone, $(printf %.1f "$pp2") us two at once (medians); gdnav adds $(printf %.1f "$add_cxx") us (C++) and $(printf %.1f "$add_py") us (Python)"
echo "  against the round trip alone: $(echo "$add_cxx / $pp" | bc -l | xargs printf %.2f)x and $(echo "$add_py / $pp" | bc -l | xargs printf %.2f)x; two at once: $(echo "$add_cxx / $pp2" | bc -l | xargs printf %.2f)x and $(echo "$add_py / $pp2" | bc -l | xargs printf %.2f)x (target <= 1.2x)"
echo "plain ping-pong on gdnav's transport (UDP, $(basename "$UDP_PROFILES")): $ppu us alone, $(printf %.1f "$ppu2") us two at once (medians)"
echo "  against it alone: $(echo "$add_cxx / $ppu" | bc -l | xargs printf %.2f)x and $(echo "$add_py / $ppu" | bc -l | xargs printf %.2f)x; two at once: $(echo "$add_cxx / $ppu2" | bc -l | xargs printf %.2f)x and $(echo "$add_py / $ppu2" | bc -l | xargs printf %.2f)x"
