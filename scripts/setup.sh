#!/usr/bin/env bash
# Installs what npm cannot: the Rust wasm32 target and lint components, the wasm-bindgen CLI pinned
# to the crate's wasm-bindgen version, and (with --browser) Debian's Chromium for the browser tests.
# Every step is guarded by a version check, so a warm machine skips it in well under a second.
set -euo pipefail
cd "$(dirname "$0")/.."

WASM_BINDGEN_VERSION=0.2.106   # must equal the `wasm-bindgen = "=..."` pin in crate/Cargo.toml

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

if [ "${1:-}" = "--browser" ]; then
  if [ ! -x /usr/bin/chromium ]; then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
      echo "setup: installing Debian's chromium for the browser tests"
      apt-get update -qq
      DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium >/dev/null
    else
      echo "setup: the browser tests need Chromium at /usr/bin/chromium. Run:"
      echo "  sudo apt-get update && sudo apt-get install -y chromium"
      exit 1
    fi
  fi
fi
