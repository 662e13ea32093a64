#!/bin/bash
# The 8000-case DOE as a Slurm job array: each task solves one contiguous slice of the cases.
# `--shard slurm` takes the slice from SLURM_ARRAY_TASK_ID, SLURM_ARRAY_TASK_MIN and
# SLURM_ARRAY_TASK_COUNT and writes build/doe_8000-shardIofN.h5 (without --shard the Slurm
# variables are ignored and every task would solve every case); --resume lets a requeued task
# continue from its checkpoint; -q keeps the log to errors only (no summary table, no progress
# lines; drop -q to see a progress line every 10 % or 10 s in shcontact-doe-N.log). Submit from
# the repository root:
#
#   jobid=$(sbatch --parsable examples/slurm_doe.sh)
#   sbatch --dependency=afterok:$jobid --wrap \
#       "shcontact merge build/doe_8000.h5 build/doe_8000-shard*of8.h5"
#
# The merged file is identical, dataset for dataset, to the file of an unsharded run.
# For one case file per array task (no slicing) leave --shard out, e.g.
#   shcontact run "cases/case_${SLURM_ARRAY_TASK_ID}.nml" -o "build/case_${SLURM_ARRAY_TASK_ID}.h5" -q
#SBATCH --job-name=shcontact-doe
#SBATCH --array=1-8
#SBATCH --cpus-per-task=2
#SBATCH --time=00:10:00
#SBATCH --output=shcontact-doe-%a.log
set -euo pipefail
export OMP_NUM_THREADS="${SLURM_CPUS_PER_TASK:-1}"
mkdir -p build
shcontact run examples/doe_8000.nml -o build/doe_8000.h5 --shard slurm --resume -q
