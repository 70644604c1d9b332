#!/usr/bin/env bash
# Fails when the release binary, the test build and the Python extension
# resolve a shared dependency with different features (issue 41.8): cargo
# would then compile it, and everything above it (vbi included), once per
# set. The fix is an entry in the union block of Cargo.toml's
# [dependencies] (or [build-dependencies] for proc-macro crates).
#   tools/feature_sets.sh        # prints "one feature set" or the crates that differ
set -euo pipefail
cd "$(dirname "$0")/.."
sets=$(mktemp -d)
trap 'rm -rf "$sets"' EXIT
tree() { cargo tree --locked "$@" --prefix none -f '{p} [{f}]' | sed 's/ (\*)$//' | sort -u; }
tree -p vbi -e no-dev >"$sets/binary"
tree -p vbi >"$sets/tests"
tree -p vbi-python -e no-dev >"$sets/python"
python3 - "$sets" <<'PY'
import re, sys
def load(path):
    crates = {}
    for line in open(path):
        m = re.match(r"(\S+) (v\S+)[^\[]*\[(.*)\]$", line.strip())
        if m:
            crates.setdefault((m[1], m[2]), set()).update(f for f in m[3].split(",") if f)
    return crates
sets = {name: load(f"{sys.argv[1]}/{name}") for name in ("binary", "tests", "python")}
split = []
for crate in sorted(sets["binary"]):
    seen = {name: s[crate] for name, s in sets.items() if crate in s}
    if len({frozenset(v) for v in seen.values()}) > 1:
        split.append(f"  {crate[0]} {crate[1]}: " + "; ".join(
            f"{name} [{','.join(sorted(v))}]" for name, v in seen.items()))
if split:
    print("dependencies resolved with different features (each set compiles them again):")
    print("\n".join(split))
    print("help: add the union of their features to the block in Cargo.toml's [dependencies]")
    sys.exit(1)
print("one feature set for the binary, the tests and the Python extension")
PY
