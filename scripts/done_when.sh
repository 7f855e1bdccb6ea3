#!/usr/bin/env bash
# Runs the campaigns that the open issues' "Done when" sections name and
# prints each criterion beside its target (scripts/done_when.py):
#   issue 24: open sea, 2/4/8/16 targets, constant and COLREGs-obeying, COUNT runs each;
#   issue 22: coastal (1/2/4/8 targets, COUNT/4 each) and TSS (westbound,
#             two-way, COUNT/2 each), constant and COLREGs-obeying.
# Usage: scripts/done_when.sh OUT [COUNT] [JOBS]   (defaults 1000, 2; seed 11)
# Every batch's wall and CPU seconds go to OUT/times.txt.
set -euo pipefail
out=${1:?usage: scripts/done_when.sh OUT [COUNT] [JOBS]}
count=${2:-1000}
jobs=${3:-2}
cd "$(dirname "$0")/.."
cargo build --release --quiet --bin vorrt
mkdir -p "$out"
# A copy, so that rebuilding meanwhile cannot change the binary mid-campaign.
cp target/release/vorrt "$out/vorrt"
: > "$out/times.txt"
run() {
    local name=$1
    shift
    local start
    start=$(date +%s.%N)
    /usr/bin/time -f "%U %S" -o "$out/$name.cpu" \
        "$out/vorrt" batch "$@" --seed 11 --jobs "$jobs" --out "$out/$name" > "$out/$name.log" 2>&1
    echo "$name $(echo "$(date +%s.%N) - $start" | bc) $(cat "$out/$name.cpu")" >> "$out/times.txt"
}
for behaviour in constant colregs; do
    for n in 2 4 8 16; do
        run "os$n-$behaviour" --generate open-sea --targets "$n" --count "$count" --behaviour "$behaviour"
    done
    for n in 1 2 4 8; do
        run "coastal$n-$behaviour" --generate coastal --targets "$n" --count $((count / 4)) --behaviour "$behaviour"
    done
    for direction in westbound two-way; do
        run "tss-$direction-$behaviour" --generate tss --direction "$direction" --count $((count / 2)) --behaviour "$behaviour"
    done
done
python3 scripts/done_when.py "$out"
