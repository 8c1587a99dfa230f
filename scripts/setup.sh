#!/usr/bin/env bash
# Bootstraps this repo on a fresh Debian machine (run as root) and does nothing, quietly, once it has.
#
#   - Debian packages: installs only the missing ones (dpkg says which); `apt-get update` only then.
#   - .venv at the repo root: made if absent (or if its interpreter no longer runs).
#   - `pip install -e '.[test,dask]'` (the test tools, and the optional Dask extra so that its executor is
#     tested for real): only when pyproject.toml (or the install mode below) changed since the last install; a
#     hash of them is kept in .venv/.physink-pyproject.sha256 after each successful install. The editable
#     install is a plain path in a .pth file (setuptools' `editable_mode=compat`), not setuptools' import hook,
#     whose start-up (pathlib, urllib.parse, ipaddress: ~25 ms of CPU on this machine) every `physink` command
#     paid and a pip-installed physink does not (docs/BENCHMARKS.md, `physink decode`).
#
# Works from any directory. Set PHYSINK_PYTHON to use another interpreter than python3 (>= 3.11).
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
ROOT=$PWD
VENV=$ROOT/.venv
STAMP=$VENV/.physink-pyproject.sha256
PY=${PHYSINK_PYTHON:-python3}

# Shared libraries the edges load at run time: the devices (hidapi, pyusb), the renderer (skia-python needs
# libGL/libEGL/libX11 even offscreen), the one font every picture is drawn with (DejaVu Sans), PortAudio for the
# microphone (sounddevice; without it everything but listening on a microphone works), tmux, in which a test runs
# `physink demo` in a real terminal (tests/test_tui_tmux.py), and the speech synthesisers whose voices the speech tests
# hear (tests/test_speech_voices.py, scripts/make_speech_corpus.py): espeak-ng, flite, festival with its English
# festvox voices (SVOX Pico comes from the test extra, py-nanotts); and Graphviz, whose `dot` draws the causal
# timeline as a picture (`physink export PROJECT --timeline graph.svg|graph.png`).
DEBIAN_LIBS=(libusb-1.0-0 libhidapi-hidraw0 libgl1 libegl1 libx11-6 fonts-dejavu-core libportaudio2 tmux
             espeak-ng flite festival festvox-kallpc16k festvox-kdlpc16k festvox-us-slt-hts graphviz)

log() { printf 'setup: %s\n' "$*" >&2; }
die() { log "$*"; exit 1; }

as_root() {
    if [ "$(id -u)" -eq 0 ]; then
        "$@"
    elif command -v sudo >/dev/null 2>&1; then
        sudo "$@"
    else
        die "need root to run: $*"
    fi
}

is_installed() { dpkg -s "$1" 2>/dev/null | grep -q '^Status: install ok installed'; }

# apt_install PKG... : installs those of PKG that are not installed yet.
apt_install() {
    command -v dpkg >/dev/null 2>&1 || { log "not a Debian system; make sure these are installed: $*"; return 0; }
    local missing=() pkg
    for pkg in "$@"; do
        is_installed "$pkg" || missing+=("$pkg")
    done
    [ "${#missing[@]}" -eq 0 ] && return 0
    log "installing Debian packages: ${missing[*]}"
    as_root env DEBIAN_FRONTEND=noninteractive apt-get update -qq
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

apt_install "${DEBIAN_LIBS[@]}"

# --- the virtual environment ---------------------------------------------------------------------------
if ! { [ -x "$VENV/bin/python" ] && "$VENV/bin/python" -c '' 2>/dev/null; }; then
    if ! command -v "$PY" >/dev/null 2>&1 && [ "$PY" = python3 ]; then
        apt_install python3 python3-venv   # a minimal Debian image may come without Python
    fi
    command -v "$PY" >/dev/null 2>&1 || die "no $PY on PATH (Python >= 3.11 is needed)"
    "$PY" -c 'import sys; sys.exit(sys.version_info < (3, 11))' \
        || die "$PY is $("$PY" -V 2>&1); Python >= 3.11 is needed (set PHYSINK_PYTHON)"
    # Debian's own python3 can only make a venv with pip once python3-venv is installed.
    if ! "$PY" -c 'import ensurepip, venv' 2>/dev/null; then
        apt_install python3-venv
    fi
    log "creating $VENV"
    rm -rf "$VENV"
    if ! "$PY" -m venv "$VENV"; then
        rm -rf "$VENV"
        die "could not create $VENV with $PY -m venv"
    fi
fi

# --- the project, editable, with the test tools and the Dask extra -------------------------------------
EDITABLE_MODE=compat
want=$( (cat "$ROOT/pyproject.toml"; echo "editable_mode=$EDITABLE_MODE") | sha256sum | cut -d' ' -f1)
have=$(cat "$STAMP" 2>/dev/null || true)
if [ "$want" != "$have" ]; then
    log "installing physink-tui (editable, with test tools and the dask extra) into .venv"
    rm -f "$STAMP"
    PIP_NO_INPUT=1 PIP_DISABLE_PIP_VERSION_CHECK=1 \
        "$VENV/bin/python" -m pip install --quiet --editable "$ROOT[test,dask]" \
        --config-settings editable_mode=$EDITABLE_MODE
    printf '%s\n' "$want" >"$STAMP"
fi
