#!/bin/bash
# Measures what docs/cluster.md and BENCHMARKS.md quote for sharded studies
# (issue 27), on the study tests/slurm/rail-car-fra5-mc.yaml (300 samples):
#   1. wall time of the whole study as 1, 2 and 4 Slurm array tasks plus
#      the merge, submission to merged folder (needs a cluster: run it as
#      `.ci/slurm bash slurm/measure.sh`);
#   2. per-task overhead: a one-sample shard against the per-sample cost;
#   3. merge wall time, peak RSS and part-file bytes against N, the parts
#      made by `vbi run --shard` outside Slurm.
# Prints a table; writes nothing outside a temporary folder.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
vbi=${VBI:-$repo/target/release/vbi}
scene=rail-car-fra5-mc.yaml
work=$(mktemp -d /tmp/vbi-measure.XXXXXX)
trap 'rm -rf "$work"' EXIT
cp "$repo/tests/slurm/$scene" "$work/"
cd "$work"
now() { date +%s.%N; }
secs() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", b - a }'; }

echo "machine: $(nproc) CPUs, load average $(cut -d' ' -f1-3 /proc/loadavg)"
t0=$(now)
"$vbi" run "$scene" -q --out whole
t1=$(now)
echo "unsharded vbi run (all CPUs): $(secs "$t0" "$t1") s"

if command -v sbatch >/dev/null && sinfo >/dev/null 2>&1; then
  for n in 1 2 4; do
    t0=$(now)
    read -r array merge < <(VBI=$vbi "$repo/slurm/vbi-array.sh" "$scene" "$n" --out "slurm$n" 2>/dev/null)
    while [ -n "$(squeue --noheader --jobs "$array,$merge" 2>/dev/null)" ]; do sleep 0.2; done
    t1=$(now)
    state=$(scontrol show job "$merge" | grep -o 'JobState=[A-Z]*')
    echo "slurm: $n tasks (1 CPU each) + merge: $(secs "$t0" "$t1") s ($state)"
  done
else
  echo "slurm: no cluster, array timings skipped (run as .ci/slurm bash slurm/measure.sh)"
fi

# Per-task overhead: a one-sample shard (of 300) is the process start, the
# scene load and the part write plus one sample.
t0=$(now)
"$vbi" run "$scene" -q --shard 1/300 --out one
t1=$(now)
echo "one-sample shard (1/300): $(secs "$t0" "$t1") s; part $(stat -c %s one/part-1-of-300.json) bytes"
RAYON_NUM_THREADS=1 /usr/bin/time -f "%e" -o single.t "$vbi" run "$scene" -q --shard 1/1 --out single
echo "whole study as one shard, 1 thread: $(cat single.t) s, $(awk '{ printf "%.4f", $1 / 300 }' single.t) s a sample"

for n in 1 10 100 300; do
  for ((k = 1; k <= n; k++)); do
    RAYON_NUM_THREADS=1 "$vbi" run "$scene" -q --shard "$k/$n" --out "parts$n" &
    # two at a time
    if ((k % 2 == 0)); then wait; fi
  done
  wait
  bytes=$(cat "parts$n"/part-*-of-"$n".json | wc -c)
  files=()
  for ((k = 1; k <= n; k++)); do files+=("parts$n/part-$k-of-$n.json"); done
  /usr/bin/time -f "%e %M" -o merge.t "$vbi" merge -q "${files[@]}" --out "merged$n"
  read -r wall rss <merge.t
  cmp -s <(grep -v wall_time whole/summary.json) <(grep -v wall_time "merged$n"/summary.json) && same=same || same=DIFFERENT
  echo "merge of N=$n parts: $wall s, peak RSS $((rss / 1024)) MB, parts $bytes bytes in all (summary.json $same)"
  rm -rf "parts$n" "merged$n"
done
