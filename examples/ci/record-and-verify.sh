#!/usr/bin/env bash
# A CI job for a repository of Tether scenes, to copy: builds the headless `tether` (no window,
# no embedded viewer: the Rerun SDK alone), then for each scene checks it, records it and
# verifies the recording. It fails — exit code not 0 — when a scene does not load (`tether
# check`), when its run breaks the energy balance (`tether record` exits 1 when the health check
# finds the balance drifting past its budget, PHYSICS.md §5: a divergence), or when the recording
# does not verify (`rerun rrd verify`).
#
#   examples/ci/record-and-verify.sh [SCENE.ron ...]     # default: scenes/*.ron
#
# Environment:
#   CARGO_TARGET_DIR  the build cache, outside the clone so that it outlives it (CI keeps it
#                     between runs; default /var/tmp/tether-target)
#   TETHER_VENV       the virtual environment of the `rerun` CLI (default /var/tmp/tether-venv;
#                     made here with rerun-sdk of the recorder's version when it has none)
#   DURATION          simulated seconds recorded per scene (default 2: enough to catch a blow-up)
#   OUT               where the recordings go (default a temporary directory, removed after)
set -euo pipefail
cd "$(dirname "$0")/../.."
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-/var/tmp/tether-target}"
export TETHER_VENV="${TETHER_VENV:-/var/tmp/tether-venv}"
duration="${DURATION:-2}"

# The `rerun` CLI (pip's rerun-sdk, the version the recorder writes).
source scripts/setup.sh
ensure_rerun_cli

echo "== building the headless tether in $CARGO_TARGET_DIR" >&2
cargo build --release --locked --no-default-features --bin tether
tether="$CARGO_TARGET_DIR/release/tether"

out="${OUT:-$(mktemp -d)}"
[ -n "${OUT:-}" ] || trap 'rm -rf "$out"' EXIT
mkdir -p "$out"
if [ $# -eq 0 ]; then set -- scenes/*.ron; fi

failed=0
for scene in "$@"; do
    name=$(basename "$scene" .ron)
    rrd="$out/$name.rrd"
    if ! "$tether" check "$scene" >"$out/$name.check.txt" 2>&1; then
        echo "FAIL $scene: tether check: $(tail -n 1 "$out/$name.check.txt")" >&2
        failed=$((failed + 1))
        continue
    fi
    if ! "$tether" record "$scene" -o "$rrd" --duration "$duration" --log-hz 30 2>"$out/$name.record.txt"; then
        echo "FAIL $scene: tether record: $(grep -m1 '^error' "$out/$name.record.txt" || tail -n 1 "$out/$name.record.txt")" >&2
        failed=$((failed + 1))
        continue
    fi
    if ! rerun rrd verify "$rrd" >"$out/$name.verify.txt" 2>&1; then
        echo "FAIL $scene: rerun rrd verify: $(tail -n 1 "$out/$name.verify.txt")" >&2
        failed=$((failed + 1))
        continue
    fi
    echo "ok   $scene ($duration s recorded, $(du -h "$rrd" | cut -f1), verified)" >&2
done
passed=$(($# - failed))
echo "scenes: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
