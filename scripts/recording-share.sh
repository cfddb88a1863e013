#!/usr/bin/env bash
# The recording's share of a `tether record` run's CPU time, the run's CPU and wall time and the
# file's size, for every shipped scene at its default 60 frames per second over 20 s, from
# `tether record --timing`: the median of RUNS runs (default 5) per binary, the binaries' runs
# interleaved so that an A/B in one call sees the same machine.
#   scripts/recording-share.sh [BINARY…]   (default: this checkout's release build)
#   RUNS=9 scripts/recording-share.sh /tmp/tether-before target/release/tether
set -euo pipefail
cd "$(dirname "$0")/.."
binaries=("$@")
if [ ${#binaries[@]} -eq 0 ]; then
    cargo build --release --quiet -p tether
    binaries=("${CARGO_TARGET_DIR:-target}/release/tether")
fi
runs=${RUNS:-5}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
# The file holding a binary's runs of the current scene.
runs_of() { echo "$out/$(echo "$1" | md5sum | cut -c1-8)"; }
printf '%-34s' scene
for binary in "${binaries[@]}"; do printf ' %36s' "$(basename "$(dirname "$binary")")/$(basename "$binary")"; done
printf '\n%-34s' ''
for _ in "${binaries[@]}"; do printf ' %36s' 'recording %  CPU ms  wall ms  file MB'; done
echo
for scene in scenes/*.ron scenes/bench/*.ron; do
    for binary in "${binaries[@]}"; do : >"$(runs_of "$binary")"; done
    for _ in $(seq "$runs"); do
        for binary in "${binaries[@]}"; do
            "$binary" record "$scene" -o "$out/run.rrd" --duration 20 --timing 2>&1 \
                | awk '/^timing:/ {wall = $6} /^  CPU/ {cpu = $2; share = $0; sub(/.*recording [0-9.]+ s \(/, "", share); sub(/%.*/, "", share)} /^file:/ {mb = $2}
                       END {print share, 1000 * cpu, 1000 * wall, mb}' \
                >>"$(runs_of "$binary")"
        done
    done
    printf '%-34s' "$scene"
    for binary in "${binaries[@]}"; do
        file=$(runs_of "$binary")
        printf ' %11s %7.1f %8.1f %8.2f' "$(cut -d' ' -f1 "$file" | median)" "$(cut -d' ' -f2 "$file" | median)" "$(cut -d' ' -f3 "$file" | median)" "$(cut -d' ' -f4 "$file" | median)"
    done
    echo
done
