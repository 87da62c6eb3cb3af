#!/bin/bash
# Output that never mixes or destroys runs (block_compression, coarse):
#  - a second run moves the first run's results aside ('move aside'), or
#    refuses ('refuse'), or deletes them ('replace');
#  - a run refuses a directory locked by a live run, takes over the lock
#    of a killed one, removes its lock when it ends, and names a damaged
#    lock as damaged;
#  - an output directory that is a file, or not writable, ends a 2-rank
#    run with the message (no hang).
#   output_directory.sh <block_compression> <its .prm> <work dir>
set -euo pipefail
exe=$1 prm=$2 work=$3
. "$(dirname "$0")/common.sh"
start_in_work_dir "$work" "$prm"
with_prm base.prm short.prm Time "set End time = 0.2"
with_prm short.prm run.prm Output "set Directory = out"
run_expect 0 first.log "$exe" run.prm
[ "$(($(wc -l < out/block_history.csv) - 1))" = 5 ] || { echo "FAIL: first run"; exit 1; }

# A second, longer run: the first run's files move aside as a whole.
with_prm base.prm second.prm Output "set Directory = out"
run_expect 0 second.log "$exe" second.prm
expect_message second.log "to 'out/previous-run-1'"
[ "$(($(wc -l < out/previous-run-1/block_history.csv) - 1))" = 5 ] || {
  echo "FAIL: the first run's history was not kept whole"; exit 1; }
[ "$(($(wc -l < out/block_history.csv) - 1))" = 21 ] || {
  echo "FAIL: the second run's history is not its own"; exit 1; }
[ "$(ls out/*.vtu | wc -l)" = 2 ] || { echo "FAIL: VTU files of two runs mixed"; exit 1; }
[ ! -e out/.softgrasp.lock ] || { echo "FAIL: the lock was left behind"; exit 1; }

with_prm run.prm refuse.prm Output "set Existing results = refuse"
run_expect 1 refuse.log "$exe" refuse.prm
expect_clean_error refuse.log
expect_message refuse.log "holds the results of an earlier run"
[ "$(($(wc -l < out/block_history.csv) - 1))" = 21 ] || {
  echo "FAIL: a refused run touched the earlier results"; exit 1; }

with_prm run.prm replace.prm Output "set Existing results = replace"
run_expect 0 replace.log "$exe" replace.prm
[ "$(($(wc -l < out/block_history.csv) - 1))" = 5 ] || { echo "FAIL: replace"; exit 1; }
[ -d out/previous-run-1 ] && [ ! -d out/previous-run-2 ] || { echo "FAIL: replace moved files"; exit 1; }

# A live run holds the directory: refused. A killed run's lock is taken over.
sleep 600 &
holder=$!
echo "$(hostname) $holder" > out/.softgrasp.lock
run_expect 1 locked.log "$exe" replace.prm
expect_message locked.log "Another run (process $holder on host"
kill $holder; wait $holder 2>/dev/null || true
run_expect 0 stale.log "$exe" replace.prm
[ ! -e out/.softgrasp.lock ] || { echo "FAIL: the stale lock was left"; exit 1; }

# A damaged lock (empty, or without a process id) is reported as damaged,
# not as a live run of "process 0 on host ''".
for content in "" "garbage"; do
  printf '%s' "$content" > out/.softgrasp.lock
  run_expect 1 damaged-lock.log "$exe" replace.prm
  expect_clean_error damaged-lock.log
  expect_message damaged-lock.log "out/.softgrasp.lock' of the output directory 'out' is damaged"
done
rm out/.softgrasp.lock

# The output directory is a file, or is not writable: the whole 2-rank job
# ends with the message.
touch a-file
with_prm short.prm file.prm Output "set Directory = a-file"
run_expect 1 file.log mpirun -np 2 "$exe" file.prm
expect_message file.log "'Output/Directory' = 'a-file' is a file, not a directory"
with_prm short.prm nested.prm Output "set Directory = a-file/sub"
run_expect 1 nested.log mpirun -np 2 "$exe" nested.prm
expect_message nested.log "Cannot create the output directory 'a-file/sub'"
echo "output directory: all cases passed"
