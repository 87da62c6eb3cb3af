#!/bin/bash
# Restart with frictional contact: the ironing example run to the end
# (reference), and run to t = 0.5 s and then resumed from its checkpoint to
# t = 1 s. The friction state (each node's position at the last converged
# step) is rebuilt from the checkpointed displacement, so the contact force
# history of the resumed run must equal the reference.
#   contact_resume.sh <ironing executable> <ironing.prm> <work dir>
set -euo pipefail
exe=$1
prm=$2
work=$3
rm -rf "$work"
mkdir -p "$work"
cd "$work"
{ cat "$prm"; printf 'subsection Checkpoint\n set Interval = 1\nend\n'; } > base.prm
{ cat base.prm; printf 'subsection Output\n set Directory = reference\n set VTU interval = 0\nend\n'; } > reference.prm
{ cat base.prm; printf 'subsection Output\n set Directory = split\n set VTU interval = 0\nend\n'; } > split.prm
{ cat split.prm; printf 'subsection Time\n set End time = 0.5\nend\n'; } > first.prm
{ cat split.prm; printf 'subsection Checkpoint\n set Resume = true\nend\n'; } > resume.prm

"$exe" reference.prm > reference.log
"$exe" first.prm > first.log
"$exe" resume.prm > resume.log
grep -q "Resumed from the checkpoint at step 25" resume.log
numdiff -q -a 1e-10 -r 1e-7 -s ', \n' reference/ironing_contact.csv split/ironing_contact.csv
echo "resumed contact run equals the uninterrupted run"
