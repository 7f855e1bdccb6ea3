#!/usr/bin/env bash
# Runs each cargo-fuzz target of fuzz/ for a fixed time, one after the other,
# on the stable toolchain without a sanitizer (`-s none`), at low priority.
#
#   scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]
#
# SECONDS_PER_TARGET defaults to 600. TARGETs default to every target
# (scenario_parser, planner, ais_reader). Needs `cargo install cargo-fuzz --locked`.
# The corpora grow in fuzz/corpus/<target>/ (git-ignored), seeded from the
# committed fuzz/seeds/<target>/; a crash is saved under fuzz/artifacts/.
# libFuzzer's last lines (`#N ... DONE`) give the executions; each run's log
# is kept in fuzz/target/logs/<target>.log (git-ignored).
set -euo pipefail

seconds="${1:-600}"
shift || true
targets=("$@")
if [ "${#targets[@]}" -eq 0 ]; then
    targets=(scenario_parser planner ais_reader)
fi

root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root/fuzz"
mkdir -p target/logs

for target in "${targets[@]}"; do
    mkdir -p "corpus/$target"
    cp -n "seeds/$target"/* "corpus/$target/" 2>/dev/null || true
    echo "fuzzing $target for $seconds s"
    # -timeout: any single input taking more than 10 s counts as a hang.
    set +e
    nice -n 10 cargo +stable fuzz run -s none "$target" "corpus/$target" -- \
        -max_total_time="$seconds" -timeout=10 -print_final_stats=1 \
        >"target/logs/$target.log" 2>&1
    status=$?
    set -e
    grep -E '^(#[0-9]+.*DONE|Done [0-9]+ runs|stat::number_of_executed_units|==[0-9]+== ERROR)' \
        "target/logs/$target.log" || true
    if [ "$status" -ne 0 ]; then
        echo "fuzz target $target failed (exit $status); see fuzz/target/logs/$target.log" >&2
        exit "$status"
    fi
done
