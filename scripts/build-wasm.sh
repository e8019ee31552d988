#!/usr/bin/env bash
# Builds the core to WebAssembly and generates the JS glue into crate/pkg (git-ignored).
#   scripts/build-wasm.sh        release build, optimised with wasm-opt from npm's binaryen
#   scripts/build-wasm.sh --dev  release build without wasm-opt (faster, for `npm start`)
# Never use Debian's binaryen: its wasm-opt 108 breaks wasm-bindgen output (see docs/TOOLCHAIN notes).
set -euo pipefail
cd "$(dirname "$0")/.."
[ -f "$HOME/.cargo/env" ] && . "$HOME/.cargo/env"

cargo build --quiet --manifest-path crate/Cargo.toml --lib --release --target wasm32-unknown-unknown
wasm-bindgen --target web --out-dir crate/pkg crate/target/wasm32-unknown-unknown/release/meristem.wasm
if [ "${1:-}" != "--dev" ]; then
  node_modules/.bin/wasm-opt -Oz --enable-reference-types --enable-bulk-memory --enable-nontrapping-float-to-int \
    --enable-sign-ext --enable-mutable-globals --enable-multivalue \
    crate/pkg/meristem_bg.wasm -o crate/pkg/meristem_bg.wasm
fi
