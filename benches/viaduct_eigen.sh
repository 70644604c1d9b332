#!/bin/bash
# Lowest 100 modes of the generated ~157,000-DOF viaduct: vbi against
# scipy.sparse.linalg.eigsh(K, 100, M, sigma=0), same files, one after the
# other, wall time and peak memory from /usr/bin/time -v. See BENCHMARKS.md.
#
# Usage: benches/viaduct_eigen.sh [WORKDIR=/tmp/vbi-viaduct-bench] [PYTHON=python3]
# PYTHON must have numpy and scipy (e.g. python3 -m venv V && V/bin/pip install scipy).
set -eu
work=${1:-/tmp/vbi-viaduct-bench}
python=${2:-python3}
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
cargo build --release --locked --bin vbi --example mtx_modes
mkdir -p "$work"
./target/release/vbi generate viaduct --spans 30 --span-length 25 --pier-height 10 \
    --rail-divisions 9 --out "$work/viaduct"
cat "$work/viaduct/README.txt"
echo "== vbi"
/usr/bin/time -v ./target/release/examples/mtx_modes "$work/viaduct" 100 \
    > "$work/vbi.txt" 2> "$work/vbi.time"
head -3 "$work/vbi.txt"
grep -E "Elapsed|Maximum resident" "$work/vbi.time"
echo "== vbi through the modes cache: first run (miss, solves and writes), second (hit, reads and re-checks)"
rm -rf "$work/cache"
for run in first second; do
    /usr/bin/time -v ./target/release/examples/mtx_modes "$work/viaduct" 100 --cache "$work/cache" \
        > "$work/vbi-cache-$run.txt" 2> "$work/vbi-cache-$run.time"
    sed -n 2p "$work/vbi-cache-$run.txt"
    grep -E "Elapsed|Maximum resident" "$work/vbi-cache-$run.time"
done
if diff <(sed 1,2d "$work/vbi-cache-first.txt") <(sed 1,2d "$work/vbi-cache-second.txt") >/dev/null; then
    echo "cached run: frequencies and check figures identical to the solving run"
else
    echo "cached run DIFFERS from the solving run"
fi
echo "== vbi phases (Lanczos, polish, inertia count timed apart; a separate run)"
./target/release/examples/mtx_modes "$work/viaduct" 100 --phases > "$work/vbi-phases.txt"
head -1 "$work/vbi-phases.txt"
echo "== vbi modes on a scene of the viaduct (100 modes), --threads 2 then 1 (same output expected)"
cat > "$work/viaduct.yaml" <<SCENE
name: viaduct-modes
bridge:
  type: fe_import
  stiffness: viaduct/K.mtx
  mass: viaduct/M.mtx
  dof_map: viaduct/dof_map.csv
  rails: [{name: left, file: viaduct/rail_left.csv}, {name: right, file: viaduct/rail_right.csv}]
  damping: {type: modal, ratio: 0.02}
  modes: {count: 100}
vehicles:
  - {type: rail_car, speed: 300 km/h}
contact: {type: permanent}
solver: {time_step: 5.0e-4}
limits: {dofs: 200000}
record:
  - {name: span15_mid, quantity: bridge_displacement, x: 372.7}
SCENE
for threads in 2 1; do
    /usr/bin/time -v ./target/release/vbi --threads $threads modes "$work/viaduct.yaml" --trust-limits \
        > "$work/modes-$threads.txt" 2> "$work/modes-$threads.time"
    echo "--threads $threads"
    grep -E "Elapsed|Maximum resident|User time|Percent of CPU" "$work/modes-$threads.time"
done
cmp -s "$work/modes-1.txt" "$work/modes-2.txt" && echo "vbi modes: identical output with 1 and 2 threads"
echo "== scipy"
/usr/bin/time -v "$python" benches/viaduct_eigen.py "$work/viaduct" 100 \
    > "$work/scipy.txt" 2> "$work/scipy.time"
head -3 "$work/scipy.txt"
grep -E "Elapsed|Maximum resident" "$work/scipy.time"
echo "== largest relative frequency difference vbi / scipy"
"$python" - "$work/vbi.txt" "$work/scipy.txt" <<'PY'
import sys
def freqs(path):
    lines = open(path).read().split("frequencies\n")[1].split()
    return [float(x) for x in lines]
a, b = freqs(sys.argv[1]), freqs(sys.argv[2])
print(max(abs(x - y) / y for x, y in zip(a, b)))
PY
