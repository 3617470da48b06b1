#!/usr/bin/env bash
# Runs a small map as a Slurm job array on a single-node Slurm started here, merges the shards and
# compares the result byte for byte with the one-process run (docs/maps.md §4).
#   scripts/slurm-map-check.sh [path/to/hertz-tui]
# Exit 0: identical; 1: a failure (its reason on stderr); 77: Slurm is not installed here.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
bin=$(realpath "${1:-$here/../target/debug/hertz-tui}")
for tool in slurmctld slurmd sbatch sinfo; do
    if ! command -v "$tool" >/dev/null 2>&1; then
        echo "skip: $tool is not installed (Debian: apt-get install slurm-wlm)" >&2
        exit 77
    fi
done

dir=$(mktemp -d)
# shellcheck source=slurm-local.sh
set --  # the sourced file reads its own arguments
source "$here/slurm-local.sh"
cleanup() {
    slurm_local_stop "$dir/cluster"
    rm -rf "$dir"
}
trap cleanup EXIT
slurm_local_start "$dir/cluster"

map=(--scene bouncing-ball --x system.gamma --from 0.9 --to 3.5 --points 16
     --y impact.restitution --from 0.3 --to 0.9 --points 9 --transient 200 --recorded 32
     --lyapunov 100)
mkdir -p "$dir/shards"
# --wait: sbatch returns when every task has ended, with the worst exit status.
HERTZ_TUI=$bin MAP_DIR=$dir/shards timeout 300 sbatch --quiet --wait --array=1-3 \
    --output="$dir/task-%a.log" "$here/map-shard.sbatch" "${map[@]}"
"$bin" merge "$dir"/shards/shard-*.csv --out "$dir/merged.csv" > /dev/null
"$bin" map "${map[@]}" > "$dir/whole.csv"
if cmp "$dir/merged.csv" "$dir/whole.csv"; then
    echo "slurm: 3 array tasks merged into the one-process map, byte for byte ($(wc -l < "$dir/whole.csv") lines)"
else
    echo "slurm: the merged map differs from the one-process run" >&2
    exit 1
fi
