#!/usr/bin/env bash
# The window's resident memory while it plays a scene (docs/window.md, "Memory"): `tether gui
# SCENE` on a virtual X server (Xvfb; the viewer renders with Vulkan on the CPU there, as on a VM
# or a remote desktop without a GPU), Space pressed once, the process's resident set size (VmRSS)
# printed at each of the marks, in seconds of play, with the CPU time the window has taken since
# play started. Run it under `nice`: the window rendering on the CPU takes a core.
#   scripts/memory-while-playing.sh [BINARY]   (default: this checkout's release build)
#   MARKS="60 300 600" SCENE=scenes/moored_buoy.ron GUI_ARGS="--max-fps 60" scripts/memory-while-playing.sh
# Any other variable set (VK_ICD_FILENAMES for another Vulkan driver…) reaches the window as it is.
set -euo pipefail
cd "$(dirname "$0")/.."
binary=${1:-}
if [ -z "$binary" ]; then
    cargo build --release --quiet -p tether
    binary="${CARGO_TARGET_DIR:-target}/release/tether"
fi
scene=${SCENE:-scenes/moored_buoy.ron}
marks=${MARKS:-60 300 600}
home=$(mktemp -d)
exec 3< <(Xvfb -displayfd 1 -screen 0 1600x1000x24 -nolisten tcp -noreset 2>/dev/null & echo "pid $!")
read -r _ xvfb <&3
read -r display <&3
export DISPLAY=":$display"
HOME="$home" XDG_CONFIG_HOME="$home" XDG_DATA_HOME="$home" "$binary" gui "$scene" ${GUI_ARGS:-} 2>"$home/stderr" &
gui=$!
trap 'kill "$gui" 2>/dev/null; wait "$gui" 2>/dev/null; kill "$xvfb"; rm -rf "$home"' EXIT
rss_mb() { awk '/^VmRSS/ {printf "%.0f", $2 / 1024}' "/proc/$gui/status"; }
# User and system CPU time of the window so far [s] (fields 14 and 15 of /proc/PID/stat, in ticks).
cpu_s() { awk -v hz="$(getconf CLK_TCK)" '{printf "%.1f", ($14 + $15) / hz}' "/proc/$gui/stat"; }
for _ in $(seq 600); do
    window=$(xdotool search --onlyvisible --name '^Tether$' 2>/dev/null | head -1) && break
    sleep 0.2
done
[ -n "${window:-}" ] || { echo "no Tether window after 120 s:" >&2; cat "$home/stderr" >&2; exit 1; }
# The window draws its first frames and loads the scene before it takes keys.
sleep 5
xdotool windowfocus --sync "$window"
echo "$scene with $binary: ${marks// /, } s of play"
echo "before play: $(rss_mb) MB"
xdotool key space
start=$(date +%s)
cpu_at_play=$(cpu_s)
for mark in $marks; do
    sleep $((start + mark - $(date +%s)))
    echo "after $mark s: $(rss_mb) MB resident, $(awk -v a="$(cpu_s)" -v b="$cpu_at_play" 'BEGIN {printf "%.1f", a - b}') s of CPU"
done
# What the viewer said about its memory (a limit reached, data dropped).
grep -i "memory" "$home/stderr" | sed 's/\x1b\[[0-9;]*m//g' || true
