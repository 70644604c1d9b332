#!/bin/sh
# The automatic settings on imported track models (issue 24.4; docs/methods.md, "Free rail
# ends: the entry length" and "Automatic modes on an imported track"): each shipped scene with
# its explicit `modes` and `time_step` removed, against `vbi converge`'s reference (Δt/4 and
# twice the modes). Prints the convergence table; results in results/auto-settings/<stem>.
# Usage, from the repository root after `cargo build --release`:
#   tools/auto_settings.sh [scene-stem...]
# (default: viaduct-2span-axle-loads embs-viaduct-ave-s103-quake; the second takes
# about 10 minutes of a quiet core). VBI names the binary (default target/release/vbi).
set -e
vbi=${VBI:-target/release/vbi}
out=results/auto-settings
mkdir -p "$out"
for s in ${*:-viaduct-2span-axle-loads embs-viaduct-ave-s103-quake}; do
  python3 tools/scene_variant.py "scenarios/$s.yaml" "$out/$s.yaml" auto
  "$vbi" --trust-limits --data-dir scenarios --data-dir "$out" converge "$out/$s.yaml" \
    --levels 1 --tolerance 0.5% --modes-cache "$out/.cache" --out "$out/$s" --force
done
