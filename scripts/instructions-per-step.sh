#!/usr/bin/env bash
# Instructions one world step costs, counted by callgrind (repeatable to the instruction whatever
# else the machine runs, unlike the step bench's seconds): the difference between 2000 and 1000
# steps after 3000 settling steps, divided by 1000. Needs valgrind.
#   scripts/instructions-per-step.sh [SCENE…]   (default: the two bench chains)
# For an A/B, run it in a checkout of each commit.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet -p tether-physics --example steps
binary="${CARGO_TARGET_DIR:-target}/release/examples/steps"
count() { valgrind --tool=callgrind --callgrind-out-file=/dev/null "$binary" "$1" 3000 "$2" 2>&1 | awk '/Collected/ {print $4}'; }
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(scenes/bench/chain100.ron scenes/bench/chain100_air.ron)
for scene in "${scenes[@]}"; do
    short=$(count "$scene" 1000)
    long=$(count "$scene" 2000)
    echo "$scene: $(( (long - short) / 1000 )) instructions per step"
done
