#!/bin/bash
# Every program recognises another program's file (issue 55): each of the
# twelve programs is given every shipped .prm. A file of a program it does
# not read is refused before anything runs, with exit code 1, a clean
# 'Error:' and the name of the program the file is written for (its
# 'Program' entry); a file it reads passes a dry run (--dry-run: read and
# checked, nothing run or written) with exit code 0. The runs stop once the
# input is read, so the whole matrix takes seconds per program.
#   other_programs.sh <build dir> <source dir> <work dir>
set -euo pipefail
build=$1 source=$2 work=$3
. "$(dirname "$0")/common.sh"
rm -rf "$work" && mkdir -p "$work" && cd "$work"

# program -> executable (relative to the build directory)
declare -A exe=(
  [block_compression]=examples/block_compression/block_compression
  [cook_membrane]=examples/cook_membrane/cook_membrane
  [frictional_drag]=examples/frictional_drag/frictional_drag
  [hertz_indentation]=examples/hertz_indentation/hertz_indentation
  [ironing]=examples/ironing/ironing
  [tissue_curves]=examples/tissue_curves/tissue_curves
  [material_fit]=examples/material_fit/material_fit
  [sphere_squeeze]=studies/sphere_squeeze/sphere_squeeze
  [arm_grasp]=studies/arm_grasp/arm_grasp
  [grasp_pull_sweep]=studies/grasp_pull_sweep/grasp_pull_sweep
  [mujoco_grasp]=studies/mujoco_grasp/mujoco_grasp
  [softgrasp]=programs/softgrasp/softgrasp)
# the programs whose files a program reads besides its own
declare -A reads=(
  [softgrasp]="block_compression cook_membrane frictional_drag hertz_indentation ironing"
  [mujoco_grasp]="sphere_squeeze")

files=$(cd "$source" && git ls-files '*.prm' 2>/dev/null | grep -v '^tests/\|^doc/' ||
        find examples parameter-files programs -name '*.prm')
[ -n "$files" ] || { echo "FAIL: no shipped .prm files found"; exit 1; }
refused=0 read_ok=0
for file in $files; do
  # files from the source tree, runs in the work directory (nothing lands
  # in the source tree, whatever a program does)
  path=$source/$file
  written=$(sed -n 's/^set Program *= *//p' "$path" | head -1)
  [ -n "$written" ] || { echo "FAIL: '$file' has no 'set Program = ...' line"; exit 1; }
  [ -n "${exe[$written]:-}" ] || { echo "FAIL: '$file' names the unknown program '$written'"; exit 1; }
  for program in "${!exe[@]}"; do
    log=$work/$program-$(echo "$file" | tr / _).log
    if [ "$program" = "$written" ] || [[ " ${reads[$program]:-} " == *" $written "* ]]; then
      run_expect 0 "$log" "$build/${exe[$program]}" --dry-run "$path"
      expect_message "$log" "Dry run: '$path' was read as a $program file"
      read_ok=$((read_ok + 1))
    else
      run_expect 1 "$log" "$build/${exe[$program]}" "$path"
      expect_clean_error "$log"
      expect_message "$log" "is written for $written (its entry 'Program = $written'), and this program is $program"
      refused=$((refused + 1))
    fi
  done
done
echo "other programs' files: $refused refused by name, $read_ok read by a dry run"
