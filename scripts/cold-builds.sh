#!/usr/bin/env bash
# The cold builds README quotes, in one run: the headless application (`--no-default-features`)
# and the full one (the window with the embedded viewer), each in an empty target directory, and,
# when the `python` folder and maturin are there, the Python wheel. Prints wall and CPU (user +
# system) seconds for each, as `/usr/bin/time -f` measures them.
#
#   scripts/cold-builds.sh [DIR]     # DIR: where the empty target directories go (/var/tmp)
#
# CPU seconds are the figure to compare: wall seconds depend on what else runs on the machine.
# On a shared machine, run it at the lowest priority so that it takes only idle CPU:
#   nice -n 19 scripts/cold-builds.sh & echo 19 > /proc/$!/autogroup
# The crates are downloaded first (`cargo fetch`) so that the network is not timed.
set -euo pipefail
cd "$(dirname "$0")/.."
base="${1:-/var/tmp}/tether-cold-builds"
rm -rf "$base"
mkdir -p "$base"
cargo fetch --locked >/dev/null

status=0
# measure NAME COMMAND...: runs COMMAND in the empty target directory $base/NAME.
measure() {
    local name=$1
    shift
    mkdir -p "$base/$name"
    echo "== $name: $* ($(date -u +%T) UTC)" >&2
    CARGO_TARGET_DIR="$base/$name" /usr/bin/time -o "$base/$name.time" -f "%e %U %S" "$@" >"$base/$name.log" 2>&1 || {
        echo "$name: the build failed, see $base/$name.log" >&2
        status=1
        return 0
    }
    read -r wall user system <"$base/$name.time"
    awk -v n="$name" -v w="$wall" -v u="$user" -v s="$system" \
        'BEGIN { printf "%-9s cold build: %6.0f s wall, %6.0f s CPU (user %.0f + system %.0f)\n", n, w, u + s, u, s }'
}

measure headless cargo build --release --locked --no-default-features
measure full cargo build --release --locked
if [ -f python/pyproject.toml ] && command -v maturin >/dev/null; then
    measure wheel maturin build --release --manifest-path python/Cargo.toml --out "$base/wheel-out"
fi
rm -rf "$base"/headless "$base"/full "$base"/wheel
exit $status
