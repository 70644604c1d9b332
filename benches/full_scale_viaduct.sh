#!/bin/bash
# The EMBS paper's scene at full scale (issue 24 point 7): the shipped
# scenarios/full-scale/embs-viaduct-30span-ave-s103-train.yaml (the 30-span viaduct of
# `vbi generate viaduct` at its defaults, 48,516 DOFs; an eight-car
# AVE-S103 set at 300 km/h; the synthetic lateral record's strong phase
# during the crossing; EMBS and coupled side by side, `compare: true`).
# Generates the model's files beside the scene (not shipped: 7 MB), then
# runs the scene twice into one output folder: the first run solves the
# modes and writes the cache, the second reads them from it. Wall time and
# peak memory from /usr/bin/time -v. Then a reference run with the modes
# cut at twice the frequency and half the time step, and the errors of the
# shipped settings against it. See BENCHMARKS.md for the figures.
#
# Usage: benches/full_scale_viaduct.sh [WORKDIR=/tmp/vbi-full-scale]
set -eu
work=${1:-/tmp/vbi-full-scale}
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
cargo build --release --locked --bin vbi
vbi=$here/target/release/vbi
scene=scenarios/full-scale/embs-viaduct-30span-ave-s103-train.yaml
if [ ! -f scenarios/full-scale/viaduct-30span/K.mtx ]; then
    "$vbi" generate viaduct --out scenarios/full-scale/viaduct-30span
fi
mkdir -p "$work"
rm -rf "$work/out"
for run in first second; do
    echo "== $run run"
    /usr/bin/time -v "$vbi" run "$scene" --out "$work/out" -q --trust-limits 2> "$work/time-$run.txt"
    grep -E "Elapsed|Maximum resident|User time" "$work/time-$run.txt"
    python3 - "$work/out/summary.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
r = d["run"]; e = d["embs"]; c = e["comparison"]
print(f"modes {r['modes_used']} (from cache: {r['modes_from_cache']}), steps {r['steps']}, "
      f"wall {r['wall_time']:.2f} s")
print(f"embs {c['embs_solve_time']:.2f} s, coupled {c['coupled_solve_time']:.2f} s, "
      f"speed-up {c['speed_up']:.2f}")
for q in c["quantities"]:
    print(f"  {q['name']:24s} EMBS error {100 * q['error']:.2f} % of the coupled peak {q['coupled_peak']:.4e}")
PY
done
# Converged accuracy: the shipped settings solved by `coupled` alone
# against a reference with the modes cut at twice the frequency (30 Hz)
# and half the time step.
echo "== shipped settings, coupled only; reference: modes to 30 Hz, half the step"
sed -e 's/method: embs, compare: true, time_step: 5.0e-4/method: coupled, time_step: 5.0e-4/' \
    "$scene" > scenarios/.full-scale-coupled.yaml
sed -e 's/max_frequency: 15.0}/max_frequency: 30.0}/' \
    -e 's/method: embs, compare: true, time_step: 5.0e-4/method: coupled, time_step: 2.5e-4/' \
    "$scene" > scenarios/.full-scale-reference.yaml
for case in coupled reference; do
    /usr/bin/time -v "$vbi" run scenarios/.full-scale-$case.yaml --out "$work/$case" -q \
        --trust-limits --modes-cache "$work/out/.vbi-cache" 2> "$work/time-$case.txt"
    rm -f scenarios/.full-scale-$case.yaml
    grep -E "Elapsed|Maximum resident" "$work/time-$case.txt"
done
python3 - "$work/coupled/history.csv" "$work/reference/history.csv" <<'PY'
import csv, sys
def load(path):
    rows = list(csv.reader(open(path)))
    return rows[0], [[float(v) for v in r] for r in rows[1:]]
(names, a), (_, b) = load(sys.argv[1]), load(sys.argv[2])
# The reference has twice the samples: compare at the shipped run's times.
at = {round(r[0], 9): r for r in b}
pairs = [(r, at[round(r[0], 9)]) for r in a if round(r[0], 9) in at]
for k, name in enumerate(names[1:], start=1):
    peak = max(abs(y[k]) for _, y in pairs)
    error = max(abs(x[k] - y[k]) for x, y in pairs)
    print(f"  {name:36s} shipped settings against the reference: {100 * error / peak:.3f} % of its peak {peak:.4e}")
PY
