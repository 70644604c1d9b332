#!/bin/bash
# Run a vbi study as a Slurm job array: task K of N runs shard K/N and
# writes results/<study>/parts/part-K-of-N.json; a dependent job merges.
#
#   sbatch --array=1-32 slurm/vbi-array.sh scenarios/lcp-fig8-monte-carlo-speeds.yaml
#   # when the array has finished (or chain it: see the bottom of this file):
#   vbi merge results/lcp-fig8-monte-carlo-speeds/parts/part-*-of-32.json \
#       --out results/lcp-fig8-monte-carlo-speeds
#
# N is the array's size (SLURM_ARRAY_TASK_COUNT), so the same script serves
# any shard count. Each task is an independent single-node run: vbi uses
# the task's CPUs through rayon (RAYON_NUM_THREADS below); results do not
# depend on the thread count or on N.
#SBATCH --job-name=vbi-shard
#SBATCH --cpus-per-task=4
#SBATCH --mem=2G
#SBATCH --time=01:00:00
#SBATCH --output=slurm-%A_%a.out
set -euo pipefail

scene=${1:?usage: sbatch --array=1-N slurm/vbi-array.sh SCENE.yaml}
stem=$(basename "${scene%.*}")
parts="results/${stem}/parts"
export RAYON_NUM_THREADS=${SLURM_CPUS_PER_TASK:-1}

vbi run "$scene" --quiet \
    --shard "${SLURM_ARRAY_TASK_ID}/${SLURM_ARRAY_TASK_COUNT}" \
    --out "$parts"

# To merge automatically, submit the array and a dependent merge job:
#   jid=$(sbatch --parsable --array=1-32 slurm/vbi-array.sh SCENE.yaml)
#   sbatch --dependency=afterok:$jid --wrap \
#     "vbi merge results/STEM/parts/part-*-of-32.json --out results/STEM"
