#!/usr/bin/env bash
# The one test command (`npm test`): installs the tools npm cannot, then runs every gate and suite
# (lint: cargo fmt, clippy, eslint; cargo test, the Python runtime's unit tests, the boundary tests under wasm32, vitest with the real wasm, the export files read by their real consumers,
# browser tests in headless Chromium) even when an earlier one fails, and ends with one line
# `N passed, N failed` counting them all.
# Artefacts (screenshots, JSON reports) go to test-results/.
set -uo pipefail
cd "$(dirname "$0")/.."
[ -f "$HOME/.cargo/env" ] && . "$HOME/.cargo/env"
export PATH="$PWD/node_modules/.bin:$PATH"

bash scripts/setup.sh --browser --consumers || { echo "setup failed"; echo "0 passed, 1 failed"; exit 1; }

rm -rf test-results && mkdir -p test-results
passed=0
failed=0
gate() { # gate NAME COMMAND...: a lint or build step counted as one test
  local name=$1; shift
  echo "::: $name"
  if "$@"; then passed=$((passed + 1)); else echo "FAILED: $name"; failed=$((failed + 1)); fi
}
count_vitest() { # count_vitest REPORT.json: add a vitest JSON report's totals; no report is a failure
  local counts
  if counts=$(node -e '
      const r = JSON.parse(require("fs").readFileSync(process.argv[1], "utf8"));
      // A suite that failed to load has no failed tests but success=false: count it as one failure.
      const broken = r.success === false && r.numFailedTests === 0 ? 1 : 0;
      console.log(r.numPassedTests, r.numFailedTests + broken);' "$PWD/$1" 2>/dev/null) && [ -n "$counts" ]; then
    read -r p f <<<"$counts"
    passed=$((passed + p)); failed=$((failed + f))
  else
    echo "FAILED: no readable report $1"; failed=$((failed + 1))
  fi
}

gate "cargo fmt --check" cargo fmt --manifest-path crate/Cargo.toml --check
gate "cargo clippy -D warnings" cargo clippy --quiet --manifest-path crate/Cargo.toml --all-targets -- -D warnings
gate "eslint" npm run --silent lint
echo "::: cargo test"
cargo test --manifest-path crate/Cargo.toml 2>&1 | tee test-results/cargo.txt
cargo_status=${PIPESTATUS[0]}
read -r p f < <(grep -E '^test result:' test-results/cargo.txt | sed -E 's/.* ([0-9]+) passed; ([0-9]+) failed.*/\1 \2/' | awk '{p+=$1; f+=$2} END {print p+0, f+0}')
passed=$((passed + p)); failed=$((failed + f))
if [ "$cargo_status" -ne 0 ] && [ "$f" -eq 0 ]; then echo "FAILED: cargo test did not run to the end"; failed=$((failed + 1)); fi

echo "::: python unit tests (python/meristem_lsystem: the L-Py and lpfg runtime)"
python3 -m unittest discover -s python/tests 2>&1 | tee test-results/python.txt
python_status=${PIPESTATUS[0]}
ran=$(sed -nE 's/^Ran ([0-9]+) tests?.*/\1/p' test-results/python.txt | tail -1)
bad=$(sed -nE 's/^FAILED \((.*)\)$/\1/p' test-results/python.txt | grep -oE '(failures|errors)=[0-9]+' | cut -d= -f2 | awk '{s+=$1} END {print s+0}')
if [ -z "$ran" ] || [ "$ran" -eq 0 ]; then echo "FAILED: no python test ran"; failed=$((failed + 1))
else passed=$((passed + ran - bad)); failed=$((failed + bad)); fi
if [ "$python_status" -ne 0 ] && [ "$bad" -eq 0 ]; then echo "FAILED: the python tests did not run to the end"; failed=$((failed + 1)); fi

gate "build wasm" bash scripts/build-wasm.sh
echo "::: wasm32 boundary tests (wasm-pack test --node, the core compiled to WebAssembly with SIMD, as crate/pkg is)"
RUSTFLAGS="${RUSTFLAGS:-} -C target-feature=+simd128" wasm-pack --log-level warn test --node crate --test wasm_boundary 2>&1 | tee test-results/wasm32.txt
wasm32_status=${PIPESTATUS[0]}
read -r p f < <(grep -E '^test result:' test-results/wasm32.txt | sed -E 's/.* ([0-9]+) passed; ([0-9]+) failed.*/\1 \2/' | awk '{p+=$1; f+=$2} END {print p+0, f+0}')
passed=$((passed + p)); failed=$((failed + f))
if [ "$wasm32_status" -ne 0 ] && [ "$f" -eq 0 ]; then echo "FAILED: the wasm32 tests did not run to the end"; failed=$((failed + 1)); fi
if [ "$p" -eq 0 ] && [ "$wasm32_status" -eq 0 ]; then echo "FAILED: no wasm32 test ran"; failed=$((failed + 1)); fi
# tsc needs the generated crate/pkg/meristem.d.ts, so it runs after the wasm build.
gate "tsc --noEmit" tsc --noEmit -p tsconfig.json
echo "::: vitest (unit and cross-boundary, real wasm in node)"
vitest run --reporter=default --reporter=json --outputFile=test-results/vitest.json
count_vitest test-results/vitest.json

echo "::: export tests (every format read back by the real tools)"
vitest run --config tests/export/vitest.config.ts --reporter=default --reporter=json --outputFile=test-results/export.json
count_vitest test-results/export.json

gate "vite build" vite build --logLevel warn
echo "::: browser tests (headless Chromium)"
vitest run --config tests/browser/vitest.config.ts --reporter=default --reporter=json --outputFile=test-results/browser.json
count_vitest test-results/browser.json

echo
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
