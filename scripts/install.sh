#!/usr/bin/env bash
# Installs every tool cablenav needs, idempotently and pinned. Safe to run again: each step
# checks first and does nothing when the right version is already there.
#   scripts/install.sh            tools for the tests (wasm target, wasm-bindgen, wasm-pack, chromium,
#                                 chromium-driver, playwright-core, npm's binaryen (wasm-opt), and a Python virtual environment
#                                 target/venv with maturin, pytest and dask[distributed])
#   scripts/install.sh --serve    also trunk, for `scripts/serve.sh`
#   scripts/install.sh --batotp   only g++ and Eigen (Debian's g++ and libeigen3-dev), to build the peer
#                                 batotp for `scripts/bench.sh --batotp` (examples/bench/batotp.rs)
set -euo pipefail
cd "$(dirname "$0")/.."

WASM_BINDGEN_VERSION=0.2.130   # must match the `wasm-bindgen = "=0.2.130"` pin in web/Cargo.toml
WASM_PACK_VERSION=0.15.1
TRUNK_VERSION=0.21.14          # 0.22 needs a newer rustc than these machines have
PLAYWRIGHT_CORE_VERSION=1.64.1
# wasm-opt for the page (scripts/wasm-opt/package.json): npm's binaryen, because Debian's 108 breaks
# wasm-bindgen's externref table and binaryen's GitHub releases cannot be downloaded here.
BINARYEN_VERSION=132.0.0
# The Python package's build and tests (python/): pinned, installed into target/venv.
PYTHON_TOOLS=(maturin==1.16.0 pytest==9.2.0 "dask[distributed]==2026.8.0")

say() { printf '[install] %s\n' "$*" >&2; }
export PATH="$HOME/.cargo/bin:$PATH"

has_version() { # has_version CMD VERSION: CMD --version mentions VERSION
  command -v "$1" >/dev/null 2>&1 && "$1" --version 2>/dev/null | grep -q "$2"
}

SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
APT_UPDATED=""
apt_install() { # apt_install PACKAGE...: Debian packages, non-interactively
  if [ -z "$APT_UPDATED" ]; then $SUDO apt-get update -qq; APT_UPDATED=1; fi
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "$@" >/dev/null
}
has_deb() { # has_deb PACKAGE: the Debian package is installed
  dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q 'install ok installed'
}

if [ "${1:-}" = "--batotp" ]; then
  # the peer batotp (../shared/peers/batotp, PEER.md) is C++11 with Eigen 3 headers only
  if ! command -v g++ >/dev/null 2>&1; then
    say "installing g++ (Debian package) to build batotp"
    apt_install g++
  fi
  if ! has_deb libeigen3-dev; then
    say "installing libeigen3-dev (Debian package, Eigen's headers) to build batotp"
    apt_install libeigen3-dev
  fi
  say "tools ready"
  exit 0
fi

if ! rustup target list --installed | grep -q '^wasm32-unknown-unknown$'; then
  say "adding rust target wasm32-unknown-unknown"
  rustup target add wasm32-unknown-unknown
fi

if ! has_version wasm-bindgen "$WASM_BINDGEN_VERSION"; then
  say "installing wasm-bindgen-cli $WASM_BINDGEN_VERSION (a few minutes)"
  # no --locked: one locked dependency version is missing from the registry
  cargo install wasm-bindgen-cli --version "$WASM_BINDGEN_VERSION" --force
fi

if [ "${1:-}" = "--serve" ]; then
  # serving needs only the target, wasm-bindgen and trunk
  if ! has_version trunk "$TRUNK_VERSION"; then
    say "installing trunk $TRUNK_VERSION (about 13 minutes on 2 cores, once)"
    cargo install trunk --version "$TRUNK_VERSION" --locked --force
  fi
  say "tools ready"
  exit 0
fi

if ! has_version wasm-pack "$WASM_PACK_VERSION"; then
  say "installing wasm-pack $WASM_PACK_VERSION (a few minutes)"
  cargo install wasm-pack --version "$WASM_PACK_VERSION" --locked --force
fi

if ! command -v chromium >/dev/null 2>&1; then
  say "installing chromium (Debian package) for the browser tests"
  apt_install chromium
fi

if ! command -v chromedriver >/dev/null 2>&1; then
  say "installing chromium-driver (Debian package) for the editor's component tests (wasm-pack test --chrome)"
  apt_install chromium-driver
fi

if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  say "installing node and npm (Debian packages) for the browser tests"
  apt_install nodejs npm
fi

if [ ! -f tests/browser/node_modules/playwright-core/package.json ] || \
   ! grep -q "\"version\": \"$PLAYWRIGHT_CORE_VERSION\"" tests/browser/node_modules/playwright-core/package.json; then
  say "installing playwright-core $PLAYWRIGHT_CORE_VERSION (npm; drives Debian's chromium, downloads no browser)"
  (cd tests/browser && PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm install --no-audit --no-fund --no-package-lock --silent)
fi
if [ ! -f scripts/wasm-opt/node_modules/binaryen/package.json ] || \
   ! grep -q "\"version\": \"$BINARYEN_VERSION\"" scripts/wasm-opt/node_modules/binaryen/package.json; then
  say "installing binaryen $BINARYEN_VERSION (npm): the wasm-opt that scripts/build-page.sh runs"
  (cd scripts/wasm-opt && npm install --no-audit --no-fund --no-package-lock --silent)
fi

VENV=target/venv
if [ ! -x "$VENV/bin/python" ]; then
  say "creating the Python virtual environment $VENV"
  python3 -m venv "$VENV"
fi
if ! "$VENV/bin/python" - "${PYTHON_TOOLS[@]}" <<'PY' 2>/dev/null
import sys
from importlib.metadata import version
for spec in sys.argv[1:]:
    name, wanted = spec.split("==")
    if version(name.split("[")[0]) != wanted:
        sys.exit(1)
import distributed  # the [distributed] extra
PY
then
  say "installing ${PYTHON_TOOLS[*]} into $VENV (pip, PyPI)"
  "$VENV/bin/python" -m pip install --quiet --disable-pip-version-check "${PYTHON_TOOLS[@]}"
fi
say "tools ready"
