#!/usr/bin/env bash
# A screenshot of the window as a user sees it (README's and docs' images): `tether gui SCENE` on
# a virtual X server of the given size, Space pressed once (play), the whole screen saved after
# SECONDS of play. The window renders with Vulkan on the CPU there (the driver scripts/run installs).
#   scripts/screenshot.sh SCENE OUT.png [SECONDS] [WIDTHxHEIGHT]
#   scripts/screenshot.sh scenes/moored_buoy.ron screenshots/gui_moored_buoy.png 20 1600x1000
# KEYS="..." (xdotool key names) are pressed after play starts; MOUSE="X Y" puts the pointer
# there before the capture (a hover's tooltip; default the top left corner, where it shows
# none); BINARY picks another build.
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 2 ] || { sed -n 2,7p "$0" >&2; exit 2; }
scene=$1 out=$2 seconds=${3:-20} size=${4:-1600x1000}
command -v import >/dev/null || { echo "needs ImageMagick's import: apt-get install imagemagick" >&2; exit 1; }
binary=${BINARY:-}
if [ -z "$binary" ]; then
    cargo build --release --quiet -p tether
    binary="${CARGO_TARGET_DIR:-target}/release/tether"
fi
home=$(mktemp -d)
exec 3< <(Xvfb -displayfd 1 -screen 0 "${size}x24" -nolisten tcp -noreset 2>/dev/null & echo "pid $!")
read -r _ xvfb <&3
read -r display <&3
export DISPLAY=":$display"
HOME="$home" XDG_CONFIG_HOME="$home" XDG_DATA_HOME="$home" "$binary" gui "$scene" 2>"$home/stderr" &
gui=$!
trap 'kill "$gui" 2>/dev/null; wait "$gui" 2>/dev/null; kill "$xvfb"; rm -rf "$home"' EXIT
for _ in $(seq 600); do
    window=$(xdotool search --onlyvisible --name '^Tether$' 2>/dev/null | head -1) && break
    sleep 0.2
done
[ -n "${window:-}" ] || { echo "no Tether window after 120 s:" >&2; cat "$home/stderr" >&2; exit 1; }
# The window fills the screen, draws its first frames and loads the scene before it takes keys.
xdotool windowsize --sync "$window" "${size%x*}" "${size#*x}" windowmove "$window" 0 0
sleep 5
xdotool windowfocus --sync "$window" key space
for key in ${KEYS:-}; do xdotool key "$key"; sleep 0.5; done
sleep "$seconds"
# shellcheck disable=SC2086 # two coordinates
xdotool mousemove ${MOUSE:-0 0}
sleep 1
import -window root "$out"
echo "$out: $scene after $seconds s of play at $size"
