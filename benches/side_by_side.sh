#!/usr/bin/env bash
# Criterion suites of two checkouts, run alternately in one session, so that
# their medians can be compared on a shared, noisy machine (docs/performance.md).
#
#   git worktree add ../vorrt-old <OLD_COMMIT>
#   benches/side_by_side.sh ../vorrt-old [ROUNDS] [OUT_DIR]
#   python3 benches/side_by_side.py [OUT_DIR]
#
# Each round runs, for the old checkout and then this one, the geometry
# suite, the `plan/*` benchmarks of the planner suite and the closed-loop
# suite; criterion writes each run's estimates to
# OUT_DIR/<old|new>/round<N>/ (CRITERION_HOME). ROUNDS defaults to 3,
# OUT_DIR to target/side_by_side. The old checkout builds into
# $OLD_TARGET_DIR (default <old>/target), this one into $CARGO_TARGET_DIR
# (default target). WARM_UP_S and MEASURE_S (default 1 and 2) set the times
# of the benchmarks whose group does not fix them in code; SUITES (default
# "geometry planner closed_loop") chooses the suites.
set -euo pipefail

old_dir=$(cd "${1:?usage: benches/side_by_side.sh OLD_CHECKOUT [ROUNDS] [OUT_DIR]}" && pwd)
rounds=${2:-3}
new_dir=$(cd "$(dirname "$0")/.." && pwd)
out=$(mkdir -p "${3:-$new_dir/target/side_by_side}" && cd "${3:-$new_dir/target/side_by_side}" && pwd)
old_target=$(realpath -m "${OLD_TARGET_DIR:-$old_dir/target}")
new_target=$(realpath -m "${CARGO_TARGET_DIR:-$new_dir/target}")
warm_up_s=${WARM_UP_S:-1}
measure_s=${MEASURE_S:-2}

run_suites() { # side dir target_dir round
    local side=$1 dir=$2 target=$3 round=$4
    local home="$out/$side/round$round"
    mkdir -p "$home"
    for suite in ${SUITES:-geometry planner closed_loop}; do
        local filter=""
        [ "$suite" = planner ] && filter='^plan/'
        echo "== round $round, $side, $suite ($(uptime | sed 's/.*load average: //'))"
        (cd "$dir" && CARGO_TARGET_DIR="$target" CRITERION_HOME="$home" \
            cargo bench -q --no-default-features --bench "$suite" -- \
            --warm-up-time "$warm_up_s" --measurement-time "$measure_s" --noplot $filter) \
            >"$home/$suite.out" 2>"$home/$suite.err"
    done
}

for side_dir in "old:$old_dir:$old_target" "new:$new_dir:$new_target"; do
    IFS=: read -r side dir target <<<"$side_dir"
    echo "building $side ($dir)"
    (cd "$dir" && CARGO_TARGET_DIR="$target" cargo bench -q --no-default-features --no-run)
done
for round in $(seq 1 "$rounds"); do
    run_suites old "$old_dir" "$old_target" "$round"
    run_suites new "$new_dir" "$new_target" "$round"
done
echo "done: python3 benches/side_by_side.py $out"
