#!/usr/bin/env bash
# Runs a sun study on a Slurm cluster: a job array of N shards, then one merge job that starts
# when every shard has succeeded. docs/sun-study-cluster.md.
set -euo pipefail

usage() {
  cat <<'EOF'
usage: sun-study.sh --shards N --out DIR [OPTIONS] SCENE [--lat DEG --lon DEG --utc-offset HOURS]
                    --from T --to T --step MINUTES [other sun-study options]

--lat, --lon and --utc-offset may be left out when the scene file has a site.

Submits `shadowkit sun-study ... --shard I/N --out DIR/shard-I` as a job array of N tasks
(sbatch --array=0-(N-1)), then `shadowkit sun-study-merge DIR/shard-0 ... --out DIR` as a job
that waits for all of them (--dependency=afterok). DIR then holds the study's files, byte for
byte those of one unsharded run; the tasks' logs go to DIR/slurm/. Prints the two job ids.

Options of this script (every other argument goes to `shadowkit sun-study` as it is):
  --shards N          number of shards, one array task each (N >= 1)
  --out DIR           the study's folder (on a file system every node sees)
  --shadowkit PATH    the shadowkit program, at a path every node sees
                      (default: $SHADOWKIT, else `shadowkit` on PATH)
  --only LIST         submit only these shards (a Slurm array list: 3 or 1,4-6), e.g. to
                      rerun the ones that failed; the merge still joins all N folders
  --max-running K     run at most K shards at once (--array=0-(N-1)%K)
  --partition P, --account A, --qos Q
                      both jobs
  --time T, --cpus-per-task C, --mem M
                      each shard's task; --cpus-per-task also becomes sun-study's --threads
                      unless --threads is given
  --merge-time T      the merge job's time limit
  --job-name NAME     the array's name (default sun-study; the merge's is NAME-merge)
  --sbatch OPT        one more sbatch option for both jobs, repeatable (--sbatch=--constraint=x)
  --merge-sbatch OPT  one more sbatch option for the merge job only, repeatable
  --wait              wait until the merge job ends; exit 0 only if it completed
  --poll SECONDS      how often --wait asks Slurm (default 5)
  --dry-run           print the sbatch commands instead of running them
  -h, --help          this help

Without Slurm, rerun shard I with the same arguments as
  shadowkit sun-study SCENE ... --shard I/N --out DIR/shard-I
and merge with
  shadowkit sun-study-merge DIR/shard-0 ... DIR/shard-(N-1) --out DIR
EOF
}

die() {
  echo "sun-study.sh: $*" >&2
  exit 2
}

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
shards="" out="" shadowkit=${SHADOWKIT:-} only="" max_running="" job_name=sun-study
wait_for_merge=0 dry_run=0 poll=5
both=() tasks=() merge=() study=()

# take NAME "$@": the value of an option given as `--name VALUE` or `--name=VALUE`, in `val`;
# `taken` says how many arguments it used.
val="" taken=0
take() {
  local name=$1
  shift
  if [[ $1 == *=* ]]; then
    val=${1#*=} taken=1
  else
    (($# >= 2)) || die "$name needs a value"
    val=$2 taken=2
  fi
}

while (($#)); do
  arg=$1
  case $arg in
    -h | --help)
      usage
      exit 0
      ;;
    --wait) wait_for_merge=1 taken=1 ;;
    --dry-run) dry_run=1 taken=1 ;;
    --shards | --shards=*) take --shards "$@"; shards=$val ;;
    --out | --out=*) take --out "$@"; out=$val ;;
    --shadowkit | --shadowkit=*) take --shadowkit "$@"; shadowkit=$val ;;
    --only | --only=*) take --only "$@"; only=$val ;;
    --max-running | --max-running=*) take --max-running "$@"; max_running=$val ;;
    --job-name | --job-name=*) take --job-name "$@"; job_name=$val ;;
    --poll | --poll=*) take --poll "$@"; poll=$val ;;
    --partition | --partition=* | --account | --account=* | --qos | --qos=*)
      take "${arg%%=*}" "$@"
      both+=("${arg%%=*}=$val")
      ;;
    --time | --time=* | --cpus-per-task | --cpus-per-task=* | --mem | --mem=*)
      take "${arg%%=*}" "$@"
      tasks+=("${arg%%=*}=$val")
      ;;
    --merge-time | --merge-time=*) take --merge-time "$@"; merge+=("--time=$val") ;;
    --sbatch | --sbatch=*) take --sbatch "$@"; both+=("$val") ;;
    --merge-sbatch | --merge-sbatch=*) take --merge-sbatch "$@"; merge+=("$val") ;;
    --shard | --shard=*) die "--shard is this script's to give: use --shards N" ;;
    --)
      shift
      study+=("$@")
      break
      ;;
    *)
      # A sun-study argument. Every sun-study option takes a value: keep the pair together,
      # so that a value such as `--lon -3.7` is never read as an option of this script.
      if [[ $arg == --* && $arg != *=* ]] && (($# >= 2)); then
        study+=("$arg" "$2")
        taken=2
      else
        study+=("$arg")
        taken=1
      fi
      ;;
  esac
  shift "$taken"
done

# whole NAME VALUE: VALUE is a whole number >= 1, or the script stops.
whole() {
  [[ $2 =~ ^[0-9]{1,9}$ ]] && ((10#$2 >= 1)) && return
  die "$1: expected a whole number >= 1, got '$2'"
}
[[ -n $shards ]] || die "give --shards N (try --help)"
whole --shards "$shards"
shards=$((10#$shards))
[[ -n $out ]] || die "give --out DIR (try --help)"
((${#study[@]})) || die "give the sun-study arguments: SCENE --from ... (try --help)"
for arg in "${study[@]}"; do
  [[ $arg == --out || $arg == --out=* ]] && die "give --out once, as this script's option"
done
[[ -z $max_running ]] || whole --max-running "$max_running"
if [[ -n $only ]]; then
  [[ $only =~ ^[0-9]+(-[0-9]+)?(,[0-9]+(-[0-9]+)?)*$ ]] ||
    die "--only: expected shard numbers such as 3 or 1,4-6, got '$only'"
  for n in ${only//[,-]/ }; do
    ((10#$n < shards)) || die "--only: shard $n is not below --shards $shards"
  done
fi
whole --poll "$poll"

# The jobs run wherever Slurm puts them: give them absolute paths.
[[ -n $shadowkit ]] || shadowkit=shadowkit
if [[ $shadowkit != */* ]]; then
  found=$(command -v "$shadowkit") || die "no '$shadowkit' on PATH: give --shadowkit PATH or set SHADOWKIT"
  shadowkit=$found
fi
[[ -f $shadowkit && -x $shadowkit ]] || die "'$shadowkit' is not an executable file"
shadowkit=$(realpath -m -s -- "$shadowkit")
out=$(realpath -m -s -- "$out")

array=${only:-0-$((shards - 1))}
[[ -n $max_running ]] && array+=%$max_running
logs=$out/slurm
task_cmd=(sbatch --parsable --job-name="$job_name" --array="$array"
  --output="$logs/shard-%a.log" "${both[@]}" "${tasks[@]}"
  "$here/sun-study-task.sbatch" "$shadowkit" "$shards" "$out" "${study[@]}")
merge_cmd=(sbatch --parsable --job-name="$job_name-merge" --kill-on-invalid-dep=yes
  --output="$logs/merge.log" "${both[@]}" "${merge[@]}")
merge_args=("$here/sun-study-merge.sbatch" "$shadowkit" "$shards" "$out")

if ((dry_run)); then
  printf '%q ' "${task_cmd[@]}"
  echo
  printf '%q ' "${merge_cmd[@]}" "--dependency=afterok:ARRAY_JOB_ID" "${merge_args[@]}"
  echo
  exit 0
fi

command -v sbatch >/dev/null || die "no sbatch on PATH: run this on a Slurm login node"
# Slurm refuses arrays past its MaxArraySize (largest index + 1); say so before submitting.
max_array=$(scontrol show config 2>/dev/null | sed -n 's/^MaxArraySize *= *\([0-9]*\).*/\1/p') || true
if [[ -n $max_array ]] && ((shards > max_array)); then
  die "--shards $shards: this cluster's MaxArraySize is $max_array"
fi

mkdir -p "$logs" || die "cannot create '$logs'"
# The merged files of an earlier study in DIR go first, as sun-study's own do: DIR never shows
# an old result as if it were this one's.
rm -f "$out"/{times.csv,polygons.csv,sunlit_fraction.f32,sun_hours.csv,sun_study.json}

array_id=$("${task_cmd[@]}") || die "sbatch refused the job array"
array_id=${array_id%%;*}  # --parsable prints ID or ID;CLUSTER
merge_id=$("${merge_cmd[@]}" --dependency="afterok:$array_id" "${merge_args[@]}") || {
  scancel "$array_id" 2>/dev/null || true
  die "sbatch refused the merge job; job array $array_id cancelled"
}
merge_id=${merge_id%%;*}
echo "sun-study: $shards shards in job array $array_id, merge in job $merge_id: $out (logs in $logs)"
((wait_for_merge)) || exit 0

# --wait: follow the merge job until it ends. It is cancelled (--kill-on-invalid-dep) when a
# shard fails; then say which.
job_state() {
  scontrol show job -o "$1" 2>/dev/null | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | head -n 1
}
while :; do
  state=$(job_state "$merge_id")
  case $state in
    PENDING | CONFIGURING | RUNNING | COMPLETING | SUSPENDED | REQUEUED | RESIZING | REQUEUE_HOLD | \
      REQUEUE_FED | SIGNALING | STAGE_OUT | RESV_DEL_HOLD | SPECIAL_EXIT | STOPPED) sleep "$poll" ;;
    *) break ;;
  esac
done
if [[ $state == COMPLETED ]]; then
  echo "sun-study: merge job $merge_id completed: $out"
  exit 0
fi
if [[ -z $state ]]; then
  # Slurm forgot the job (MinJobAge): the merge's manifest, written last, tells.
  if [[ -f $out/sun_study.json ]]; then
    echo "sun-study: merge job $merge_id ended and $out/sun_study.json is there: $out"
    exit 0
  fi
  echo "sun-study: merge job $merge_id ended without writing $out/sun_study.json; see $logs/merge.log" >&2
  exit 1
fi
# The shards that did not complete, as "I STATE EXITCODE" lines in shard order.
failures=$(scontrol show job -o "$array_id" 2>/dev/null |
  sed -n 's/.*ArrayTaskId=\([0-9]*\) .*JobState=\([A-Z_]*\) .*ExitCode=\([0-9:]*\).*/\1 \2 \3/p' |
  awk '$2 != "COMPLETED"' | sort -n) || true
if [[ -z $failures ]]; then
  echo "sun-study: merge job $merge_id ended $state; see $logs/merge.log" >&2
  exit 1
fi
echo "sun-study: merge job $merge_id ended $state: not every shard completed" >&2
while read -r task task_state code; do
  echo "  shard $task: $task_state (exit $code), log $logs/shard-$task.log" >&2
done <<<"$failures"
echo "rerun them with the same command and --only $(cut -d' ' -f1 <<<"$failures" | paste -sd,)" >&2
exit 1
