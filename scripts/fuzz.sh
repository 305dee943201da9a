#!/usr/bin/env bash
# Coverage-guided fuzzing of what voxflame reads from users: the flame importer (flame files) and
# the preset reader (JSON). Builds the libFuzzer targets of fuzz/ with clang, ASan and UBSan in
# their own build directory (build-fuzz; the normal build is untouched), then runs each target for
# SECONDS (default 60) from a scratch copy of its seeds: the real flame files beside the repository
# (../shared/data/flames) and flam3's samples (/usr/share/flam3) for the importer, the shipped
# presets for the preset reader. A crash, an exception other than core::Error, undefined
# behaviour, a leak, a timeout (an input taking over 10 s), a huge allocation or running out of
# memory fails the script; the input that did it is kept under BUILD/fuzz-artifacts and its path
# printed with the command that reproduces it.
# Usage: scripts/fuzz.sh [SECONDS] [extra cmake args...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-60}"
shift || true
build="${VOXFLAME_FUZZ_BUILD:-$root/build-fuzz}"
targets=(flame_xml_fuzzer preset_fuzzer)

# -O1 keeps the sanitizers' reports readable and the build short; asserts stay on (no NDEBUG).
CC=clang CXX=clang++ VOXFLAME_BUILD_TYPE=RelWithDebInfo VOXFLAME_BUILD_TARGET="${targets[*]}" \
  "$root/scripts/setup.sh" "$build" -DVOXFLAME_FUZZ=ON -DVOXFLAME_TESTS=OFF \
  "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only" "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only" "$@"

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# Copies the seed files given into a fresh working corpus for one target; libFuzzer adds the
# inputs it finds there, so the repository and the shared data are never written.
seed() {
  local corpus="$1"
  shift
  mkdir -p "$corpus"
  local file count=0
  for file in "$@"; do
    if [ -f "$file" ]; then
      cp -- "$file" "$corpus/"
      count=$((count + 1))
    fi
  done
  echo "$count"
}

shopt -s nullglob
flame_seeds=("$root"/../shared/data/flames/*.flame "$root"/../shared/data/flames/*.flam3 /usr/share/flam3/*.flam3)
preset_seeds=("$root"/presets/*.json)
shopt -u nullglob

failed=()
run() {
  local name="$1" max_len="$2" options="$3"
  shift 3
  local corpus="$work/$name" artifacts="$build/fuzz-artifacts/$name" log="$build/fuzz-artifacts/$name.log"
  rm -rf "$artifacts"
  mkdir -p "$artifacts"
  local seeds
  seeds="$(seed "$corpus" "$@")"
  echo
  echo "=== $name: $seconds s from $seeds seed files"
  local status=0
  # Leaks are checked after every input (LeakSanitizer through libFuzzer); UBSan's first report
  # stops the run (the targets are built with -fno-sanitize-recover).
  # System libraries' one-time allocations (fontconfig's configuration, which text_wf reads) are
  # theirs: the suppressions CI's sanitizer stage uses apply here too.
  # shellcheck disable=SC2086 # $options holds zero or more flags
  ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=1" \
    LSAN_OPTIONS="${LSAN_OPTIONS:+$LSAN_OPTIONS:}suppressions=$root/.ci/lsan.supp:print_suppressions=0" \
    UBSAN_OPTIONS="${UBSAN_OPTIONS:+$UBSAN_OPTIONS:}print_stacktrace=1:halt_on_error=1" \
    "$build/fuzz/$name" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len="$max_len" \
    -dict="$root/fuzz/${name%_fuzzer}.dict" -use_value_profile=1 -print_final_stats=1 $options \
    -artifact_prefix="$artifacts/" "$corpus" >"$log" 2>&1 || status=$?
  grep -E '^#[0-9]+[[:space:]]+DONE|^stat::(number_of_executed_units|average_exec_per_sec|peak_rss_mb|new_units_added)' "$log" || true
  local found=("$artifacts"/*)
  if [ "$status" -ne 0 ] || [ -e "${found[0]}" ]; then
    tail -n 60 "$log"
    echo "$name FAILED (exit $status); the whole log: $log"
    local file
    for file in "${found[@]}"; do
      [ -e "$file" ] && echo "reproducer: $file  (run: $build/fuzz/$name $file)"
    done
    failed+=("$name")
  else
    echo "$name: clean"
  fi
}

# Real flame files run to 220 kB; 16 kB inputs keep the runs fast and still hold whole flames (a
# longer seed is cut, which the tolerant reading of broken XML then meets).
# The importer's corpus grows to thousands of features per input: libFuzzer's entropic schedule
# then spends most of the time ranking them (a quarter of the executions), so plain scheduling.
run flame_xml_fuzzer 16384 "-entropic=0" "${flame_seeds[@]}"
run preset_fuzzer 32768 "" "${preset_seeds[@]}"

if [ ${#failed[@]} -gt 0 ]; then
  echo
  echo "fuzzing found problems in: ${failed[*]}"
  exit 1
fi
echo
echo "fuzzing: every target ran $seconds s without a problem"
