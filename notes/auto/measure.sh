#!/bin/sh
# Issue 24 point 4: the two imported-track scenes at automatic settings
# (explicit modes/time_step removed) against `vbi converge`'s reference.
# Usage: notes/auto/measure.sh [scene-stem]   (from the worktree root)
set -e
for s in ${1:-viaduct-2span-axle-loads embs-viaduct-ave-s103-quake}; do
  ./target/release/vbi --trust-limits --data-dir scenarios converge notes/auto/$s.yaml \
    --levels 1 --tolerance 0.5% --modes-cache notes/auto/.cache --out notes/auto/out/$s
done
