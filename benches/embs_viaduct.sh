#!/bin/bash
# EMBS against coupled, side by side in one run on the same model (issue
# 13, Speed): the AVE-S103 car (`train_3d`, 27 DOFs, 12 rail contacts) at
# 300 km/h crossing the generated ~157,000-DOF viaduct (30 spans of 25 m,
# 100 cached modes) while the synthetic lateral record shakes it, FRA
# class 5 with alignment. `solver.compare: true` solves the same model by
# `coupled` after `embs`; summary.json `embs.comparison` gives both solve
# times, the speed-up and each recorded quantity's EMBS error. Then the
# cost per step of the 27-DOF car alone: the same car over a one-mode
# rigid-ish span for 200,000 steps (the bridge's share is negligible), to
# set against the flop count of the car's condensed Newmark step (see
# BENCHMARKS.md). See BENCHMARKS.md for the figures.
#
# Usage: benches/embs_viaduct.sh [WORKDIR=/tmp/vbi-embs-viaduct]
set -eu
work=${1:-/tmp/vbi-embs-viaduct}
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
cargo build --release --locked --bin vbi
mkdir -p "$work"
if [ ! -f "$work/viaduct/K.mtx" ]; then
    ./target/release/vbi generate viaduct --spans 30 --span-length 25 --pier-height 10 \
        --rail-divisions 9 --out "$work/viaduct"
fi
cp scenarios/records/synthetic-lateral.AT2 "$work/"
cat > "$work/embs.yaml" <<SCENE
name: embs-viaduct
bridge:
  type: fe_import
  stiffness: viaduct/K.mtx
  mass: viaduct/M.mtx
  dof_map: viaduct/dof_map.csv
  rails: [{name: left, file: viaduct/rail_left.csv}, {name: right, file: viaduct/rail_right.csv}]
  damping: {type: modal, ratio: 0.02}
  modes: {count: 100}
vehicles:
  - {type: train_3d, speed: 300 km/h, parameters: {contact_half_spacing: 0.88}}
surface: {type: fra, class: 5, alignment: true, rails: independent, seed: 2024}
ground_motion: [{file: synthetic-lateral.AT2, direction: lateral}]
contact: {type: permanent}
solver: {method: embs, compare: true, time_step: 5.0e-4}
limits: {dofs: 200000}
record:
  - {name: span15_vertical, quantity: bridge_displacement, x: 372.7}
  - {name: span15_vertical_acc, quantity: bridge_acceleration, x: 372.7, max_frequency: 30.0}
  - {name: span15_lateral, quantity: bridge_displacement, x: 372.7, direction: uy}
  - {name: span15_lateral_acc, quantity: bridge_acceleration, x: 372.7, direction: uy, max_frequency: 30.0}
  - {name: body_lateral, quantity: vehicle_displacement, dof: body_lateral}
  - {name: body_lateral_acc, quantity: vehicle_acceleration, dof: body_lateral}
SCENE
cat > "$work/car.yaml" <<SCENE
name: car-alone
bridge: {type: beam, spans: [10.0], bending_stiffness: 1.0e14, mass_per_length: 1.0e4, modes: {count: 1}}
vehicles: [{type: train_3d, speed: 10.0}]
surface: {type: fra, class: 5, alignment: true, rails: independent}
contact: {type: permanent}
solver: {method: coupled, time_step: 2.0e-5, free_vibration: 1.5}
output: {every: 1000}
record:
  - {name: body_lateral, quantity: vehicle_displacement, dof: body_lateral}
SCENE
echo "== EMBS and coupled on the viaduct (modes cached after the first run)"
for run in first second; do
    /usr/bin/time -f "%e s wall, %U s user, %M kB peak" \
        ./target/release/vbi run "$work/embs.yaml" --out "$work/out-embs" -q \
        --modes-cache "$work/cache" --trust-limits
done
python3 - "$work/out-embs/summary.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
e = d["embs"]; c = e["comparison"]; steps = d["run"]["steps"]
print(f"steps {steps}, modes {d['run']['modes_used']}, epsilon {e['epsilon']:.3f} (lateral {e['epsilon_lateral']:.3f})")
print(f"embs {c['embs_solve_time']:.3f} s ({1e6 * c['embs_solve_time'] / steps:.1f} us/step), "
      f"coupled {c['coupled_solve_time']:.3f} s ({1e6 * c['coupled_solve_time'] / steps:.1f} us/step), "
      f"speed-up {c['speed_up']:.2f}")
for q in c["quantities"]:
    print(f"  {q['name']:22s} error {q['error']:.3e} of the coupled peak {q['coupled_peak']:.4e}")
PY
echo "== the 27-DOF car alone"
/usr/bin/time -f "%e s wall, %U s user, %M kB peak" \
    ./target/release/vbi run "$work/car.yaml" --out "$work/out-car" -q
python3 - "$work/out-car/summary.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
r = d["run"]
print(f"steps {r['steps']}, wall {r['wall_time']:.3f} s, {1e9 * r['wall_time'] / r['steps']:.0f} ns/step")
PY
