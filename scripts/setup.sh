#!/usr/bin/env bash
# Installs what npm cannot: the Rust wasm32 target and lint components, the wasm-bindgen CLI pinned
# to the crate's wasm-bindgen version (with its wasm-bindgen-test-runner), wasm-pack, with --browser Debian's Chromium for the browser tests, and
# with --consumers the programs the export tests feed the exported files to (POV-Ray, tovrmlx3d and
# view3dscene under Xvfb, Open Inventor's ivcat). Every step is guarded by a version or `command -v`
# check, so a warm machine skips it in well under a second. Usage: setup.sh [--browser] [--consumers]
set -euo pipefail
cd "$(dirname "$0")/.."

WASM_BINDGEN_VERSION=0.2.106   # must equal the `wasm-bindgen = "=..."` pin in crate/Cargo.toml
WASM_PACK_VERSION=0.15.1       # builds the core (scripts/build-wasm.sh) and runs its wasm32 tests

if ! command -v cargo >/dev/null 2>&1; then
  [ -f "$HOME/.cargo/env" ] && . "$HOME/.cargo/env"
fi
command -v rustup >/dev/null 2>&1 || { echo "setup: rustup is required (https://rustup.rs)"; exit 1; }

rustup target list --installed | grep -qx wasm32-unknown-unknown \
  || rustup target add wasm32-unknown-unknown
for component in rustfmt clippy; do
  rustup component list --installed | grep -q "^$component" || rustup component add "$component"
done

if ! wasm-bindgen --version 2>/dev/null | grep -qx "wasm-bindgen $WASM_BINDGEN_VERSION"; then
  echo "setup: installing wasm-bindgen-cli $WASM_BINDGEN_VERSION (about 5 minutes on 2 cores, once per machine)"
  cargo install wasm-bindgen-cli --version "$WASM_BINDGEN_VERSION" --locked
fi
# From the crates registry (the npm package `wasm-pack` downloads its binary in postinstall, which
# fails offline). wasm-pack then uses the wasm-bindgen above and npm's wasm-opt: it downloads nothing.
if ! wasm-pack --version 2>/dev/null | grep -qx "wasm-pack $WASM_PACK_VERSION"; then
  echo "setup: installing wasm-pack $WASM_PACK_VERSION (about 4 minutes on 2 cores, once per machine)"
  cargo install wasm-pack --version "$WASM_PACK_VERSION" --locked
fi

browser=false
consumers=false
for flag in "$@"; do
  case "$flag" in
    --browser) browser=true ;;
    --consumers) consumers=true ;;
    *) echo "setup: unknown option $flag (use --browser, --consumers)"; exit 2 ;;
  esac
done

# apt_install WHAT PACKAGE...: installs Debian packages as root, or prints the command and fails.
apt_install() {
  local what=$1; shift
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "setup: installing $* for $what"
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "$@" >/dev/null
  else
    echo "setup: $what need $*. Run:"
    echo "  sudo apt-get update && sudo apt-get install -y $*"
    exit 1
  fi
}

# The CLI runs L-Py and lpfg models with the machine's Python (python/meristem_lsystem/); the
# studio runs the same package on Pyodide and needs nothing here.
if ! python3 -c 'import sys; sys.exit(sys.version_info < (3, 11))' 2>/dev/null; then
  apt_install "the CLI's L-Py and lpfg route (Python 3.11 or newer)" python3
fi

if $browser && [ ! -x /usr/bin/chromium ]; then
  apt_install "the browser tests (Chromium at /usr/bin/chromium)" chromium
fi

if $consumers; then
  # program -> Debian package; the export tests run each of them on the exported files.
  missing=()
  for pair in povray:povray tovrmlx3d:view3dscene view3dscene:view3dscene xvfb-run:xvfb xauth:xauth ivcat:inventor-clients; do
    command -v "${pair%%:*}" >/dev/null 2>&1 || missing+=("${pair#*:}")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    # shellcheck disable=SC2207 # package names have no spaces
    packages=($(printf '%s\n' "${missing[@]}" | sort -u))
    apt_install "the export tests (the real consumers of the files)" "${packages[@]}"
  fi
fi
