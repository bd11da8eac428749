#!/usr/bin/env bash
# A Slurm array for the large closure corpora (docs/results.md): each task runs
# one shard of `bench_closure --pipeline` and writes shard-K.csv (a requeued task
# goes on after the rows it has); merge them with
#   build/bench/bench_closure --merge closure-out/shard-*.csv
# Submit from a clone of the repository after scripts/setup.sh, for example
#   sbatch --array=1-64 scripts/slurm-closure.sh 18     (4,461 inputs)
#   sbatch --array=1-512 scripts/slurm-closure.sh 20    (49,957 inputs)
#SBATCH --job-name=loom-closure
#SBATCH --cpus-per-task=1
#SBATCH --mem=4G
#SBATCH --time=12:00:00
set -euo pipefail
quads="${1:?usage: sbatch --array=1-N scripts/slurm-closure.sh QUADS}"
n="${SLURM_ARRAY_TASK_COUNT:?run under sbatch --array}"
k="${SLURM_ARRAY_TASK_ID:?run under sbatch --array}"
mkdir -p closure-out
exec build/bench/bench_closure --quads "$quads" --pipeline --shard "$k/$n" --csv "closure-out/shard-$k.csv" --resume
