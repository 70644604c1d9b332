#!/bin/bash
# A rail car crossing the generated ~157,000-DOF viaduct with 100 cached modes,
# against the same car crossing a 30-span beam with 100 modes: same solver,
# same step, one after the other. The viaduct runs twice: the first solves
# the modes and writes the cache, the second reads it. Wall time and peak
# memory of the whole command from /usr/bin/time; `run.wall_time` in
# summary.json is the crossing alone (build + solve + record). See
# BENCHMARKS.md.
#
# Usage: benches/viaduct_crossing.sh [WORKDIR=/tmp/vbi-viaduct-crossing]
set -eu
work=${1:-/tmp/vbi-viaduct-crossing}
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
cargo build --release --locked --bin vbi
mkdir -p "$work"
./target/release/vbi generate viaduct --spans 30 --span-length 25 --pier-height 10 \
    --rail-divisions 9 --out "$work/viaduct"
vehicle="  - {type: rail_car, speed: 300 km/h}"
cat > "$work/viaduct.yaml" <<SCENE
name: viaduct-crossing
bridge:
  type: fe_import
  stiffness: viaduct/K.mtx
  mass: viaduct/M.mtx
  dof_map: viaduct/dof_map.csv
  rails: [{name: left, file: viaduct/rail_left.csv}, {name: right, file: viaduct/rail_right.csv}]
  damping: {type: modal, ratio: 0.02}
  modes: {count: 100}
vehicles:
$vehicle
contact: {type: permanent}
solver: {time_step: 5.0e-4}
limits: {dofs: 200000}
record:
  - {name: span15_mid, quantity: bridge_displacement, x: 372.7}
  - {name: body_acc, quantity: vehicle_acceleration, dof: body_bounce}
SCENE
spans=$(printf '25, %.0s' $(seq 29))25
cat > "$work/beam.yaml" <<SCENE
name: beam-crossing
bridge:
  type: beam
  spans: [$spans]
  bending_stiffness: 6.0e10
  mass_per_length: 25000
  elements_per_span: 20
  damping: {type: modal, ratio: 0.02}
  modes: {count: 100}
vehicles:
$vehicle
contact: {type: permanent}
solver: {time_step: 5.0e-4}
record:
  - {name: span15_mid, quantity: bridge_displacement, x: 362.5}
  - {name: body_acc, quantity: vehicle_acceleration, dof: body_bounce}
SCENE
rm -rf "$work/out-viaduct" "$work/out-beam"
for run in first second; do
    echo "== viaduct, $run run"
    /usr/bin/time -f "%e s wall, %U s user, %M kB peak" \
        ./target/release/vbi run "$work/viaduct.yaml" --out "$work/out-viaduct" -q --trust-limits
    grep -E '"wall_time"|"steps"|"modes_from_cache"' "$work/out-viaduct/summary.json"
done
echo "== beam"
/usr/bin/time -f "%e s wall, %U s user, %M kB peak" \
    ./target/release/vbi run "$work/beam.yaml" --out "$work/out-beam" -q
grep -E '"wall_time"|"steps"' "$work/out-beam/summary.json"
