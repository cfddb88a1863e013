# What README's two commands need on a fresh Debian 12 / Ubuntu 24.04 with rustup, installed only
# when missing. Sourced by scripts/run and scripts/test; every function is idempotent and quiet
# when there is nothing to do.

# apt-get as root, or through sudo for a user.
as_root() {
    if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi
}

# Installs the Debian packages named that are not installed yet (one apt-get for all of them).
ensure_packages() {
    local missing=()
    for package in "$@"; do
        dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "ok installed" || missing+=("$package")
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    echo "installing ${missing[*]}" >&2
    # Through env: sudo does not pass the caller's environment on.
    as_root env DEBIAN_FRONTEND=noninteractive apt-get update -qq
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# The build: a C toolchain for rustc's linker and -sys crates; libudev-dev and pkg-config for the
# embedded Rerun viewer's gamepad support.
ensure_build_packages() {
    ensure_packages gcc libc6-dev pkg-config libudev-dev
}

# The tests: mesa-vulkan-drivers (lavapipe) and libgl1-mesa-dri render the GUI on the CPU;
# libxkbcommon-x11-0, xvfb and xdotool run the whole window as a user would under a virtual X
# server; zenity is the file dialog without a desktop portal; python3-venv holds the `rerun` CLI;
# munge and slurm-wlm give the sweep's test a real one-node Slurm (their services are not started
# by the packages in a container: that test starts and stops its own daemons).
ensure_test_packages() {
    ensure_packages mesa-vulkan-drivers libgl1-mesa-dri libxkbcommon-x11-0 xvfb xdotool zenity python3-venv \
        munge slurm-wlm
}

# The window on a machine without a GPU (no /dev/dri render node: a VM, a remote desktop, Xvfb)
# renders with Mesa's lavapipe, whose Debian 12 release (22.3.6) leaks about 14 MB a second while
# the viewer plays (docs/window.md, "Memory"); bookworm-backports' Mesa 25 does not. On Debian 12
# without a GPU, adds bookworm-backports to apt's sources and installs its lavapipe (and the
# libdrm it needs); elsewhere, or with Mesa 25 already, does nothing.
ensure_cpu_vulkan_driver() {
    compgen -G "/dev/dri/renderD*" >/dev/null && return 0
    grep -q '^VERSION_CODENAME=bookworm$' /etc/os-release 2>/dev/null || return 0
    local installed
    installed=$(dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null || true)
    [ -n "$installed" ] && dpkg --compare-versions "$installed" ge 25 && return 0
    echo "installing Mesa's lavapipe from bookworm-backports (Debian 12's leaks while the viewer plays)" >&2
    if ! grep -rqs "bookworm-backports" /etc/apt/sources.list /etc/apt/sources.list.d/; then
        printf '%s\n' "Types: deb" "URIs: http://deb.debian.org/debian" "Suites: bookworm-backports" \
            "Components: main" "Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg" \
            | as_root tee /etc/apt/sources.list.d/bookworm-backports.sources >/dev/null
    fi
    as_root env DEBIAN_FRONTEND=noninteractive apt-get update -qq
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
        -t bookworm-backports mesa-vulkan-drivers
}

# The `rerun` CLI of the Rust crate's version (Python package rerun-sdk), in a virtual environment
# (Debian 12 and Ubuntu 24.04 refuse a system-wide pip install), put first on PATH.
RERUN_VERSION=0.36.3
ensure_rerun_cli() {
    local venv="${TETHER_VENV:-${XDG_CACHE_HOME:-$HOME/.cache}/tether/rerun-venv}"
    if ! "$venv/bin/rerun" --version 2>/dev/null | grep -q "${RERUN_VERSION//./\\.}"; then
        echo "installing rerun-sdk==$RERUN_VERSION into $venv" >&2
        python3 -m venv "$venv"
        "$venv/bin/pip" install --quiet "rerun-sdk==$RERUN_VERSION"
    fi
    export PATH="$venv/bin:$PATH"
    rerun analytics disable >/dev/null 2>&1 || true
}

# The Python module's build and test tools (maturin, pytest, numpy, pyarrow for the sweep's table,
# pandas), in their own virtual environment ($TETHER_PY_VENV, default beside the rerun one).
ensure_python_venv() {
    export TETHER_PY_VENV="${TETHER_PY_VENV:-${TETHER_VENV:-${XDG_CACHE_HOME:-$HOME/.cache}/tether/rerun-venv}-python}"
    if ! "$TETHER_PY_VENV/bin/python" -c "import maturin, pytest, numpy, pyarrow, pandas" 2>/dev/null; then
        echo "installing maturin, pytest, numpy, pyarrow, pandas into $TETHER_PY_VENV" >&2
        python3 -m venv "$TETHER_PY_VENV"
        "$TETHER_PY_VENV/bin/pip" install --quiet "maturin>=1.5,<2" pytest numpy pyarrow pandas
    fi
}
