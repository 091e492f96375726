#!/usr/bin/env bash
# Regenerates the topic graph picture of docs/architecture.md from the code: `gdnav list --graph dot` of SCENARIO
# into docs/architecture/topics_SCENARIO.dot, rendered by Graphviz into topics_SCENARIO.svg, which carries the DOT
# text's SHA-256 so that the test Architecture.TopicGraph can tell a picture drawn from an older graph.
#   tools/dev/topic_graph.sh [GDNAV] [SCENARIO]     GDNAV defaults to build/bin/gdnav, SCENARIO to default
# With --check (first argument) it only compares and exits 1 naming what differs.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
check=0
if [ "${1:-}" = --check ]; then check=1; shift; fi
gdnav=${1:-$root/build/bin/gdnav}
scenario=${2:-default}
dot_file="$root/docs/architecture/topics_$scenario.dot"
svg_file="$root/docs/architecture/topics_$scenario.svg"
text=$("$gdnav" list --graph dot --scenario "$scenario")
sum=$(printf '%s\n' "$text" | sha256sum | cut -d' ' -f1)
if [ $check = 1 ]; then
  [ -f "$dot_file" ] || { echo "topic_graph: $dot_file is missing (run tools/dev/topic_graph.sh)" >&2; exit 1; }
  if [ "$(cat "$dot_file")" != "$text" ]; then
    echo "topic_graph: $dot_file differs from what gdnav list --graph dot --scenario $scenario prints now" \
         "(run tools/dev/topic_graph.sh and commit both files)" >&2
    diff <(printf '%s\n' "$text") "$dot_file" >&2 || true
    exit 1
  fi
  grep -q "topics dot sha256 $sum" "$svg_file" || {
    echo "topic_graph: $svg_file was not drawn from the current $dot_file (run tools/dev/topic_graph.sh)" >&2; exit 1; }
  echo "topic graph of $scenario: picture and text match the code"
  exit 0
fi
command -v dot > /dev/null || { echo "topic_graph: needs Graphviz's dot (apt-get install graphviz)" >&2; exit 1; }
mkdir -p "$(dirname "$dot_file")"
printf '%s\n' "$text" > "$dot_file"
printf '%s\n' "$text" | dot -Tsvg | sed "2i <!-- topics dot sha256 $sum -->" > "$svg_file"
echo "wrote $dot_file and $svg_file"
