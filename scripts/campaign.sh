#!/usr/bin/env bash
# Runs the Monte Carlo campaign of docs/evaluation.md: open sea with 2, 4, 8
# and 16 targets and the TSS at 1 and 3 targets per nm, under the four target
# behaviours, COUNT runs a row, into OUT/<kind>-<behaviour>/, with the wall
# time of each row in OUT/times.txt. Then prints the table:
#   scripts/campaign.sh OUT [COUNT] [JOBS]
#   python3 scripts/evaluation_table.py OUT
set -euo pipefail
out=${1:?usage: scripts/campaign.sh OUT [COUNT] [JOBS]}
count=${2:-1000}
jobs=${3:-2}
cd "$(dirname "$0")/.."
cargo build --release --quiet
mkdir -p "$out"
# A copy, so that rebuilding the checkout meanwhile cannot change the binary
# half way through the campaign.
cp target/release/vorrt "$out/vorrt"
vorrt=$out/vorrt
for behaviour in constant colregs noisy sudden-turn; do
    for kind in os2 os4 os8 os16 tss1 tss3; do
        case $kind in
            os*) args=(--generate open-sea --targets "${kind#os}") ;;
            tss*) args=(--generate tss --density "${kind#tss}") ;;
        esac
        dir="$out/$kind-$behaviour"
        start=$(date +%s)
        "$vorrt" batch "${args[@]}" --count "$count" --seed 11 --behaviour "$behaviour" \
            --jobs "$jobs" --out "$dir" > "$dir.log" 2>&1 || true
        echo "$kind-$behaviour $(( $(date +%s) - start )) s" >> "$out/times.txt"
    done
done
