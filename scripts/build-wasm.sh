#!/usr/bin/env bash
# Builds the core to WebAssembly with wasm-pack (installed by scripts/setup.sh), twice, into two npm
# packages (git-ignored), each with its package.json, JS glue and TypeScript types:
#   crate/pkg-core  meristem_core: without the importers and exporters (`--no-default-features`,
#                   see the `io` feature in crate/Cargo.toml): what the page and the build workers
#                   load for the first plant
#   crate/pkg       meristem: the whole boundary, for the export worker and for importing files
#   scripts/build-wasm.sh        release builds, optimised with wasm-opt from npm's binaryen
#   scripts/build-wasm.sh --dev  release builds without wasm-opt (faster, for `npm start`)
# wasm-pack runs the pinned wasm-bindgen CLI it finds on PATH and wasm-opt from node_modules/.bin
# (first on PATH here): never Debian's binaryen, whose wasm-opt 108 breaks wasm-bindgen output.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -f "$HOME/.cargo/env" ] && . "$HOME/.cargo/env"
export PATH="$PWD/node_modules/.bin:$PATH"

opt=()
[ "${1:-}" = "--dev" ] && opt=(--no-opt)
# crate/pkg-core, what the browser downloads for the first plant (issue 22, the first load), is
# built for size a little over speed: opt-level "s", then wasm-opt -Oz (the flags in
# crate/Cargo.toml). Measured 2026-11-25 (docs/notes/performance-history.md, "The first load"): "s" makes it about 6% smaller
# gzipped than "3" and derives 5-25% slower; "z" saves 10% but derives 2-4x slower, so no.
# crate/pkg (the export worker, imports, `npm run bench` and ../shared/bench/ratio.sh) loads after
# the first plant, so it is built for speed (issue 20): opt-level 3 with WebAssembly SIMD
# (+simd128, which every current browser runs: the derivation copies successors 16 bytes at a
# time), then wasm-opt -O3; in its own target folder, so the two builds do not rebuild each other.
# Native builds, `cargo test` and the criterion benches keep the release profile's 3.
# (panic = "abort" would change nothing: wasm32-unknown-unknown aborts on a panic already, after
# the panic hook of src/wasm/panic.rs has reported it.)
# pack OUT_DIR NAME [WASM_PACK_ARGS...] [-- CARGO_ARGS...]: one package (package.json, glue,
# types, the .wasm)
pack() {
  local out=$1 name=$2; shift 2
  wasm-pack --quiet --log-level warn build --target web --release --no-gitignore --out-dir "$out" --out-name "$name" "$@"
}
CARGO_PROFILE_RELEASE_OPT_LEVEL=s pack pkg-core meristem_core "${opt[@]}" crate -- --no-default-features
CARGO_PROFILE_RELEASE_OPT_LEVEL=3 RUSTFLAGS="${RUSTFLAGS:-} -C target-feature=+simd128" \
  CARGO_TARGET_DIR="$PWD/crate/target/wasm-speed" pack pkg meristem --no-opt crate
if [ ${#opt[@]} -eq 0 ]; then
  # The same features as Cargo.toml's wasm-opt line, and SIMD, optimised for speed.
  # --one-caller-inline-max-function-size: binaryen inlines every function that has one caller,
  # whatever its size (default -1), which undoes rustc's #[inline(never)] and merged the whole
  # derivation (each path's hot loop, its set-up and its cold error paths) into one function of
  # ~30,000 lines, which V8's TurboFan compiles with its loop values spilled to the stack: C (the
  # parametric tree) ran 1.6x slower than with the cap (measured 2026-11-26, CPU time per
  # derivation 15 -> 9 ms; 50, 200 and 1000 alike). The unexplained fast build of 2026-11-26 01:40
  # (docs/notes/performance-history.md, issue 20) was most likely a tree whose hot loops had two callers.
  # --no-inline also names the Fixed/Choice copy loop (derive/fixed_pass.rs, `ModuleClasses::write_fixed`) as one
  # never to inline (before -O3, while the names are still there), whatever its size: E n = 11 and a
  # classes-path 1.24d ran about 1.1-1.5x slower with it inlined (measured 2026-11-26).
  wasm-opt crate/pkg/meristem_bg.wasm -o crate/pkg/meristem_bg.wasm \
    --no-inline='*classes*Classes*write_fixed*' -O3 --enable-reference-types \
    --enable-bulk-memory --enable-nontrapping-float-to-int --enable-sign-ext \
    --enable-mutable-globals --enable-multivalue --enable-simd \
    --one-caller-inline-max-function-size 200
fi
# The vocabulary, which crate/pkg-core leaves out, as a file for the studio (issue 22).
node scripts/vocabulary-json.mjs
