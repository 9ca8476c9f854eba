# Shared by fuzz/short-run.sh and scripts/fuzz.sh (sourced, not run): what a fuzz target reads,
# where its seeds come from, and the libFuzzer options every run uses. docs/fuzzing.md.

fuzz_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
fuzz_root=$(cd "$fuzz_dir/.." && pwd)

# Every target, in the order CMake defines them (fuzz/CMakeLists.txt).
fuzz_targets() {
  local formats renders
  formats=$(sed -n 's/^set(SHADOWKIT_FUZZ_MESH_FORMATS \(.*\))$/\1/p' "$fuzz_dir/CMakeLists.txt")
  renders=$(sed -n 's/^set(SHADOWKIT_FUZZ_RENDER_KINDS \(.*\))$/\1/p' "$fuzz_dir/CMakeLists.txt")
  echo scene $formats shading_groups frame_request $(printf 'render_%s ' $renders)
}

# The input kind of target NAME: "scene", "shading_groups" or a mesh extension
# (render_obj -> obj).
fuzz_kind() { echo "${1#render_}"; }

# The file extension of input kind KIND.
fuzz_extension() {
  case $1 in
    scene) echo json ;;
    shading_groups) echo csv ;;
    frame_request) echo request.json ;;
    *) echo "$1" ;;
  esac
}

# Collects the seeds of input kind KIND into directory OUT (emptied first): fuzz/corpus/KIND/,
# every file of the kind's extension under examples/ and, when installed, under the assimp test
# models (Debian's assimp-testmodels; SHADOWKIT_FUZZ_ASSIMP_MODELS overrides the path), up to
# 64 KiB each. File names keep their origin: examples_models_pebble.obj.
fuzz_collect_seeds() {
  local kind=$1 out=$2 ext models file
  ext=$(fuzz_extension "$kind")
  models=${SHADOWKIT_FUZZ_ASSIMP_MODELS:-/usr/share/assimp/models}
  rm -rf "$out"
  mkdir -p "$out"
  _fuzz_copy_seeds() {  # ROOT PREFIX FIND-ARGS...
    local root=$1 prefix=$2 rel
    shift 2
    [[ -d $root ]] || return 0
    while IFS= read -r -d '' file; do
      rel=${file#"$root"/}
      cp "$file" "$out/$prefix${rel//\//_}"
    done < <(find "$root" -type f "$@" -print0 | sort -z)
  }
  _fuzz_copy_seeds "$fuzz_dir/corpus/$kind" "corpus_"
  _fuzz_copy_seeds "$fuzz_root/examples" "examples_" -iname "*.$ext" -size -65k
  _fuzz_copy_seeds "$models" "assimp_" -iname "*.$ext" -size -65k
}

# The corpus directories target NAME replays before it mutates anything: its regression inputs
# and, for a render target, those of its load target too.
fuzz_regression_dirs() {
  local name=$1 kind
  kind=$(fuzz_kind "$name")
  [[ -d $fuzz_dir/regressions/$name ]] && echo "$fuzz_dir/regressions/$name"
  [[ $kind != "$name" && -d $fuzz_dir/regressions/$kind ]] && echo "$fuzz_dir/regressions/$kind"
  return 0
}

# libFuzzer options of every run of target NAME: the 20 s hang limit, the memory limit, the
# input size limit and the kind's dictionary.
fuzz_options() {
  local name=$1 kind
  kind=$(fuzz_kind "$name")
  echo -timeout=20 -rss_limit_mb=2048 -print_final_stats=1
  if [[ $kind == scene ]]; then
    echo -max_len=4096
  elif [[ $kind == frame_request ]]; then
    echo -max_len=2048  # the requests the page sends are a few hundred bytes
  elif [[ $kind == shading_groups ]]; then
    echo -max_len=1024  # each group is a column of the schedule's year of rows
  elif [[ $kind != "$name" ]]; then
    echo -max_len=16384  # render targets: odd geometry more than size
  else
    echo -max_len=65536
  fi
  [[ -f $fuzz_dir/dict/$kind.dict ]] && echo "-dict=$fuzz_dir/dict/$kind.dict"
  return 0
}

# Sanitizer settings for every run: stack traces for UBSan, every report fatal.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
