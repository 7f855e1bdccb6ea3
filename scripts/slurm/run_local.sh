#!/usr/bin/env bash
# Runs the job array of campaign.sbatch here, without Slurm: each task with
# SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT set as Slurm sets them,
# one after another, then merge.sh. For tests and small campaigns.
#   scripts/slurm/run_local.sh TASKS OUT [BATCH OPTIONS...]
set -euo pipefail
tasks=${1:?usage: run_local.sh TASKS OUT [BATCH OPTIONS...]}
out=${2:?usage: run_local.sh TASKS OUT [BATCH OPTIONS...]}
shift 2
here=$(dirname "$0")
for ((task = 0; task < tasks; task++)); do
    SLURM_ARRAY_TASK_ID=$task SLURM_ARRAY_TASK_COUNT=$tasks \
        bash "$here/campaign.sbatch" "$out" "$@"
done
bash "$here/merge.sh" "$out"
