#!/bin/bash
# Faults while a run writes (block_compression, coarse):
#  - a full disk (a small tmpfs; the test is skipped, exit 77, where
#    mounting is not allowed) stops the run with a message naming the
#    directory, on 1 and on 2 ranks, and leaves only complete files (every
#    VTU ends its XML, every PNG/CSV whole, no partial files) and the PVD
#    listing only complete VTU files;
#  - a write that fails on rank 0 only (the history file's name is taken by
#    a directory mid-run) ends the whole 2-rank job with the message, no
#    hang.
#   write_faults.sh <block_compression> <its .prm> <work dir>
set -euo pipefail
exe=$1 prm=$2 work=$3
. "$(dirname "$0")/common.sh"
start_in_work_dir "$work" "$prm" 1

check_whole() { # every file in $1 is complete
  if ls "$1" | grep -q '\.partial$'; then echo "FAIL: partial files left"; ls "$1"; exit 1; fi
  for f in "$1"/*.vtu; do
    [ "$(tail -c 11 "$f")" = "</VTKFile>" ] || { echo "FAIL: $f is truncated"; exit 1; }
  done
  for f in $(grep -o 'file="[^"]*"' "$1/block.pvd" | cut -d'"' -f2); do
    [ -f "$1/$f" ] || { echo "FAIL: the PVD lists the missing $f"; exit 1; }
  done
}

# Rank 0 alone fails: a directory takes the history file's name.
with_prm base.prm one.prm Output "set Directory = one" "set VTU interval = 0"
with_prm one.prm one-long.prm Time "set End time = 20"
timeout 300 mpirun -np 2 "$exe" one-long.prm > one.log 2>&1 &
job=$!
until [ "$(cat one/block_history.csv 2>/dev/null | wc -l)" -ge 3 ]; do
  kill -0 $job 2>/dev/null || { echo "FAIL: the run ended early"; cat one.log; exit 1; }
  sleep 0.05
done
until mkdir -p one/block_history.csv.partial/blocker 2>/dev/null; do sleep 0.01; done
code=0; wait $job || code=$?
[ "$code" != 0 ] && [ "$code" != 124 ] || { echo "FAIL: exit code $code"; cat one.log; exit 1; }
expect_message one.log "ending the whole job"
expect_message one.log "block_history.csv"

mkdir -p small
if ! mount -t tmpfs -o size=400k tmpfs small 2>/dev/null; then
  echo "cannot mount a small file system here: full-disk cases skipped"
  exit 77
fi
trap 'umount "$work/small" 2>/dev/null || true' EXIT
# VTU, PVD and CSV writes fail (no checkpoints), then checkpoints are
# refused for want of space before p4est is asked to write them.
for interval in 0 1; do
  for ranks in 1 2; do
    rm -rf small/out
    with_prm base.prm full.prm Output "set Directory = small/out"
    with_prm full.prm full-$interval.prm Checkpoint "set Interval = $interval"
    run_expect 1 full-$interval-$ranks.log mpirun -np $ranks "$exe" full-$interval.prm
    expect_clean_error full-$interval-$ranks.log
    expect_message full-$interval-$ranks.log "small/out"
    grep -qE "disk is not full|Not enough free disk space" full-$interval-$ranks.log || {
      echo "FAIL: the message does not name the full disk"; cat full-$interval-$ranks.log; exit 1; }
    check_whole small/out
  done
done
echo "write faults: all cases passed"
