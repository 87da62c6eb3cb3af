#!/bin/bash
# Checkpoint/restart test: run the block_compression example to the end
# (reference), run it again and SIGKILL it mid-way after some checkpoints,
# resume it with "set Resume = true", and compare the final history with the
# reference (every column but the wall time) with numdiff. With a rank
# count, every run uses mpirun on that many ranks and the kill hits the
# whole job (mpirun and its ranks) at once; the resume takes over the dead
# run's lock of the output directory.
#   kill_and_resume.sh <block_compression executable> <its .prm> <work dir>
#                      [MPI ranks]
set -euo pipefail
exe=$1
prm=$2
work=$3
ranks=${4:-}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
launch=()
if [ -n "$ranks" ]; then launch=(mpirun -np "$ranks"); fi
rm -rf "$work"
mkdir -p "$work"
cd "$work"

# A coarse, quick variant of the example.
sed -e 's/set Global refinements = 1/set Global refinements = 0/' \
    -e 's/set VTU interval   = 5/set VTU interval = 0/' "$prm" > base.prm
sed -e 's/set Directory      = .*/set Directory = reference/' base.prm > reference.prm
sed -e 's/set Directory      = .*/set Directory = killed/' base.prm > killed.prm
sed -e 's/set Resume   = false/set Resume = true/' killed.prm > resume.prm
grep -q "set Resume = true" resume.prm

"${launch[@]}" "$exe" reference.prm > reference.log

# In a session of its own, so that one kill reaches every process of it.
setsid "${launch[@]}" "$exe" killed.prm > killed.log 2>&1 &
pid=$!
# Wait for step 6 to be recorded, then kill without warning.
until grep -q "^6," killed/block_history.csv 2>/dev/null; do
  if ! kill -0 $pid 2>/dev/null; then
    echo "FAIL: the run ended before it could be killed"; exit 1
  fi
  sleep 0.02
done
kill -9 -- -$pid
wait $pid 2>/dev/null || true
sleep 0.5
steps_before=$(($(wc -l < killed/block_history.csv) - 1))
echo "killed after $steps_before recorded steps"
if grep -q "^20," killed/block_history.csv; then
  echo "FAIL: the run had finished before the kill"; exit 1
fi

"${launch[@]}" "$exe" resume.prm > resume.log
grep -q "Resumed from the checkpoint at step" resume.log
if [ -e killed/.softgrasp.lock ]; then
  echo "FAIL: the resumed run left the lock of its directory"; exit 1
fi

# Drop the wall_time column (7th) and compare.
cut -d, -f1-6,8- reference/block_history.csv > reference.csv
cut -d, -f1-6,8- killed/block_history.csv > resumed.csv
if [ "$(wc -l < reference.csv)" != "$(wc -l < resumed.csv)" ]; then
  echo "FAIL: row counts differ"; exit 1
fi
numdiff -q -a 1e-12 -r 1e-8 -s ', \n' reference.csv resumed.csv
echo "resumed run equals the uninterrupted run"
