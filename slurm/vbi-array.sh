#!/bin/bash
# Run a vbi study on a Slurm cluster: N array tasks, task K running shard
# K/N (`vbi run SCENE --shard K/N`), then a merge job that starts only when
# every task succeeded (--dependency=afterok) and writes exactly the files
# an unsharded run writes (`vbi merge`). Run it on a login node; it checks
# the scene and N, then submits (see docs/cluster.md):
#
#   slurm/vbi-array.sh [OPTIONS] SCENE N
#
#   -A, --account ACCOUNT    charge the jobs to ACCOUNT   (env VBI_SLURM_ACCOUNT)
#   -p, --partition NAME     submit to partition NAME     (env VBI_SLURM_PARTITION)
#   -q, --qos QOS            quality of service           (env VBI_SLURM_QOS)
#   -t, --time LIMIT         time limit of each task      (env VBI_SLURM_TIME, 01:00:00)
#       --merge-time LIMIT   time limit of the merge job  (env VBI_SLURM_MERGE_TIME, 00:30:00)
#   -c, --cpus-per-task C    CPUs of each task, used by vbi's threads (env VBI_SLURM_CPUS, 1)
#       --mem SIZE           memory of each task (env VBI_SLURM_MEM, 2G)
#       --merge-mem SIZE     memory of the merge (env VBI_SLURM_MERGE_MEM, as --mem);
#                            it folds one part at a time: the largest part's
#                            bytes plus the merged study suffice
#   -o, --out DIR            results folder, on a file system every node sees
#                            (default results/<scene stem>): parts in DIR/parts,
#                            job logs in DIR/logs, the merged study in DIR
#       --only K[,K...]      submit only these shards (to re-run failed ones)
#                            and a merge after them; the other parts must be in DIR/parts
#       --no-merge           submit the tasks only
#       --merge-only         submit the merge only, at once (the parts are in DIR/parts)
#       --vbi-arg ARG        pass ARG to every vbi command (repeatable), e.g.
#                            --vbi-arg=--allow-large, --vbi-arg=--data-dir=/data
#   -n, --dry-run            check and print the sbatch commands, submit nothing
#
# The vbi binary is $VBI, else `vbi` on PATH, resolved to an absolute path
# at submission (the nodes must see the same path). The jobs run in the
# current folder, where SCENE and DIR are resolved. On success it prints
# the array's job id and the merge's on stdout (`ARRAY MERGE`); everything
# else goes to stderr. See docs/cluster.md.
set -euo pipefail

# ---- Inside a job: the two roles this script submits itself for. ----
if [ "${1:-}" = __task ]; then
  # __task VBI SCENE N PARTS [VBI_ARG...]: shard SLURM_ARRAY_TASK_ID of N.
  # N is given, not SLURM_ARRAY_TASK_COUNT: an array that re-runs a few
  # shards (--only) has fewer elements than the study has shards.
  vbi=$2 scene=$3 n=$4 parts=$5
  shift 5
  export RAYON_NUM_THREADS=${SLURM_CPUS_PER_TASK:-1}
  echo "vbi shard ${SLURM_ARRAY_TASK_ID}/$n of $scene on $(hostname), $RAYON_NUM_THREADS threads" >&2
  exec "$vbi" "$@" run "$scene" --quiet --shard "${SLURM_ARRAY_TASK_ID}/$n" --out "$parts"
fi
if [ "${1:-}" = __merge ]; then
  # __merge VBI N PARTS OUT [VBI_ARG...]: every part, named, so that a
  # missing one is reported with its shard and the command to re-run it.
  vbi=$2 n=$3 parts=$4 out=$5
  shift 5
  files=()
  for ((k = 1; k <= n; k++)); do
    files+=("$parts/part-$k-of-$n.json")
  done
  exec "$vbi" "$@" merge "${files[@]}" --out "$out"
fi

# ---- On the login node: check, then submit. ----
usage() {
  sed -n '/^#   slurm\/vbi-array.sh/,/^#   -n, --dry-run/p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 0
}
fail() {
  echo "vbi-array.sh: $*" >&2
  exit 2
}

account=${VBI_SLURM_ACCOUNT:-}
partition=${VBI_SLURM_PARTITION:-}
qos=${VBI_SLURM_QOS:-}
time=${VBI_SLURM_TIME:-01:00:00}
merge_time=${VBI_SLURM_MERGE_TIME:-00:30:00}
cpus=${VBI_SLURM_CPUS:-1}
mem=${VBI_SLURM_MEM:-2G}
merge_mem=${VBI_SLURM_MERGE_MEM:-}
out=
only=
merge=1
tasks=1
dry=0
vbi_args=()
positional=()
while [ $# -gt 0 ]; do
  case $1 in
    -A | --account) account=${2:?$1 needs a value}; shift 2 ;;
    --account=*) account=${1#*=}; shift ;;
    -p | --partition) partition=${2:?$1 needs a value}; shift 2 ;;
    --partition=*) partition=${1#*=}; shift ;;
    -q | --qos) qos=${2:?$1 needs a value}; shift 2 ;;
    --qos=*) qos=${1#*=}; shift ;;
    -t | --time) time=${2:?$1 needs a value}; shift 2 ;;
    --time=*) time=${1#*=}; shift ;;
    --merge-time) merge_time=${2:?$1 needs a value}; shift 2 ;;
    --merge-time=*) merge_time=${1#*=}; shift ;;
    -c | --cpus-per-task) cpus=${2:?$1 needs a value}; shift 2 ;;
    --cpus-per-task=*) cpus=${1#*=}; shift ;;
    --mem) mem=${2:?$1 needs a value}; shift 2 ;;
    --mem=*) mem=${1#*=}; shift ;;
    --merge-mem) merge_mem=${2:?$1 needs a value}; shift 2 ;;
    --merge-mem=*) merge_mem=${1#*=}; shift ;;
    -o | --out) out=${2:?$1 needs a value}; shift 2 ;;
    --out=*) out=${1#*=}; shift ;;
    --only) only=${2:?$1 needs a value}; shift 2 ;;
    --only=*) only=${1#*=}; shift ;;
    --no-merge) merge=0; shift ;;
    --merge-only) tasks=0; shift ;;
    --vbi-arg) vbi_args+=("${2:?$1 needs a value}"); shift 2 ;;
    --vbi-arg=*) vbi_args+=("${1#*=}"); shift ;;
    -n | --dry-run) dry=1; shift ;;
    -h | --help) usage ;;
    --) shift; positional+=("$@"); break ;;
    -*) fail "unknown option $1 (see --help)" ;;
    *) positional+=("$1"); shift ;;
  esac
done
[ ${#positional[@]} -eq 2 ] || fail "give the scene and the number of shards: slurm/vbi-array.sh [OPTIONS] SCENE N (see --help)"
scene=${positional[0]}
n=${positional[1]}

[[ $n =~ ^[1-9][0-9]{0,8}$ ]] || fail "N must be a positive whole number, got '$n'"
[[ $cpus =~ ^[1-9][0-9]{0,4}$ ]] || fail "--cpus-per-task must be a positive whole number, got '$cpus'"
[ -f "$scene" ] || fail "$scene: no such scene file"

vbi=${VBI:-$(command -v vbi || true)}
[ -n "$vbi" ] || fail "vbi not found: put it on PATH or set VBI=/path/to/vbi"
[ -x "$vbi" ] || fail "VBI=$vbi is not an executable file"
vbi=$(readlink -f "$vbi")

# The scene validates and its study splits into N shards (exit 2 and vbi's
# message otherwise: no study, N above its run count or its budget).
"$vbi" "${vbi_args[@]}" check --shards "$n" "$scene" >&2 ||
  fail "$scene cannot run as $n shards (vbi's message above); nothing submitted"

stem=$(basename "${scene%.*}")
out=${out:-results/$stem}
parts=$out/parts
logs=$out/logs

# Shards to submit: 1..N, or the --only list, each within 1..N.
if [ -n "$only" ]; then
  [[ $only =~ ^[0-9]+(,[0-9]+)*$ ]] || fail "--only takes shard numbers separated by commas, got '$only'"
  IFS=, read -r -a ks <<<"$only"
  for k in "${ks[@]}"; do
    ((10#$k >= 1 && 10#$k <= n)) || fail "--only: shard $k is not one of 1..$n"
  done
  indices=$only
else
  indices=1-$n
fi

if command -v scontrol >/dev/null 2>&1; then
  # Array indices run from 0 to MaxArraySize - 1.
  max=$(scontrol show config 2>/dev/null | awk '$1 == "MaxArraySize" { print $3 }' || true)
  if [[ ${max:-} =~ ^[0-9]+$ ]] && ((n > max - 1)); then
    fail "N = $n is above this cluster's largest array index, $((max - 1)) (MaxArraySize); use fewer shards"
  fi
fi
command -v sbatch >/dev/null 2>&1 || ((dry)) || fail "sbatch not found: run this on a Slurm login node"

common=(--chdir="$PWD")
[ -n "$account" ] && common+=(--account="$account")
[ -n "$partition" ] && common+=(--partition="$partition")
[ -n "$qos" ] && common+=(--qos="$qos")
self=$(readlink -f "$0")
task_cmd=(sbatch --parsable --job-name="vbi-$stem" --array="$indices" "${common[@]}"
  --time="$time" --cpus-per-task="$cpus" --mem="$mem" --output="$logs/task-%A_%a.out"
  "$self" __task "$vbi" "$scene" "$n" "$parts" "${vbi_args[@]}")
merge_cmd=(sbatch --parsable --job-name="vbi-$stem-merge" "${common[@]}" --time="$merge_time" --mem="${merge_mem:-$mem}"
  --cpus-per-task=1 --kill-on-invalid-dep=yes --output="$logs/merge-%j.out"
  "$self" __merge "$vbi" "$n" "$parts" "$out" "${vbi_args[@]}")

((merge || tasks)) || fail "--no-merge and --merge-only together submit nothing"
if ((dry)); then
  ((tasks)) && { printf '%q ' "${task_cmd[@]}" >&2; echo >&2; }
  if ((merge)); then
    dep=()
    ((tasks)) && dep=(--dependency=afterok:ARRAY)
    printf '%q ' sbatch "${dep[@]}" "${merge_cmd[@]:1}" >&2
    echo >&2
  fi
  exit 0
fi

mkdir -p "$parts" "$logs"
array=-
dep=()
if ((tasks)); then
  array=$("${task_cmd[@]}")
  array=${array%%;*}
  dep=(--dependency=afterok:"$array")
  echo "vbi-array.sh: array job $array: shards $indices of $n of $scene; parts in $parts, logs in $logs" >&2
fi
merged=
if ((merge)); then
  merged=$(sbatch "${dep[@]}" "${merge_cmd[@]:1}")
  merged=${merged%%;*}
  echo "vbi-array.sh: merge job $merged$( ((tasks)) && echo " after every task succeeds"); results in $out" >&2
fi
echo "$array${merged:+ $merged}"
