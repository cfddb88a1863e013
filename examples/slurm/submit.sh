#!/bin/bash
# Submits a sweep to Slurm as a job array of TASKS shards, and its merge as a job that starts
# when every shard has succeeded (--dependency=afterok). Extra arguments go to both sbatch calls
# (--partition=…, --account=…, --cpus-per-task=…).
#
#   examples/slurm/submit.sh SPEC.ron OUT_DIR TASKS [sbatch options…]
#
# Prints the two job ids. If a shard fails, the merge never starts (squeue shows it
# DependencyNeverSatisfied): fix the cause, resubmit the array (its tasks --resume), and submit
# merge.sbatch again.
set -euo pipefail
usage="usage: $0 SPEC.ron OUT_DIR TASKS [sbatch options…]"
spec=${1:?$usage}
out=${2:?$usage}
tasks=${3:?$usage}
shift 3
here=$(cd "$(dirname "$0")" && pwd)
array=$(sbatch --parsable --array="0-$((tasks - 1))" "$@" "$here/sweep.sbatch" "$spec" "$out")
array=${array%%;*} # "id;cluster" on a multi-cluster setup
merge=$(sbatch --parsable --dependency="afterok:$array" "$@" "$here/merge.sbatch" "$out")
merge=${merge%%;*}
echo "array job $array ($tasks tasks), merge job $merge"
