#!/usr/bin/env bash
# Runs one fuzz target for a time, from a scratch corpus seeded with tests/fuzz/corpus/<format>,
# the samples of share/data and the files of tests/data/formats and tests/data/bonds in that format:
#   bash tests/fuzz/fuzz.sh <build dir> <format> <seconds>
# The scratch corpus (<build dir>/fuzz-corpus/<format>) grows from run to run; crashes, leaks and
# inputs slower than 10 s land in <build dir>/fuzz-artifacts/<format>/. Prints libFuzzer's final
# statistics (runs, executions per second, coverage).
set -euo pipefail
source_dir="$(cd "$(dirname "$0")/../.." && pwd)"
build=$1 format=$2 seconds=$3
target="$build/tests/fuzz/fuzz_reader_$format"
[[ -x "$target" ]] || { echo "fuzz.sh: no $target; build the target fuzz_reader_$format" >&2; exit 2; }
corpus="$build/fuzz-corpus/$format"
artifacts="$build/fuzz-artifacts/$format/"
mkdir -p "$corpus" "$artifacts"
seeds=()
[[ -d "$source_dir/tests/fuzz/corpus/$format" ]] && seeds=("$source_dir/tests/fuzz/corpus/$format")
shopt -s globstar nullglob
for sample in "$source_dir"/share/data/* "$source_dir"/tests/data/{formats,bonds}/**/*; do
    case "$format" in
    lammps) [[ "$sample" == *.lammpstrj || "$sample" == *.dump ]] ;;
    lammpsdata) [[ "$sample" == *.data ]] ;;
    *) [[ "$sample" == *."$format" || ( "$format" == xyz && "$sample" == *.extxyz ) ]] ;;
    esac && cp -n "$sample" "$corpus/" || true
done
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
log="$build/fuzz-artifacts/$format.log"
status=0
"$target" "$corpus" ${seeds[@]+"${seeds[@]}"} -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len=65536 -print_final_stats=1 -artifact_prefix="$artifacts" >"$log" 2>&1 || status=$?
grep -E '^(#[0-9]+ +(INITED|DONE)|stat::|INFO: seed corpus|SUMMARY)|ERROR|==[0-9]+==' "$log" || true
echo "fuzz.sh: $format: exit $status, log $log"
exit $status
