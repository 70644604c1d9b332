#!/usr/bin/env bash
# Accuracy of a Monte Carlo study's time step: the rail car over FRA class 5
# at 300 km/h (scenarios/lcp-fig9-rail-car-fra.yaml reduced to that case),
# 200 samples at each setting against a reference with a quarter of the
# automatic step (average-acceleration Newmark, 3.4534e-5 s) and twice its
# modes (34). Prints, per setting, each envelope's largest error over time
# relative to the reference's peak (%), and each wheel's expected largest
# gap against the reference's (%). See BENCHMARKS.md. Needs python3 with numpy.
#
#   benches/monte_carlo_accuracy.sh [SAMPLES]
set -euo pipefail
cd "$(dirname "$0")/.."
samples=${1:-200}
cargo build --release --quiet
vbi=target/release/vbi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
base=$(sed -e '/speeds:/d' -e '/roughness:/d' -e "s/samples: 4/samples: $samples/" \
  scenarios/lcp-fig9-rail-car-fra.yaml)
scene() { # name, solver line, modes line (empty: automatic)
  local text
  text=$(printf '%s\n' "$base" | sed "s/solver: {free_vibration: 0.1}/$2/")
  if [ -n "$3" ]; then
    text=$(printf '%s\n' "$text" | sed "s/  damping: {type: modal, ratio: 0.02}/  damping: {type: modal, ratio: 0.02}\n  modes: {count: $3}/")
  fi
  printf '%s\n' "$text" > "$work/$1.yaml"
  "$vbi" run "$work/$1.yaml" --out "$work/$1" -q
}
fg='newmark: {beta: 0.08333333333333333}'
scene reference 'solver: {free_vibration: 0.1, time_step: 3.4534e-5}' 34
scene automatic 'solver: {free_vibration: 0.1}' ''
runs="automatic"
for dt in 1.727e-4 2.072e-4 2.417e-4 2.763e-4; do
  scene "fox-goodwin-$dt" "solver: {free_vibration: 0.1, time_step: $dt, $fg}" 17
  runs="$runs fox-goodwin-$dt"
done
for dt in 1.381e-4 2.072e-4; do
  scene "average-$dt" "solver: {free_vibration: 0.1, time_step: $dt}" 17
  runs="$runs average-$dt"
done
python3 - "$work" $runs <<'EOF'
import csv, sys
import numpy as np
work, runs = sys.argv[1], sys.argv[2:]
def envelopes(run):
    with open(f"{work}/{run}/envelopes.csv") as f:
        rows = list(csv.reader(f))
    return rows[0][3:], np.array([[float(x) for x in r[3:]] for r in rows[1:]])
def gaps(run):
    with open(f"{work}/{run}/separation.csv") as f:
        return [(float(r["probability"]), float(r["expected_max_gap [m]"]),
                 float(r["expected_max_gap_std_error [m]"])) for r in csv.DictReader(f)]
names, ref = envelopes("reference")
ref_gaps = gaps("reference")
print("reference: expected largest gap per wheel (mm):",
      ", ".join(f"{g*1e3:.4f} ± {e*1e3:.4f}" for _, g, e in ref_gaps),
      "; separation probability", ", ".join(f"{p:g}" for p, _, _ in ref_gaps))
wanted = [n for n in names[1:] if "_mean" in n or "_std" in n]
print("| setting | " + " | ".join(wanted) + " | expected gap, wheels 1–4 | probability |")
print("|---|" + "---:|" * len(wanted) + "---|---|")
for run in runs:
    h, a = envelopes(run)
    cells = []
    for n in wanted:
        j, k = h.index(n), names.index(n)
        y = np.interp(a[:, 0], ref[:, 0], ref[:, k])
        cells.append(f"{100 * np.max(np.abs(a[:, j] - y)) / np.max(np.abs(ref[:, k])):.2f} %")
    g = gaps(run)
    gap = " ".join(f"{100 * (x[1] - r[1]) / r[1]:+.2f} %" for x, r in zip(g, ref_gaps))
    same = all(x[0] == r[0] for x, r in zip(g, ref_gaps))
    print(f"| {run} | " + " | ".join(cells) + f" | {gap} | {'same' if same else 'differs'} |")
EOF
