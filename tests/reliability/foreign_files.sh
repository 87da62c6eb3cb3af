#!/bin/bash
# A run touches only files it can prove it wrote (block_compression,
# coarse; issue 55): its manifest records each file's size and checksum,
# and 'Existing results' moves or deletes an entry only if it matches.
#  - a folder without a manifest holding the user's own files of the run's
#    names: they are moved aside (and said so), never written over;
#  - a manifest that lists more than the run wrote (a user's notes, the
#    running .prm with 'Directory = .'), or a result the user edited since:
#    'replace' and 'move aside' leave those entries as they are;
#  - a foreign or damaged manifest is refused by name, nothing touched;
#  - a shorter rerun after a run without (or with a truncated) manifest:
#    the stale VTU files are named in a warning and kept out of the PVD.
# After every case the user's files are byte-identical, wherever they are.
#   foreign_files.sh <block_compression> <its .prm> <work dir>
set -euo pipefail
exe=$1 prm=$2 work=$3
. "$(dirname "$0")/common.sh"
start_in_work_dir "$work" "$prm"
manifest=softgrasp-run-files.txt
# run_in <dir> <end time> <mode> <log>: the example into <dir>, every step.
run_in() {
  with_prm base.prm case.prm Time "set End time = $2"
  with_prm case.prm "run.prm" Output "set Directory = $1" \
    "set Base name = block" "set Existing results = $3" "set VTU interval = 1"
  run_expect 0 "$4" "$exe" run.prm
}
# same <file> <text>: the file holds exactly the text.
same() {
  [ -f "$1" ] && [ "$(cat "$1")" = "$2" ] || {
    echo "FAIL: '$1' is not the user's file any more"; ls -la "$(dirname "$1")"; exit 1; }
}

# 1. No manifest, the user's own history and PVD of the run's names.
mkdir mine
echo "my history" > mine/block_history.csv
echo "my pvd" > mine/block.pvd
run_in mine 0.2 "move aside" mine.log
expect_message mine.log "Moved 'mine/block_history.csv', which this run did not write"
expect_message mine.log "to 'mine/moved-aside-1'"
same mine/moved-aside-1/block_history.csv "my history"
same mine/moved-aside-1/block.pvd "my pvd"
[ "$(($(wc -l < mine/block_history.csv) - 1))" = 5 ] || { echo "FAIL: no run history"; exit 1; }

# 2. A manifest that lists more than the run wrote, and a result edited by
#    the user since: neither 'replace' nor 'move aside' touches them.
for mode in replace "move aside"; do
  rm -rf more && mkdir more
  run_in more 0.2 replace more-1.log
  echo "my notes" > more/notes.txt
  echo "notes.txt" >> more/$manifest
  echo "my edit" >> more/block_history.csv
  cp more/block_history.csv edited.csv
  run_in more 0.2 "$mode" more-2.log
  expect_message more-2.log "do not match the proof it records"
  expect_message more-2.log "'notes.txt'"
  same more/notes.txt "my notes"
  # the edited history is the user's now: moved aside, not overwritten
  cmp -s edited.csv more/moved-aside-1/block_history.csv || {
    echo "FAIL: '$mode' lost the edited history"; exit 1; }
done

# 3. 'Directory = .' and the running .prm listed in the manifest by hand.
rm -rf here && mkdir here && cd here
with_prm ../base.prm case.prm Time "set End time = 0.2"
with_prm case.prm here.prm Output "set Directory = ." "set Base name = block" \
  "set Existing results = replace"
cp here.prm here.copy
run_expect 0 ../here-1.log "$exe" here.prm
echo "here.prm" >> $manifest
for mode in replace "move aside"; do
  sed -i "s/set Existing results = .*/set Existing results = $mode/" here.prm
  cp here.prm here.copy
  run_expect 0 ../here-2.log "$exe" here.prm
  cmp -s here.prm here.copy || { echo "FAIL: '$mode' touched the running .prm"; exit 1; }
  expect_message ../here-2.log "'here.prm'"
  echo "here.prm" >> $manifest
done
cd ..

# 4. A foreign or a damaged manifest: refused by name; nothing touched.
for kind in foreign damaged; do
  rm -rf odd && mkdir odd
  echo "my history" > odd/block_history.csv
  if [ $kind = foreign ]; then printf 'block_history.csv\n' > odd/$manifest
  else printf '# softgrasp run manifest, format 2\n../base.prm\n' > odd/$manifest; fi
  with_prm base.prm odd.prm Output "set Directory = odd" "set Base name = block"
  run_expect 1 odd.log "$exe" odd.prm
  expect_clean_error odd.log
  if [ $kind = foreign ]; then
    expect_message odd.log "The file 'odd/$manifest' is not a softgrasp run manifest"
  else
    expect_message odd.log "The run manifest 'odd/$manifest' is damaged: its line 2 ('../base.prm')"
  fi
  same odd/block_history.csv "my history"
  [ "$(ls odd | wc -l)" = 2 ] || { echo "FAIL: a refused run wrote files"; ls odd; exit 1; }
done

# 5. A longer run without a manifest, then a shorter one: no mixing.
for damage in removed truncated; do
  rm -rf mixed && mkdir mixed
  run_in mixed 0.4 replace mixed-1.log
  if [ $damage = removed ]; then rm mixed/$manifest
  else head -n 4 mixed/$manifest > cut && mv cut mixed/$manifest; fi
  run_in mixed 0.2 replace mixed-2.log
  expect_message mixed-2.log "also holds"
  expect_message mixed-2.log "'block_00008.vtu'"
  ! grep -q "block_0000[5-8]" mixed/block.pvd || {
    echo "FAIL: the PVD lists another run's files"; exit 1; }
  [ -f mixed/block_00008.vtu ] || { echo "FAIL: an unproven file was deleted"; exit 1; }
done
echo "foreign files: all cases passed"
