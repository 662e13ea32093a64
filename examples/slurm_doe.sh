#!/bin/bash
# A sweep spread over several nodes as a Slurm job array: one task per node, with all the
# node's cores (OpenMP threads), each solving one contiguous slice of the cases; then one merge.
# `--shard slurm` takes the slice from SLURM_ARRAY_TASK_ID, SLURM_ARRAY_TASK_MIN and
# SLURM_ARRAY_TASK_COUNT and writes build/doe_8000-shardIofN.h5 (without --shard the Slurm
# variables are ignored and every task would solve every case); --resume lets a requeued task
# continue from its checkpoint; -q keeps the log to errors only (drop -q to see a progress line
# every 10 % or 10 s in shcontact-doe-N.log, add -v for the largest checkpoint block and the
# peak memory). Submit from the repository root:
#
#   jobid=$(sbatch --parsable examples/slurm_doe.sh)
#   sbatch --dependency=afterok:$jobid --wrap \
#       "shcontact merge build/doe_8000.h5 build/doe_8000-shard*of4.h5"
#
# The merged file is identical, dataset for dataset, to the file of an unsharded run (and of
# any other thread count). Size the array with doc/app.md "Large sweeps": the cases per second
# of one node, the memory (--block-memory, default 64 MiB, plus about 30 MB) and the file size
# per case. For one case file per array task (no slicing) leave --shard out, e.g.
#   shcontact run "cases/case_${SLURM_ARRAY_TASK_ID}.nml" -o "build/case_${SLURM_ARRAY_TASK_ID}.h5" -q
#SBATCH --job-name=shcontact-doe
#SBATCH --array=1-4
#SBATCH --nodes=1
#SBATCH --ntasks=1
#SBATCH --exclusive
#SBATCH --cpus-per-task=16
#SBATCH --time=00:10:00
#SBATCH --output=shcontact-doe-%a.log
set -euo pipefail
# All the cores Slurm gave the task, one OpenMP thread each, kept on their cores.
export OMP_NUM_THREADS="${SLURM_CPUS_PER_TASK:-1}"
export OMP_PROC_BIND="${OMP_PROC_BIND:-close}"
export OMP_PLACES="${OMP_PLACES:-cores}"
mkdir -p build
# Status 4 (some cases failed; the shard's file is written and lists them under /failures) is
# a finished task, so that the afterok merge above runs; the merge then exits 4 itself and
# names the failed cases. Any other non-zero status fails the task.
status=0
shcontact run examples/doe_8000.nml -o build/doe_8000.h5 --shard slurm --resume -q || status=$?
if [ "$status" -eq 4 ]; then status=0; fi
exit "$status"
