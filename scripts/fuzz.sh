#!/usr/bin/env bash
# Runs a fuzzer campaign and keeps what it found new in the repository's corpus:
#
#   scripts/fuzz.sh scene|api|restore|tiled [SECONDS]     (default 600)
#
# Sets up (scripts/setup.sh), builds the asan preset (clang, ASan + UBSan, libFuzzer),
# then fuzzes in build-asan/fuzz-work/TARGET, starting from tests/fuzz/corpus/TARGET. The
# api fuzzer has two modes (tests/fuzz/fuzz_api.cpp): chaos gets two thirds of the time,
# settled one third, each in a campaign of its own, since left together libFuzzer spends
# nearly all its time on the slow settled inputs. At the end the inputs that add coverage
# are merged into tests/fuzz/corpus/TARGET (libFuzzer's -merge=1: the corpus grows by
# what is new, not by everything tried), and the executions and findings are printed.
# A finding is saved as build-asan/fuzz-work/TARGET/crash-* (or leak-, timeout-, oom-);
# reproduce it with build-asan/tests/fuzz/fuzz_TARGET FILE.
set -euo pipefail
cd "$(dirname "$0")/.."

target=${1:-}
seconds=${2:-600}
case "$target" in
scene | api | restore | tiled) ;;
*)
    echo "usage: scripts/fuzz.sh scene|api|restore|tiled [SECONDS]" >&2
    exit 2
    ;;
esac

scripts/setup.sh
cmake --preset asan >/dev/null
cmake --build --preset asan -j"$(nproc)" --target "fuzz_$target"

fuzzer=build-asan/tests/fuzz/fuzz_$target
corpus=tests/fuzz/corpus/$target
work=build-asan/fuzz-work/$target
mkdir -p "$work/corpus" "$corpus"
options=(-timeout=20 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$work/")
seeds=("$corpus")
if [ "$target" = scene ]; then
    options+=(-dict=tests/fuzz/scene.dict)
    seeds+=(examples/scenes)
elif [ "$target" = tiled ]; then
    # Tiled's maps (tests/fuzz/fuzz_tiled.cpp): the test maps are seeds too.
    options+=(-max_len=16384)
    seeds+=(tests/level/maps)
elif [ "$target" = api ]; then
    # Programs need room: let inputs grow to the longest allowed from the start.
    options+=(-max_len=4096 -len_control=0)
else
    # Snapshots of busy worlds run to some kilobytes.
    options+=(-max_len=32768 -len_control=0)
fi

executions=0
campaign() { # MODE SECONDS
    local log="$work/${1:-fuzz}.log"
    echo "fuzz: $target${1:+ ($1)} for $2 s"
    local status=0
    JOSTLE_FUZZ_MODE=$1 "$fuzzer" "${options[@]}" -max_total_time="$2" \
        "$work/corpus" "${seeds[@]}" >"$log" 2>&1 || status=$?
    local runs
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    executions=$((executions + ${runs:-0}))
    echo "fuzz:   ${runs:-0} executions, exit status $status (log: $log)"
    grep -E "fuzz_[a-z]+ finding|ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error" \
        "$log" | head -5 || true
}

if [ "$target" = api ]; then
    campaign chaos $((seconds * 2 / 3))
    campaign settled $((seconds - seconds * 2 / 3))
else
    campaign "" "$seconds"
fi

before=$(find "$corpus" -type f | wc -l)
# Edges, not hit counts: a corpus of what reaches new code stays small.
"$fuzzer" -merge=1 -use_counters=0 -artifact_prefix="$work/" "$corpus" "$work/corpus" >"$work/merge.log" 2>&1
after=$(find "$corpus" -type f | wc -l)
findings=$(find "$work" -maxdepth 1 \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' \
    -o -name 'oom-*' \) | wc -l)
echo "fuzz: $target: $executions executions in $seconds s; corpus $corpus: $before -> $after files"
echo "fuzz: $findings findings in $work"
[ "$findings" -eq 0 ]
