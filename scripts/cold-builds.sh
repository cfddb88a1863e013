#!/usr/bin/env bash
# The cold builds README quotes, in one run: the headless application (`--no-default-features`)
# and the full one (the window with the embedded viewer), each in an empty target directory, and,
# when the `python` folder and maturin are there, the Python wheel. Prints wall and CPU (user +
# system) seconds for each, as `/usr/bin/time -f` measures them.
#
#   scripts/cold-builds.sh [DIR [BUILD...]]   # DIR: where the empty target directories go
#                                             # (/var/tmp); BUILD: headless, full, wheel (all)
#
# Measure on an idle machine: wall seconds depend on what else runs, and on a virtual machine
# whose cores are shared so do CPU seconds (the headless build took 1,727 CPU s beside four other
# builds on 2026-11-25, 967 s alone at e20d843 on 2026-11-27). The crates are downloaded first (`cargo fetch`) so that the
# network is not timed.
set -euo pipefail
cd "$(dirname "$0")/.."
# The full build's system package (libudev-dev, for the viewer's gamepad input), as scripts/run.
source scripts/setup.sh
ensure_build_packages
base="${1:-/var/tmp}/tether-cold-builds"
shift || true
builds="${*:-headless full wheel}"
mkdir -p "$base"
cargo fetch --locked >/dev/null

status=0
# measure NAME COMMAND...: runs COMMAND in the empty target directory $base/NAME.
measure() {
    local name=$1
    shift
    rm -rf "${base:?}/$name"
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

for build in $builds; do
    case $build in
    headless) measure headless cargo build --release --locked --no-default-features ;;
    full) measure full cargo build --release --locked ;;
    wheel)
        if command -v maturin >/dev/null; then
            measure wheel maturin build --release --manifest-path python/Cargo.toml --out "$base/wheel-out"
        else
            echo "wheel: skipped, maturin is not on PATH (pip install maturin)" >&2
        fi
        ;;
    *)
        echo "no such build: $build (headless, full, wheel)" >&2
        exit 2
        ;;
    esac
done
rm -rf "$base"/headless "$base"/full "$base"/wheel
exit $status
