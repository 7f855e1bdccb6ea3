#!/usr/bin/env bash
# Merges the shards of scripts/slurm/campaign.sbatch into OUT/merged with
# `vorrt merge` (which refuses a missing shard or shards of another batch).
#   sbatch --dependency=afterok:JOBID scripts/slurm/merge.sh OUT
#SBATCH --job-name=vorrt-merge
#SBATCH --cpus-per-task=1
#SBATCH --output=vorrt-merge-%j.log
set -euo pipefail
out=${1:?usage: merge.sh OUT}
vorrt=${VORRT:-vorrt}
"$vorrt" merge "$out"/shards/* --out "$out/merged"
