#!/usr/bin/env bash
# The library's floors (doc/architecture.md): a file in lib/{include/
# softgrasp,source}/<folder>/ may include softgrasp headers of its own
# folder and of lower floors only. Prints every include that points up or
# sideways and fails if there is one; run by the test style/floors.
# Usage: scripts/check-floors.sh [repository root]
set -euo pipefail
root=$(cd "${1:-$(dirname "$0")/..}" && pwd)
declare -A floor=(
  [base]=0
  [materials]=1 [meshes]=1 [rigid]=1
  [mechanics]=2
  [contact]=3
  [explicit]=4 [postprocess]=4
  [io]=5
  [solvers]=6
  [grasp]=7
  [mujoco]=8)
status=0 files=0 arrows=0
while IFS= read -r file; do
  from=$(sed -E 's#.*/(include/softgrasp|source)/([a-z_]+)/[^/]+$#\2#' <<<"$file")
  if [ -z "${floor[$from]:-}" ]; then
    echo "${file#$root/}: folder '$from' has no floor (add it to this script and doc/architecture.md)"
    status=1
    continue
  fi
  files=$((files + 1))
  while IFS= read -r to; do
    [ -n "$to" ] && [ "$to" != "$from" ] || continue
    arrows=$((arrows + 1))
    if [ -z "${floor[$to]:-}" ] || [ "${floor[$to]}" -ge "${floor[$from]}" ]; then
      echo "${file#$root/}: includes softgrasp/$to/ (floor ${floor[$to]:-?}) from $from (floor ${floor[$from]})"
      status=1
    fi
  done < <(sed -nE 's@^#include <softgrasp/([a-z_]+)/.*@\1@p' "$file" | sort -u)
done < <(find "$root/lib/include/softgrasp" "$root/lib/source" -name '*.h' -o -name '*.cc' | sort)
if [ $status = 0 ]; then
  echo "floors: $files files, $arrows folder-to-folder includes, all downward"
fi
exit $status
