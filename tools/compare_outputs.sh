#!/usr/bin/env bash
# Byte-for-byte comparison of every shipped scene's outputs, for refactors that must move no result.
#
#   tools/compare_outputs.sh run DIR [VBI]   run every scenarios/*.yaml (studies included) into DIR/<stem>
#   tools/compare_outputs.sh diff A B        compare two such folders; exit 1 on any difference
#
# Ignored: only the fields that measure the machine, not the physics: every JSON key named
# `wall_time`, `*_time` measured in wall seconds (`solve_time`, `coupled_time`, ...), EMBS's
# `speed_up` (a ratio of two wall times), `vbi_version`,
# and the `.vbi-cache` folders (modes caches are an optimisation, not a result).
set -u
cmd=${1:-}; shift || true
case "$cmd" in
run)
    out=$1; vbi=${2:-target/release/vbi}
    mkdir -p "$out"
    for f in scenarios/*.yaml; do
        stem=$(basename "$f" .yaml)
        "$vbi" run "$f" --out "$out/$stem" --quiet --force >"$out/$stem.stdout" 2>"$out/$stem.stderr"
        echo "$?" >"$out/$stem.rc"
        echo "$stem: exit $(cat "$out/$stem.rc")"
    done
    ;;
diff)
    a=$1; b=$2; status=0
    norm() {
        case "$1" in
        *.json) python3 - "$1" <<'PY'
import json, re, sys
def scrub(v):
    if isinstance(v, dict):
        return {k: ("<wall>" if (k in ("wall_time", "vbi_version", "speed_up") or re.fullmatch(r".*_time(_s)?", k) and k not in ("end_time", "start_time", "arrival_time")) else scrub(x)) for k, x in v.items()}
    if isinstance(v, list):
        return [scrub(x) for x in v]
    return v
text = open(sys.argv[1], encoding="utf-8").read()
try:
    print(json.dumps(scrub(json.loads(text)), indent=1, sort_keys=False))
except Exception:
    print(text)
PY
        ;;
        *.stderr) sed -E 's/[0-9]+(\.[0-9]+)? ?(ms|s)\b/<t>/g' "$1" ;;
        *) cat "$1" ;;
        esac
    }
    while IFS= read -r rel; do
        if [ ! -e "$b/$rel" ]; then echo "only in $a: $rel"; status=1; continue; fi
        if ! cmp -s "$a/$rel" "$b/$rel"; then
            if ! cmp -s <(norm "$a/$rel" 2>/dev/null) <(norm "$b/$rel" 2>/dev/null); then echo "differs: $rel"; status=1; fi
        fi
    done < <(cd "$a" && find . -type f -not -path '*/.vbi-cache/*' | sort)
    while IFS= read -r rel; do
        [ -e "$a/$rel" ] || { echo "only in $b: $rel"; status=1; }
    done < <(cd "$b" && find . -type f -not -path '*/.vbi-cache/*' | sort)
    [ $status = 0 ] && echo "identical (wall times and version aside)"
    exit $status
    ;;
*) sed -n 2,10p "$0"; exit 2 ;;
esac
