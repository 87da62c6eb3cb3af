#!/bin/bash
# Every case of explicit_step in its own process (so that the peak memory
# is the case's own), with the vectorised and the reference force kernel,
# on 1 and 2 MPI ranks. Run from the repository root:
#   benchmarks/explicit_step.sh build/benchmarks/explicit_step
set -euo pipefail
exe=${1:-build/benchmarks/explicit_step}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
echo "ranks,kernel,element,dofs,cells,steps,ms_per_step,dof_steps_per_s,us_per_cell_step,contact_share,peak_kB_per_dof"
for ranks in 1 2; do
  for degree in 1 2; do
    for n in 18 40 68; do
      for kernel in reference vectorized; do
        printf '%s,' "$ranks"
        mpirun -np "$ranks" "$exe" "$degree" "$n" "$kernel"
      done
    done
  done
done
