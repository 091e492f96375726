#!/bin/bash
# What a Python member costs the rest of a run (docs/python.md, "Cost"): scenario #2, distributed, nav_att external,
# PAIRS interleaved pairs of runs — the C++ example attitude filter, then the Python one — and per pair the wall time
# per step of each and the Python step callback's own wall cost. Prints medians. Needs a build with the examples
# (ctest -R ExamplesPackage) and the Python bindings.
#   tools/bench/python_member_cost.sh [BUILD_DIR=build] [STEPS=10000] [PAIRS=5]
set -euo pipefail
B=$(realpath "${1:-build}"); N=${2:-10000}; P=${3:-5}
SRC=$(cd "$(dirname "$0")/../.." && pwd)
CPP=$B/examples-build/bin/gdnav-example-attitude
[ -x "$CPP" ] || { echo "python_member_cost: $CPP missing: run ctest -R ExamplesPackage first" >&2; exit 2; }
[ -d "$B/python" ] || { echo "python_member_cost: $B/python missing (Python bindings not built)" >&2; exit 2; }
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
one() {  # one run with nav_att external: $1 = cpp|py, $2 = domain; prints "wall_s callback_wall_us"
    "$B/bin/gdnav" run --scenario paper2 --seed 1 --layout distributed --external nav_att --domain "$2" --steps "$N" \
        --out "$T/$1" > "$T/$1.run.log" 2>&1 &
    local L=$!
    if [ "$1" = cpp ]; then "$CPP" --domain "$2" > "$T/$1.member.log" 2>&1
    else PYTHONPATH=$B/python /usr/bin/python3 "$SRC/examples/python/complementary_attitude.py" --domain "$2" \
        > "$T/$1.member.log" 2>&1; fi
    wait $L
    local cb; cb=$( (grep -o 'wall mean [0-9.]*' "$T/$1.member.log" || true) | tail -1 | awk '{print $3}')
    # wall time from step 0 to the end (the clock's), not the start-up
    echo "$(awk '/^wall_s:/ {print $2}' "$T/$1/clock_summary.yaml") ${cb:-0}"
}
printf "%-5s %12s %12s %14s %16s\n" pair "C++ us/step" "Py us/step" "slow-down us" "Py callback us"
D=$(( 150 + $$ % 50 ))
for i in $(seq 1 "$P"); do
    read -r wc _ < <(one cpp "$D")
    read -r wp cb < <(one py "$D")
    uc=$(echo "1000000 * $wc / $N" | bc -l); up=$(echo "1000000 * $wp / $N" | bc -l)
    printf "%-5s %12.1f %12.1f %14.1f %16.1f\n" "$i" "$uc" "$up" "$(echo "$up - $uc" | bc -l)" "$cb"
    echo "$uc $up $cb" >> "$T/rows"
done
/usr/bin/python3 - "$T/rows" <<'PY'
import statistics as s, sys
rows = [list(map(float, l.split())) for l in open(sys.argv[1])]
d = s.median(r[1] - r[0] for r in rows); cb = s.median(r[2] for r in rows)
print(f"median slow-down {d:.1f} us/step; median Python callback {cb:.1f} us/step; "
      f"{'within' if d <= cb else 'ABOVE'} the callback's own cost")
PY
