#!/usr/bin/env bash
# Real-time factors of the design-load storm of docs/design-loads.md: `oc3_hywind_rated` (potential
# flow, Newman drift, NPD wind, the rotor, a 200-component JONSWAP sea of Hs 6 m, Tp 10 s) with
# its lines quasi-static and dynamic (N = 20), 1200 s recorded at 10 frames a second. From
# `tether record --timing`: simulated time over the simulation thread's CPU (physics and the
# recorder's calls), over the whole process's CPU and over the wall time, the median of RUNS runs
# (default 3), and what a 3-hour storm then takes on one core.
#   scripts/storm-speed.sh [BINARY]   (default: this checkout's headless release build)
set -euo pipefail
cd "$(dirname "$0")/.."
binary=${1:-}
if [ -z "$binary" ]; then
    cargo build --release --quiet -p tether --no-default-features
    binary="${CARGO_TARGET_DIR:-target}/release/tether"
fi
runs=${RUNS:-3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
dynamic='displaced_area: 0.0063617, model: Dynamic(segments: 20, damping: Ratio(0.8), drag_normal: 1.6, drag_tangential: 0.1, added_mass_normal: 1.0, added_mass_tangential: 0.0),'
# The copies read the hull and the panel code's files where the scene has them.
sed "s|\"meshes/|\"$PWD/scenes/meshes/|g" scenes/oc3_hywind_rated.ron >"$out/quasi_static.ron"
sed "s|displaced_area: 0.0063617,|$dynamic|" "$out/quasi_static.ron" >"$out/dynamic.ron"
[ "$(grep -c 'model: Dynamic' "$out/dynamic.ron")" -eq 3 ]
median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
printf '%-24s %14s %8s %9s %16s\n' lines '× (sim thread)' '× (CPU)' '× (wall)' '3 h on one core'
for scene in quasi_static dynamic; do
    : >"$out/$scene.runs"
    for _ in $(seq "$runs"); do
        "$binary" record "$out/$scene.ron" -o "$out/run.rrd" --duration 1200 --log-hz 10 --timing 2>&1 \
            | awk '/^timing:/ {simulated = $2; wall = $6}
                   /^  CPU/ {cpu = $2; physics = $5; line = $0; sub(/.*: /, "", line); sub(/ s on the simulation thread.*/, "", line); recorder = line}
                   END {print simulated / (physics + recorder), simulated / cpu, simulated / wall}' >>"$out/$scene.runs"
    done
    thread=$(cut -d' ' -f1 "$out/$scene.runs" | median)
    printf '%-24s %14.1f %8.1f %9.1f %14.0f s\n' "$scene" "$thread" "$(cut -d' ' -f2 "$out/$scene.runs" | median)" \
        "$(cut -d' ' -f3 "$out/$scene.runs" | median)" "$(echo "10800 / $thread" | bc -l)"
done
