#!/usr/bin/env bash
# Real-time factors of `moored_buoy` with its three chains dynamic (N = 40, MoorDyn's chain of
# docs/dynamic-lines.md), 120 s recorded at 60 frames per second, in the five cases of issue 34:
# the scene's regular wave and a 50-component JONSWAP sea (Hs 2.5 m, Tp 9 s), each under the
# scene's RK4 at 50 ms and the leapfrog at 10 ms, and the JONSWAP sea with the chains
# quasi-static under RK4. From `tether record --timing`: simulated time over the simulation
# thread's CPU (physics and the recorder's calls: the wall time of an idle 2-core machine, where
# Rerun's writer has the other core), over the whole process's CPU, and over the wall time; the
# median of RUNS runs (default 3) per binary, the binaries' runs interleaved so that an A/B in one
# call sees the same machine.
#   scripts/line-speed.sh [BINARY…]   (default: this checkout's headless release build)
#   RUNS=5 scripts/line-speed.sh /tmp/tether-before "$CARGO_TARGET_DIR/release/tether"
set -euo pipefail
cd "$(dirname "$0")/.."
binaries=("$@")
if [ ${#binaries[@]} -eq 0 ]; then
    cargo build --release --quiet -p tether --no-default-features
    binaries=("${CARGO_TARGET_DIR:-target}/release/tether")
fi
runs=${RUNS:-3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
dynamic='model: Dynamic(segments: 40, damping: Ratio(0.8), drag_normal: 2.4, drag_tangential: 1.15, added_mass_normal: 1.0, added_mass_tangential: 0.5),'
jonswap='waves: Jonswap(hs: 2.5, tp: 9.0, gamma: 3.3, heading_deg: 0.0, components: 50, seed: 1)'
sed "s/model: QuasiStatic,/$dynamic/" scenes/moored_buoy.ron >"$out/regular.ron"
sed "s/waves: Regular([^)]*)/$jonswap/" "$out/regular.ron" >"$out/jonswap.ron"
sed "s/waves: Regular([^)]*)/$jonswap/" scenes/moored_buoy.ron >"$out/jonswap_quasi_static.ron"
grep -q Dynamic "$out/jonswap.ron" && grep -q Jonswap "$out/jonswap.ron" && ! grep -q Dynamic "$out/jonswap_quasi_static.ron"
leapfrog=(--integrator leapfrog --dt 0.01)
cases=("regular RK4 50 ms|regular.ron" "regular leapfrog 10 ms|regular.ron|${leapfrog[*]}"
    "JONSWAP RK4 50 ms|jonswap.ron" "JONSWAP leapfrog 10 ms|jonswap.ron|${leapfrog[*]}"
    "JONSWAP quasi-static RK4 50 ms|jonswap_quasi_static.ron")
median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
# The file holding a binary's runs of the current case.
runs_of() { echo "$out/$(echo "$1" | md5sum | cut -c1-8).runs"; }
printf '%-32s' case
for binary in "${binaries[@]}"; do printf ' | %34s' "$(basename "$(dirname "$binary")")/$(basename "$binary")"; done
printf '\n%-32s' ''
for _ in "${binaries[@]}"; do printf ' | %34s' '× (sim thread)  × (CPU)  × (wall)'; done
echo
for case in "${cases[@]}"; do
    IFS='|' read -r name scene flags <<<"$case"
    for binary in "${binaries[@]}"; do : >"$(runs_of "$binary")"; done
    for _ in $(seq "$runs"); do
        for binary in "${binaries[@]}"; do
            # shellcheck disable=SC2086 # the flags are words
            "$binary" record "$out/$scene" -o "$out/run.rrd" --duration 120 --log-hz 60 $flags --timing 2>&1 \
                | awk '/^timing:/ {simulated = $2; wall = $6}
                       /^  CPU/ {cpu = $2; physics = $5; line = $0; sub(/.*: /, "", line); sub(/ s on the simulation thread.*/, "", line); recorder = line}
                       END {print simulated / (physics + recorder), simulated / cpu, simulated / wall}' \
                >>"$(runs_of "$binary")"
        done
    done
    printf '%-32s' "$name"
    for binary in "${binaries[@]}"; do
        file=$(runs_of "$binary")
        printf ' | %14.1f %8.1f %9.1f' "$(cut -d' ' -f1 "$file" | median)" "$(cut -d' ' -f2 "$file" | median)" "$(cut -d' ' -f3 "$file" | median)"
    done
    echo
done
