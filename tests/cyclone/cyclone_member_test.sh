#!/bin/sh
# CTest Cyclone.MemberJoinsFastDdsRunBitIdentical (issue item 7, docs/protocol.md "Interoperability with Cyclone DDS"):
# the test chain with its controller replaced by gdnav-cyclone-member (C, Eclipse Cyclone DDS) must complete, the
# clock must count the member, and the recorded digests must equal an all-built-in distributed run's.
# usage: cyclone_member_test.sh GDNAV_TESTCHAIN GDNAV_CYCLONE_MEMBER CHAIN_YAML WORKDIR
set -u
chain=$1 member=$2 scenario=$3 work=$4
# A DDS domain of its own: the launcher's automatic domains are 20-219; other external-member tests use 150-232.
domain=$((221 + $$ % 3))
rm -rf "$work"
mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

echo "== reference: all built-in, distributed layout (domain $domain)"
timeout 240 "$chain" run --scenario "$scenario" --layout distributed --domain "$domain" --out "$work/ref" \
  > "$work/ref.log" 2>&1
code=$?
[ $code -eq 0 ] || { cat "$work/ref.log"; fail "reference run exited $code"; }

echo "== chain_controller as a Cyclone DDS member in C (domain $domain)"
timeout 240 "$chain" run --scenario "$scenario" --layout distributed --external chain_controller \
  --domain "$domain" --join-timeout 60 --out "$work/out" > "$work/run.log" 2>&1 &
run_pid=$!
timeout 240 "$member" --domain "$domain" > "$work/member.log" 2>&1 &
member_pid=$!
wait $run_pid; run_code=$?
wait $member_pid; member_code=$?
echo "--- gdnav-testchain (exit $run_code):"; cat "$work/run.log"
echo "--- gdnav-cyclone-member (exit $member_code):"; cat "$work/member.log"

[ $run_code -eq 0 ] || fail "gdnav-testchain exited $run_code"
[ $member_code -eq 0 ] || fail "gdnav-cyclone-member exited $member_code"
grep -q "external member 'chain_controller' joined" "$work/run.log" || fail "the clock never logged the Cyclone member joining"

# record/digest.yaml: "complete: true", then one line per topic: "  TOPIC: {samples: N, last_step: K, digest: "HEX"}".
topics() {
  [ -f "$1/record/digest.yaml" ] || fail "no $1/record/digest.yaml"
  grep -qx 'complete: true' "$1/record/digest.yaml" || fail "$1/record/digest.yaml: recording not complete"
  grep '^  [^ ].*digest:' "$1/record/digest.yaml"
}
topics "$work/ref" > "$work/ref.digests"
topics "$work/out" > "$work/out.digests"
echo "--- recorded topics, all built-in:"; cat "$work/ref.digests"
echo "--- recorded topics, chain_controller in C on Cyclone DDS:"; cat "$work/out.digests"
[ "$(grep -c 'samples: 2000,' "$work/ref.digests")" -eq 4 ] || fail "expected 4 topics of 2000 samples in the reference"
cmp -s "$work/ref.digests" "$work/out.digests" || fail "recorded digests differ from the all-built-in run"
echo "PASS: Cyclone DDS member counted by the clock; digests bit-identical to the built-in controller"
