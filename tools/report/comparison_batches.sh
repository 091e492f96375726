#!/bin/bash
# The comparison batches of docs/results.md: the paper's six variants, every sensor grade, the +-300 / +-1000
# bias-drift bands, the filters beyond the paper and the truth-free start, for one scenario, each flying the same missions (same seed).
#
# usage: tools/report/comparison_batches.sh SCENARIO RUNS OUT_DIR [JOBS] [GDNAV]
#   SCENARIO  1 or 2; RUNS runs per configuration; OUT_DIR gets one batch directory per configuration
#   (OUT_DIR/sS_NAME); JOBS parallel runs (default 2); GDNAV the binary (default build/bin/gdnav).
# Batches are resumable: run it again with a larger RUNS and only the missing runs fly.
# Then: /usr/bin/python3 tools/report/results_tables.py OUT_DIR > docs/results/comparison.md
# (one configuration against the baseline, with Wilcoxon p-values: gdnav compare OUT_DIR/sS_base OUT_DIR/sS_NAME)
set -euo pipefail
[ $# -ge 3 ] || { sed -n 2,10p "$0"; exit 2; }
S=$1 RUNS=$2 OUT=$3 JOBS=${4:-2} G=${5:-build/bin/gdnav}
case "$S" in 1|2) ;; *) echo "comparison_batches.sh: SCENARIO must be 1 or 2, not '$S'" >&2; exit 2;; esac
mkdir -p "$OUT"
# Which code flew the batches: tables name this commit (results_tables.py reads OUT/provenance_sS.yaml).
commit=$(git rev-parse HEAD 2>/dev/null || echo unknown)
dirty=$([ -z "$(git status --porcelain --untracked-files=no 2>/dev/null)" ] && echo false || echo true)
printf 'commit: %s\ndirty_tree: %s\nbinary: %s\nruns: %s\nstarted: %s\ncommand: %s\n' "$commit" "$dirty" "$G" \
    "$RUNS" "$(date -u +%FT%TZ)" "tools/report/comparison_batches.sh $S $RUNS $OUT" > "$OUT/provenance_s$S.yaml"
run() {
    local name=$1; shift
    local dir="$OUT/s${S}_$name"
    echo "== s${S}_$name ($RUNS runs) $(date +%T)"
    if ! "$G" montecarlo --scenario "$S" --runs "$RUNS" --jobs "$JOBS" --layout direct --seed 1 --no-figures \
            --out "$dir" "$@" > "$dir.log" 2>&1; then
        echo "   FAILED, see $dir.log" >&2; tail -3 "$dir.log" >&2; return 1
    fi
    tail -1 "$dir.log"
}
run base
for v in att_zero_fb_derivatives att_zero_fn_derivatives hor_double_integration hor_wind_integration \
         ver_integration ver_airspeed_integration att_error_state eskf_mean_wind; do
    run "var_$v" --variant "$v"
done
for b in 300 1000; do run "band_$b" --set components.sensors_inertial.bias_drift_band=$b; done
for g in gyroscopes=better gyroscopes=worse gyroscopes=worst accelerometers=better accelerometers=worse \
         accelerometers=worst magnetometers=better magnetometers=worse air_data=better air_data=worse \
         atmospheric=worse atmospheric=worst; do
    run "grade_${g%%=*}_${g##*=}" --grade "$g"
done
# Truth-free start (issue 14 item 1): the paper's filter and the error-state filter started from the measurements.
TF=(--set components.nav_att.init_mode=measurements --set components.nav_pos.init_mode=measurements)
run tf_paper "${TF[@]}"
run tf_error_state --variant att_error_state "${TF[@]}"
echo "== done $(date +%T)"
