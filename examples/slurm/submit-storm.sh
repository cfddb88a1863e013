#!/bin/bash
# Submits a storm (docs/design-loads.md) to Slurm as a job array of TASKS slices of its seeds,
# and its report as a job that starts when every slice has succeeded (--dependency=afterok).
# STORM_ARGS (one string) go to each task's tether storm (--hours 3 --seeds 10 --warmup 600 …),
# REPORT_ARGS to the report (--code dnv-os-e301 …); extra arguments go to both sbatch calls.
#
#   STORM_ARGS="--hours 3 --seeds 10" examples/slurm/submit-storm.sh SCENE.ron OUT_DIR TASKS [sbatch options…]
#
# Prints the two job ids.
set -euo pipefail
usage="usage: $0 SCENE.ron OUT_DIR TASKS [sbatch options…]"
scene=${1:?$usage}
out=${2:?$usage}
tasks=${3:?$usage}
shift 3
here=$(cd "$(dirname "$0")" && pwd)
read -r -a storm_args <<<"${STORM_ARGS:-}"
read -r -a report_args <<<"${REPORT_ARGS:-}"
array=$(sbatch --parsable --array="0-$((tasks - 1))" "$@" "$here/storm.sbatch" "$scene" "$out" "${storm_args[@]}")
array=${array%%;*} # "id;cluster" on a multi-cluster setup
report=$(sbatch --parsable --dependency="afterok:$array" "$@" "$here/storm-report.sbatch" "$out" "${report_args[@]}")
report=${report%%;*}
echo "array job $array ($tasks tasks), report job $report"
