#!/usr/bin/env bash
# Builds and tests the Python package: a fresh venv, `pip install ./python`
# (maturin compiles the extension), the test dependencies, then pytest and
# the example notebook. The tests compare against the command-line binary,
# built first. Both reuse what `cargo test --release` compiled (one target
# folder, one profile, one feature set: tools/feature_sets.sh), so after the
# tests only pyo3, numpy and the extension itself are compiled (~30 s, not
# the whole library again).
#   bash python/ci.sh [VENV]             # default VENV: target/pyvenv
#   bash python/ci.sh --prepare [VENV]   # only the venv and the test
#                                        # dependencies (no compiling: .ci/run
#                                        # fetches them while the tests compile)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(dirname "$here")"
prepare_only=
if [ "${1:-}" = --prepare ]; then
  prepare_only=1
  shift
fi
venv="${1:-$repo/target/pyvenv}"
cd "$repo"
# A venv made by --prepare is kept (its packages are not fetched again).
[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
"$venv/bin/pip" install --quiet --upgrade pip
"$venv/bin/pip" install --quiet pytest pandas numpy matplotlib nbclient nbformat ipykernel
[ -n "$prepare_only" ] && exit 0
cargo build --release --bin vbi
"$venv/bin/pip" install --quiet "$here"
export VBI_BIN="$repo/target/release/vbi"
# From the repository's root, not python/: `python -m` puts the working
# folder on sys.path, and python/vbi (the sources, without the compiled
# extension) would shadow the installed package.
cd "$repo"
# pytest also executes examples/quickstart.ipynb (tests/test_notebook.py).
"$venv/bin/python" -m pytest -q -p no:cacheprovider python/tests
