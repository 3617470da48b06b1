#!/usr/bin/env bash
# The CPU time of a cold test build (`cargo test --no-run` in an empty target folder), as the
# project configures it and as it was before the build-time crates were compiled unoptimised
# (every dependency at opt-level 2), one after the other in one run, with the load average.
#
#     bash benches/cold_build.sh        # two cold builds: about 15 min of CPU, 8+ min of wall
#
# Cargo.toml names each crate that only runs at build time (proc macros, their parsers, the build
# scripts' helpers) at opt-level 0; "before" sets each of them back to 2 with `--config`. CPU time
# (user + system) is what to compare: the wall time follows the machine's load.
set -euo pipefail
cd "$(dirname "$0")/.."

# The crates Cargo.toml compiles unoptimised in test builds.
mapfile -t unoptimised < <(sed -n 's/^\[profile\.dev\.package\.\([A-Za-z0-9_-]*\)\]$/\1/p' Cargo.toml)
before=()
for crate in "${unoptimised[@]}"; do
    before+=(--config "profile.dev.package.$crate.opt-level=2")
done

build() { # name, extra cargo args...
    local name=$1
    shift
    local dir
    dir=$(mktemp -d)
    local load
    load=$(cut -d' ' -f1-3 /proc/loadavg)
    /usr/bin/time -f "%U %S %e" -o "$dir/time" \
        cargo test --locked --no-run --quiet "$@" --target-dir "$dir/target" >/dev/null 2>"$dir/log" ||
        { cat "$dir/log"; exit 1; }
    read -r user sys wall <"$dir/time"
    awk -v n="$name" -v u="$user" -v s="$sys" -v w="$wall" -v a="$load" -v b="$(cut -d' ' -f1-3 /proc/loadavg)" \
        'BEGIN { printf "%-38s %6.1f s CPU (%6.1f user + %5.1f sys)  %6.1f s wall  load %s -> %s\n", n, u + s, u, s, w, a, b }'
    rm -rf "$dir"
}

echo "cold cargo test --no-run, ${#unoptimised[@]} build-time crates, $(nproc) cores"
build "as configured (build-time crates O0)"
build "before (every dependency O2)" "${before[@]}"
