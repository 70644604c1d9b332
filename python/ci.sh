#!/usr/bin/env bash
# Builds and tests the Python package: a fresh venv, `pip install ./python`
# (maturin compiles the extension), the test dependencies, then pytest and
# the example notebook. The tests compare against the command-line binary,
# built first. Both reuse what `cargo test --release` compiled (one target
# folder, one profile, one feature set: tools/feature_sets.sh), so after the
# tests only pyo3, numpy and the extension itself are compiled (~30 s, not
# the whole library again). Usage: bash python/ci.sh [VENV]   (default: target/pyvenv)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(dirname "$here")"
venv="${1:-$repo/target/pyvenv}"
cd "$repo"
cargo build --release --bin vbi
python3 -m venv "$venv"
"$venv/bin/pip" install --quiet --upgrade pip
"$venv/bin/pip" install --quiet pytest pandas numpy matplotlib nbclient nbformat ipykernel
"$venv/bin/pip" install --quiet "$here"
export VBI_BIN="$repo/target/release/vbi"
# From the repository's root, not python/: `python -m` puts the working
# folder on sys.path, and python/vbi (the sources, without the compiled
# extension) would shadow the installed package.
cd "$repo"
# pytest also executes examples/quickstart.ipynb (tests/test_notebook.py).
"$venv/bin/python" -m pytest -q -p no:cacheprovider python/tests
