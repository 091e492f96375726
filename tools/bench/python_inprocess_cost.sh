#!/bin/bash
# What an in-process Python member costs per step (docs/python.md, "In-process members"; notes in
# docs/notes/python-member-cost.md): scenario #2, direct layout, REPS interleaved pairs of runs — the built-in nav_att,
# then the example's member class (examples/python/complementary_attitude.py) in its place, inside gdnav. Per pair:
#   base, py      the run's wall time per step from step 0 (clock_summary.yaml) of each
#   extra         py - base: what the run pays per step for the swap (the Python filter minus the built-in EKF)
#   body CPU      the class's step itself, its thread's CPU time read inside Python (time.thread_time_ns around it)
#   cb CPU        the step as gdnav calls it (GIL taken, arguments, the call, GIL released): its CPU time
#                 (CLOCK_THREAD_CPUTIME_ID, the log line's CPU mean)
#   handover      cb CPU - body CPU: what gdnav adds per step beyond the member's own step (target <= 5 us); CPU
#                 times, so that other processes' use of the cores does not count (wall times: columns 2-3 and
#                 the log line, which a loaded machine inflates)
#   null CPU      cb CPU of a class whose step does nothing (same ports; its run's other members fly on a zero
#                 attitude, which does not matter for this column): the hand-over alone, measured directly
# Prints medians.   tools/bench/python_inprocess_cost.sh [BUILD_DIR=build] [STEPS=10000] [REPS=5]
set -euo pipefail
B=$(realpath "${1:-build}"); N=${2:-10000}; P=${3:-5}
SRC=$(cd "$(dirname "$0")/../.." && pwd)
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
cat > "$T/null_member.py" <<PY
class Idle:
    def __init__(self, m):
        self.att = m.output("gdnav/AttitudeEstimate")
    def step(self, k, t_s):
        pass
PY
SETNULL="run.members={nav_att: {python: {file: $T/null_member.py, class: Idle}}}"
SET="run.members={nav_att: {python: {file: $SRC/tools/bench/timed_member.py, class: Timed}}}"
one() {  # $1 = base|py; prints the run's wall time from step 0 [s]
    if [ "$1" = base ]; then "$B/bin/gdnav" run --scenario paper2 --seed 1 --layout direct --steps "$N" --out "$T/$1" > "$T/$1.log" 2>&1
    elif [ "$1" = null ]; then "$B/bin/gdnav" run --scenario paper2 --seed 1 --layout direct --steps "$N" --out "$T/$1" --set "$SETNULL" > "$T/$1.log" 2>&1
    else "$B/bin/gdnav" run --scenario paper2 --seed 1 --layout direct --steps "$N" --out "$T/$1" --set "$SET" > "$T/$1.log" 2>&1; fi
    awk '/^wall_s:/ {print $2}' "$T/$1/clock_summary.yaml"
}
echo "python_inprocess_cost: scenario #2, direct layout, $N steps, $P pairs (us per step)"
printf "%-5s %9s %9s %9s %9s %9s %9s %9s\n" pair base py extra "body CPU" "cb CPU" handover "null CPU"
for i in $(seq 1 "$P"); do
    wb=$(one base); wp=$(one py); one null > /dev/null
    nul=$(grep -o 'in process), [0-9]* steps: CPU mean [0-9.]*' "$T/null.log" | awk '{print $NF}')
    body=$(grep -o 'body [0-9.]*' "$T/py.log" | awk '{print $2}')
    cbc=$(grep -o 'in process), [0-9]* steps: CPU mean [0-9.]*' "$T/py.log" | awk '{print $NF}')
    ub=$(echo "1000000 * $wb / $N" | bc -l); up=$(echo "1000000 * $wp / $N" | bc -l)
    printf "%-5s %9.2f %9.2f %9.2f %9.2f %9.2f %9.2f %9.2f\n" "$i" "$ub" "$up" "$(echo "$up - $ub" | bc -l)" "$body" \
        "$cbc" "$(echo "$cbc - $body" | bc -l)" "$nul"
    echo "$ub $up $(echo "$up - $ub" | bc -l) $body $cbc $(echo "$cbc - $body" | bc -l) $nul" >> "$T/rows"
done
median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }
printf "%-5s" median
for c in 1 2 3 4 5 6 7; do printf " %9.2f" "$(awk -v c=$c '{print $c}' "$T/rows" | median)"; done
echo
