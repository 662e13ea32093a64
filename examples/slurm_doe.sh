#!/bin/bash
# The 8000-case DOE as a Slurm job array: each task solves one contiguous slice of the cases.
# shcontact takes the slice from SLURM_ARRAY_TASK_ID, SLURM_ARRAY_TASK_MIN and
# SLURM_ARRAY_TASK_COUNT (no --shard needed) and writes doe_8000-shardIofN.h5; --resume lets a
# requeued task continue from its checkpoint. Submit from the repository root:
#
#   jobid=$(sbatch --parsable examples/slurm_doe.sh)
#   sbatch --dependency=afterok:$jobid --wrap \
#       "shcontact merge doe_8000.h5 doe_8000-shard*of8.h5"
#
# The merged file is identical, dataset for dataset, to the file of an unsharded run.
#SBATCH --job-name=shcontact-doe
#SBATCH --array=1-8
#SBATCH --cpus-per-task=2
#SBATCH --time=00:10:00
#SBATCH --output=shcontact-doe-%a.log
set -euo pipefail
export OMP_NUM_THREADS="${SLURM_CPUS_PER_TASK:-1}"
shcontact run examples/doe_8000.nml --resume -q
