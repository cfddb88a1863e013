#!/usr/bin/env bash
# What potential flow costs (issue 33): `moored_buoy` as shipped (Froude–Krylov pressure, Morison
# drag and added mass) against the same scene with its `potential` line uncommented (Capytaine's
# coefficients, state-space radiation), in the scene's regular sea under its RK4 at 50 ms, 120 s
# recorded at 60 frames per second. From `tether record --timing`: the real-time factor
# (simulated time over the process's CPU time and over the wall time) and the physics' CPU per
# simulated second; the median of RUNS runs (default 5), the two scenes' runs interleaved so that
# they see the same machine.
#   scripts/potential-flow-speed.sh [BINARY]   (default: this checkout's headless release build)
set -euo pipefail
cd "$(dirname "$0")/.."
binary=${1:-}
if [ -z "$binary" ]; then
    cargo build --release --quiet -p tether --no-default-features
    binary="${CARGO_TARGET_DIR:-target}/release/tether"
fi
runs=${RUNS:-5}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cp scenes/moored_buoy.ron "$out/morison.ron"
sed 's|// potential: Wamit(file: "meshes/buoy")|potential: Wamit(file: "meshes/buoy")|' scenes/moored_buoy.ron >"$out/potential.ron"
grep -q '^ *potential: Wamit' "$out/potential.ron" && ! grep -q '^ *potential: Wamit' "$out/morison.ron"
# The copies read their meshes beside them.
ln -s "$PWD/scenes/meshes" "$out/meshes"
median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
for _ in $(seq "$runs"); do
    for model in morison potential; do
        "$binary" record "$out/$model.ron" -o "$out/run.rrd" --duration 120 --log-hz 60 --timing 2>&1 \
            | awk '/^timing:/ {simulated = $2; wall = $6}
                   /^  CPU/ {cpu = $2; physics = $5}
                   END {print simulated / cpu, simulated / wall, physics / simulated * 1e3}' >>"$out/$model.runs"
    done
done
printf '%-10s %16s %17s %26s\n' model '× real time (CPU)' '× real time (wall)' 'physics CPU per simulated s'
for model in morison potential; do
    printf '%-10s %16.1f %17.1f %23.2f ms\n' "$model" "$(cut -d' ' -f1 "$out/$model.runs" | median)" \
        "$(cut -d' ' -f2 "$out/$model.runs" | median)" "$(cut -d' ' -f3 "$out/$model.runs" | median)"
done
ratio() { paste -d' ' "$out/potential.runs" "$out/morison.runs" | awk -v c="$1" '{print $(c + 3) / $c}' | median; }
echo "potential flow over Morison, process CPU per simulated second (median of the paired runs): $(ratio 1)"
