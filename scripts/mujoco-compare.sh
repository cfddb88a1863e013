#!/usr/bin/env bash
# Tether against MuJoCo on the bench chains (issue 34): steps per CPU second of the whole headless
# `tether record` process and of a loop of MuJoCo's `mj_step` on the same chain
# (scenes/bench/chain100*.xml beside the .ron files), ROUNDS rounds (default 5) interleaved,
# medians and their ratio; then where each chain is after its 10 s, from both. Installs the
# `mujoco` Python package (4.0.0) into a virtual environment when missing
# ($TETHER_MUJOCO_VENV, default ~/.cache/tether/mujoco-venv). Run it on an idle machine (quote
# the load average). Several binaries are run in turn in each round, for an A/B in one call.
#   scripts/mujoco-compare.sh [BINARY…]   (default: this checkout's headless release build)
#   ROUNDS=3 SCENES=chain100 scripts/mujoco-compare.sh /tmp/tether-before "$CARGO_TARGET_DIR/release/tether"
#   DURATION=60 scripts/mujoco-compare.sh   (each run's simulated time [s]; default the scene's 10 s)
set -euo pipefail
cd "$(dirname "$0")/.."
MUJOCO_VERSION=4.0.0
venv="${TETHER_MUJOCO_VENV:-${XDG_CACHE_HOME:-$HOME/.cache}/tether/mujoco-venv}"
if ! "$venv/bin/python" -c "import mujoco; assert mujoco.__version__ == '$MUJOCO_VERSION'" 2>/dev/null; then
    echo "installing mujoco==$MUJOCO_VERSION into $venv" >&2
    python3 -m venv "$venv"
    "$venv/bin/pip" install --quiet "mujoco==$MUJOCO_VERSION"
fi
target="${CARGO_TARGET_DIR:-target}/release"
binaries=("$@")
if [ ${#binaries[@]} -eq 0 ]; then
    cargo build --release --quiet -p tether --no-default-features
    binaries=("$target/tether")
fi
cargo build --release --quiet -p tether-physics --example steps
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
"$venv/bin/python" scripts/mujoco_compare.py "$target/examples/steps" "${ROUNDS:-5}" "${binaries[@]}"
