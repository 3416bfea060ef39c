#!/usr/bin/env bash
# Set up and run every test: the Rust crate (no Python needed) and the
# Python package (built by maturin through pip). Used by .ci/run.
set -euo pipefail
cd "$(dirname "$0")/.."

echo "== cargo test (core, no Python)"
cargo test --locked 2>&1 | tail -n +1

echo "== build + install the Python package with test extras"
python3 -m pip install --quiet --upgrade pip >/dev/null 2>&1 || true
python3 -m pip install --quiet ".[test]"

echo "== pytest (two worker processes: the suite is mostly single-threaded Python)"
python3 -m pytest -q -n 2 --durations=25 tests
