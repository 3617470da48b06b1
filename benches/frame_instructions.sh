#!/usr/bin/env bash
# Instructions a 160×48 explorer frame with every law checked (benches/frame.rs), counted by
# callgrind: the run drawing HERTZ_FRAMES=100 frames less the run drawing none, over 100. The count
# does not depend on the machine's load. Needs valgrind; about a minute after the build.
#
#   bash benches/frame_instructions.sh                 # this checkout
#   bash benches/frame_instructions.sh --old DIR       # another checkout (a git worktree) first
#
# An older checkout without benches/frame.rs gets this one's, and its [[bench]] entry.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
count() {
  local dir=$1 label=$2
  if [[ ! -f $dir/benches/frame.rs ]]; then
    cp "$here/benches/frame.rs" "$dir/benches/frame.rs"
    printf '\n[[bench]]\nname = "frame"\nharness = false\n' >>"$dir/Cargo.toml"
  fi
  local bin
  bin=$(cargo bench --manifest-path "$dir/Cargo.toml" --bench frame --no-run --message-format=json 2>/dev/null |
    python3 -c 'import json, sys
for line in sys.stdin:
    m = json.loads(line)
    if m.get("reason") == "compiler-artifact" and m["target"]["name"] == "frame" and m.get("executable"):
        print(m["executable"])')
  ir() {
    HERTZ_FRAMES=$1 valgrind --tool=callgrind --callgrind-out-file=/dev/null "$bin" 2>&1 |
      awk '/Collected/ { gsub(",", "", $4); print $4 }'
  }
  local none hundred
  none=$(ir 0)
  hundred=$(ir 100)
  echo "$label: $(((hundred - none) / 100)) instructions a frame"
}
if [[ ${1:-} == --old ]]; then
  count "$(cd "$2" && pwd)" "$2"
fi
count "$here" "this checkout"
