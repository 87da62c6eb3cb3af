#!/bin/bash
# Restart of an explicit dynamic run with frictional contact: the ironing
# example switched to 'Time/Integrator = explicit dynamic' (the same .prm
# plus one line) is run to t = 0.4 s (reference), and run to t = 0.2 s and
# resumed from its checkpoint to t = 0.4 s. The checkpoint holds the
# displacement, the half-step velocity, the power iteration's mode, the
# stiffness damping force and the integrator's scalars (time step,
# energies), so the contact force and energy histories of the resumed run
# must equal the reference.
# Then a run whose steps invert elements stops with the cause named and
# its last good state written.
#   explicit_resume.sh <ironing executable> <ironing.prm> <work dir>
set -euo pipefail
exe=$1
prm=$2
work=$3
rm -rf "$work"
mkdir -p "$work"
cd "$work"
{ cat "$prm"; printf 'subsection Time\n set Integrator = explicit dynamic\n set End time = 0.4\nend\nsubsection Explicit dynamics\n set Mass damping = 300\n set Stiffness damping = 0.3\nend\nsubsection Checkpoint\n set Interval = 1\nend\n'; } > base.prm
{ cat base.prm; printf 'subsection Output\n set Directory = reference\n set VTU interval = 0\nend\n'; } > reference.prm
{ cat base.prm; printf 'subsection Output\n set Directory = split\n set VTU interval = 0\nend\n'; } > split.prm
{ cat split.prm; printf 'subsection Time\n set End time = 0.2\nend\n'; } > first.prm
{ cat split.prm; printf 'subsection Checkpoint\n set Resume = true\nend\n'; } > resume.prm

"$exe" reference.prm > reference.log
"$exe" first.prm > first.log
"$exe" resume.prm > resume.log
grep -q "Resumed from the checkpoint at step 10" resume.log
numdiff -q -a 1e-10 -r 1e-7 -s ', \n' reference/ironing_contact.csv split/ironing_contact.csv
cut -d, -f1,2,6- reference/ironing_history.csv > reference.csv
cut -d, -f1,2,6- split/ironing_history.csv > split.csv
numdiff -q -a 1e-12 -r 1e-7 -s ', \n' reference.csv split.csv
echo "resumed explicit run equals the uninterrupted run"

# The roller driven 11 mm into the 10 mm thick tissue (on a fixed base)
# within 20 ms crushes the elements under it: the run must stop at the first
# bad step (energy created by the integration or an inverted element, whichever comes
# first), name the cause, and leave the last good state (VTU, checkpoint).
{ cat "$prm"; printf 'subsection Time\n set Integrator = explicit dynamic\n set End time = 0.02\n set Time step = 0.002\nend\nsubsection Rigid bodies\n subsection Body iron\n  set Trajectory = 0: 0.01, 0.015, 0, 1, 0, 0, 0; 0.02: 0.01, 0.004, 0, 1, 0, 0, 0\n end\nend\nsubsection Output\n set Directory = crushed\nend\n'; } > crushed.prm
if "$exe" crushed.prm > crushed.log 2>&1; then
  echo "the crushing run did not fail"
  exit 1
fi
grep -Eq "was refused: (an element would invert|the energy the integration creates would exceed)" crushed.log
grep -q "The last good state" crushed.log
test -f crushed/checkpoint/state.txt
test -n "$(ls crushed/*.vtu)"
echo "crushed tissue: run stopped with the cause named, last good state written"
