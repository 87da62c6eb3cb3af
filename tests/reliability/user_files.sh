#!/bin/bash
# A run owns only what it wrote (block_compression, coarse): in an output
# directory that also holds the user's .prm (named like the run's base
# name), a mesh, notes and a subfolder, no mode of 'Output/Existing results'
# moves, deletes or changes any of them, run after run; the run's manifest
# lists every entry the run created and nothing of the user's; an empty
# base name is refused.
#   user_files.sh <block_compression> <its .prm> <work dir>
set -euo pipefail
exe=$1 prm=$2 work=$3
. "$(dirname "$0")/common.sh"
start_in_work_dir "$work" "$prm"
with_prm base.prm short.prm Time "set End time = 0.2"
mkdir run run/block_folder
cd run
echo "my notes" > notes.txt
echo "a file of my own" > block_folder/inside.txt
echo "not really a mesh" > block_mesh.msh
echo "an older input" > block-old.prm
user_entries="block.prm block-old.prm block_mesh.msh block_folder notes.txt"
checksum() { find $user_entries -type f -exec md5sum {} + | sort; }

manifest=softgrasp-run-files.txt
# every entry is the user's, the manifest, a moved-aside run or listed
expect_all_listed() {
  local entry
  for entry in $(ls -A); do
    case " $user_entries $manifest " in *" $entry "*) continue ;; esac
    case "$entry" in previous-run-*) continue ;; esac
    grep -qxF -- "$entry" "$manifest" || {
      echo "FAIL: '$entry' was written but is not in the manifest"
      cat "$manifest"; exit 1; }
  done
  for entry in $user_entries; do
    ! grep -qxF -- "$entry" "$manifest" || {
      echo "FAIL: the user's '$entry' is in the manifest"; exit 1; }
  done
}

for mode in "move aside" "replace" "refuse"; do
  with_prm ../short.prm block.prm Output "set Directory = ." \
    "set Base name = block" "set Existing results = $mode" \
    "set VTU interval = 1"
  before=$(checksum)
  want=0
  # refuse: the earlier runs' results are there, so it refuses
  [ "$mode" = refuse ] && want=1
  for attempt in 1 2; do
    run_expect $want "../run-$attempt.log" "$exe" block.prm
    [ "$(checksum)" = "$before" ] || {
      echo "FAIL: '$mode' changed the user's files"; checksum; exit 1; }
    expect_all_listed
  done
done
[ "$(cat notes.txt)" = "my notes" ] || { echo "FAIL: notes"; exit 1; }
[ -d previous-run-1 ] && [ ! -e previous-run-1/notes.txt ] || {
  echo "FAIL: 'move aside' moved a user's file"; exit 1; }
grep -qx "block_history.csv" previous-run-1/$manifest || {
  echo "FAIL: the moved run lost its manifest"; exit 1; }

# An empty base name would match every file: refused with the fix.
with_prm ../short.prm empty.prm Output "set Directory = out" "set Base name ="
run_expect 1 ../empty.log "$exe" empty.prm
expect_clean_error ../empty.log
expect_message ../empty.log "Parameter 'Output/Base name' is '': it must be a non-empty"
[ "$(checksum)" = "$before" ] || { echo "FAIL: a refused run touched files"; exit 1; }
# A manifest that is not a regular file (a folder, a link to a list of
# the user's) is refused by name; nothing it names is touched.
echo "block_history.csv" > ../my-list.txt
for kind in directory "symbolic link"; do
  rm -rf ../odd && mkdir ../odd
  echo "the user's history" > ../odd/block_history.csv
  if [ "$kind" = directory ]; then mkdir ../odd/$manifest
  else ln -s ../my-list.txt ../odd/$manifest; fi
  for mode in "move aside" "replace"; do
    with_prm ../short.prm ../odd.prm Output "set Directory = ../odd" \
      "set Base name = block" "set Existing results = $mode"
    run_expect 1 ../odd.log "$exe" ../odd.prm
    expect_clean_error ../odd.log
    expect_message ../odd.log "The run manifest '../odd/$manifest' is a $kind"
    [ "$(cat ../odd/block_history.csv)" = "the user's history" ] || {
      echo "FAIL: a run with a $kind as manifest touched a file"; exit 1; }
  done
done
[ "$(cat ../my-list.txt)" = "block_history.csv" ] || {
  echo "FAIL: the linked list was changed"; exit 1; }
echo "user files: all cases passed"
