#!/bin/bash
# What a Python member costs the rest of a run (docs/python.md, "Cost"): scenario #2 with nav_att external, PAIRS
# interleaved pairs of runs — the C++ example attitude filter, then the Python one — and per pair the wall time per
# step of each, the Python step callback's own wall cost, and the CPU per step the Python member process used beyond
# the C++ member process (/usr/bin/time). Prints medians. Needs a build with the examples (ctest -R ExamplesPackage)
# and the Python bindings.
#   tools/bench/python_member_cost.sh [BUILD_DIR=build] [STEPS=10000] [PAIRS=5] [LAYOUT=composed]
set -euo pipefail
B=$(realpath "${1:-build}"); N=${2:-10000}; P=${3:-5}; LAYOUT=${4:-composed}
SRC=$(cd "$(dirname "$0")/../.." && pwd)
CPP=$B/examples-build/bin/gdnav-example-attitude
[ -x "$CPP" ] || { echo "python_member_cost: $CPP missing: run ctest -R ExamplesPackage first" >&2; exit 2; }
[ -d "$B/python" ] || { echo "python_member_cost: $B/python missing (Python bindings not built)" >&2; exit 2; }
[ -x /usr/bin/time ] || { echo "python_member_cost: /usr/bin/time missing (apt-get install time)" >&2; exit 2; }
case "$LAYOUT" in composed|distributed) ;; *) echo "python_member_cost: LAYOUT must be composed or distributed" >&2; exit 2;; esac
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
one() {  # one run with nav_att external: $1 = cpp|py, $2 = domain; prints "wall_s callback_wall_us member_cpu_s"
    "$B/bin/gdnav" run --scenario paper2 --seed 1 --layout "$LAYOUT" --external nav_att --domain "$2" --steps "$N" \
        --out "$T/$1" > "$T/$1.run.log" 2>&1 &
    local L=$!
    if [ "$1" = cpp ]; then /usr/bin/time -f "%U %S" -o "$T/$1.time" "$CPP" --domain "$2" > "$T/$1.member.log" 2>&1
    else PYTHONPATH=$B/python /usr/bin/time -f "%U %S" -o "$T/$1.time" /usr/bin/python3 \
        "$SRC/examples/python/complementary_attitude.py" --domain "$2" > "$T/$1.member.log" 2>&1; fi
    wait $L
    local cb; cb=$( (grep -o 'wall mean [0-9.]*' "$T/$1.member.log" || true) | tail -1 | awk '{print $3}')
    # wall time from step 0 to the end (the clock's), not the start-up
    echo "$(awk '/^wall_s:/ {print $2}' "$T/$1/clock_summary.yaml") ${cb:-0} $(awk '{print $1 + $2}' "$T/$1.time")"
}
echo "python_member_cost: scenario #2, $LAYOUT layout, $N steps, $P pairs"
printf "%-5s %12s %12s %14s %16s %18s\n" pair "C++ us/step" "Py us/step" "slow-down us" "Py callback us" "Py extra CPU us"
D=$(( 150 + $$ % 50 ))
for i in $(seq 1 "$P"); do
    read -r wc _ cc < <(one cpp "$D")
    read -r wp cb cp < <(one py "$D")
    uc=$(echo "1000000 * $wc / $N" | bc -l); up=$(echo "1000000 * $wp / $N" | bc -l)
    xc=$(echo "1000000 * ($cp - $cc) / $N" | bc -l)
    printf "%-5s %12.1f %12.1f %14.1f %16.1f %18.1f\n" "$i" "$uc" "$up" "$(echo "$up - $uc" | bc -l)" "$cb" "$xc"
    echo "$uc $up $cb $xc" >> "$T/rows"
done
/usr/bin/python3 - "$T/rows" <<'PY'
import statistics as s, sys
rows = [list(map(float, l.split())) for l in open(sys.argv[1])]
d = s.median(r[1] - r[0] for r in rows); cb = s.median(r[2] for r in rows); x = s.median(r[3] for r in rows)
print(f"median slow-down {d:.1f} us/step; median Python callback {cb:.1f} us/step "
      f"({'within' if d <= cb else 'ABOVE'} the callback's own cost); median extra CPU of the Python process "
      f"{x:.1f} us/step (start-up included)")
# Single pairs vary by +-150 us/step on a 2-core machine (scheduling of ~14 processes): the excess of the slow-down
# over the callback's cost, pair by pair, with its standard error, says whether any excess is real.
e = [r[1] - r[0] - r[2] for r in rows]
se = s.stdev(e) / len(e) ** 0.5 if len(e) > 1 else float("nan")
print(f"slow-down minus callback cost: mean {s.mean(e):+.1f} us/step, standard error {se:.1f} ({len(e)} pairs)")
PY
