#!/usr/bin/env bash
# Regenerate the golden files tests/<category>/<name>[.mpirun=N].output from
# fresh runs of the tests. A test whose build or run fails (a failed physics
# check aborts the run) keeps its old golden file and makes this script fail:
# golden files only ever record output whose physics checks passed.
#
# Usage: scripts/regenerate-golden-outputs.sh [build-dir] [regex] [variant]
#   build-dir  a configured build tree (default: build)
#   regex      only tests whose name matches (default: all)
#   variant    write <name>.output.<variant> instead, for a machine whose
#              floating-point results differ in the last printed digits
#              (e.g. "avx2": the SIMD width of the vectorised kernels
#              changes the order of sums). deal.II's harness accepts a
#              test's output if it matches the golden file or any variant.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
filter=${2:-.}
machine=${3:-}
type=$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build/CMakeCache.txt" | tr A-Z a-z)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

status=0
cd "$root"
while IFS= read -r golden; do
  category=$(basename "$(dirname "$golden")")
  file=$(basename "$golden" .output)
  name=${file%%.*}
  variant=""
  [[ "$file" =~ mpirun=([0-9]+) ]] && variant="mpirun=${BASH_REMATCH[1]}"
  test="$category/$name${variant:+.$variant}.$type"
  [[ "$test" =~ $filter ]] || continue
  log=$(ctest --test-dir "$build" -R "^${test//./\\.}\$" 2>&1 </dev/null || true)
  run_dir="$build/tests/$category/$name.$type${variant:+/$variant}"
  if grep -qE "BUILD failed|RUN failed|No tests were found" <<<"$log" ||
     [ ! -s "$run_dir/output" ]; then
    echo "FAILED to run $test; golden file kept:" >&2
    grep -E "failed|FAILED|CHECK" <<<"$log" | head -5 >&2 || true
    status=1
    continue
  fi
  target=$golden${machine:+.$machine}
  cp "$run_dir/output" "$target"
  echo "regenerated $target"
done < <(find tests -name '*.output' | sort)
exit $status
