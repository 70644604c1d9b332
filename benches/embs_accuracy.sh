#!/bin/bash
# EMBS accuracy against `coupled` as ε shrinks (issue 24, points 2 and 5):
# the golden seismic scene (scenarios/embs-viaduct-ave-s103-quake.yaml: the
# AVE-S103 at 300 km/h over the generated two-span viaduct during the
# synthetic lateral record, German low-interference track) with the
# primary suspension's stiffness and damping scaled by s, so ε ∝ √s in
# both directions. Prints, per s, ε per direction and for every recorded
# quantity the EMBS error (max |EMBS − coupled| / coupled peak) and the
# a-posteriori first-order ratio η of summary.json `embs.orders`.
#
# Usage: benches/embs_accuracy.sh [WORKDIR=/tmp/vbi-embs-accuracy] [s ...]
set -eu
work=${1:-/tmp/vbi-embs-accuracy}
shift || true
scales=${*:-1 0.1 0.01 0.001 0.0001}
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
cargo build --release --locked --bin vbi
mkdir -p "$work"
for s in $scales; do
    scene="scenarios/embs-accuracy-s$s.yaml"
    python3 - "$s" > "$scene" <<'PY'
import sys
s = float(sys.argv[1])
text = open("scenarios/embs-viaduct-ave-s103-quake.yaml").read()
k = [12.5e6, 120e6, 1.2e6]
c = [9e3, 27.9e3, 10e3]
names = ["longitudinal", "lateral", "vertical"]
over = ", ".join(
    [f"primary_{n}_stiffness: {s * v:.6e}" for n, v in zip(names, k)]
    + [f"primary_{n}_damping: {s * v:.6e}" for n, v in zip(names, c)]
)
text = text.replace("parameters: {contact_half_spacing: 0.88}",
                    "parameters: {contact_half_spacing: 0.88, " + over + "}")
text = text.replace("name: embs-viaduct-ave-s103-quake", f"name: embs-accuracy-s{s}")
print(text)
PY
    ./target/release/vbi run "$scene" --out "$work/s$s" -q 2>/dev/null || true
    rm -f "$scene"
    python3 - "$work/s$s/summary.json" "$s" <<'PY'
import json, sys
e = json.load(open(sys.argv[1]))["embs"]
eps = ", ".join(f"{x['direction']} {x['epsilon']:.3g}" for x in e["scales"])
print(f"s = {sys.argv[2]}: ε {eps}")
eta = {o["name"]: o["first_order_ratio"] for o in e.get("orders", [])}
for q in e["comparison"]["quantities"]:
    print(f"  {q['name']:26s} error {q['error']:.3e}  η {eta.get(q['name'], float('nan')):.3e}")
PY
done
