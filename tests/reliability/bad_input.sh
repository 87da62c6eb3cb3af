#!/bin/bash
# Bad input is refused with a message that names the real cause (its line
# or parameter) and exit code 1 -- never a signal, a hang, a library banner
# or a silent run (block_compression, coarse).
#   bad_input.sh <block_compression> <its .prm> <work dir>
set -euo pipefail
exe=$1 prm=$2 work=$3
. "$(dirname "$0")/common.sh"
start_in_work_dir "$work" "$prm"
sed -i 's/set End time  = 1/set End time = 0.1/' base.prm

# refused <name> <expected message>: base.prm mutated into <name>.prm fails.
# The output directory is left as it was (a refused run moves nothing).
refused() {
  local before
  before=$(ls -R block_compression_output 2>/dev/null || true)
  run_expect 1 "$1.log" "$exe" "$1.prm"
  expect_clean_error "$1.log"
  expect_message "$1.log" "$2"
  [ "$before" = "$(ls -R block_compression_output 2>/dev/null || true)" ] || {
    echo "FAIL: the refused run '$1' changed the output directory"; exit 1; }
}
line_of() { grep -n -- "$1" base.prm | head -1 | cut -d: -f1; }

# Earlier results that no refused run may touch.
run_expect 0 valid.log "$exe" base.prm

# Structure: the message names the line of the fault itself.
n=$(line_of "^  set Formulation")
sed "$((n + 1))d" base.prm > missing-end.prm          # the 'end' of 'Finite element'
refused missing-end "line $(line_of "^subsection Finite element"): 'subsection Finite element' is never closed"
expect_message missing-end.log "probably before line $((n + 2))" # the next subsection
sed "${n}a end" base.prm > extra-end.prm
refused extra-end "line $((n + 2)): 'end' without a matching 'subsection'"
sed "${n}s/=//" base.prm > no-equals.prm
refused no-equals "line $n: 'set Formulation        mixed u-p-J' has no '='"
sed "${n}s/set /sett /" base.prm > bad-keyword.prm
refused bad-keyword "line $n: 'sett Formulation"
{ head -c 200 base.prm; printf 'se\0t x\n'; tail -c +201 base.prm; } > nul-byte.prm
refused nul-byte "has binary data on line"
head -c 3000 "$exe" > binary.prm # an executable given by mistake
refused binary "has binary data on line"
mkdir -p a-directory.prm
run_expect 1 directory.log "$exe" a-directory.prm
expect_message directory.log "'a-directory.prm' is a directory"

# Values the mesh or the physics does not have.
with_prm base.prm unknown-bc.prm "Boundary conditions" "set Dirichlet boundary ids = 4, 5, 9" \
  "subsection Dirichlet boundary 9" "set Components = x" "set Displacement = 0; 0; 0" end
refused unknown-bc "'Boundary conditions/Dirichlet boundary ids' names boundary id 9, which the mesh does not have (its boundary ids: 0, 1, 2, 3, 4, 5)"
with_prm base.prm unknown-slave.prm Contact "set Slave boundary ids = 7"
refused unknown-slave "is set but there is no rigid body" # ids: tests/contact/bad_input
with_prm base.prm far-monitor.prm Output "set Monitor points = 0.02, 0.01, 0.005; 1, 1, 1"
refused far-monitor "point 2 (1, 1, 1 m) is not inside the mesh"
with_prm base.prm grading.prm Mesh "subsection Block" "set Grading = 1, 2" end
refused grading "'Mesh/Block/Grading' has 2 values; a 3D block needs 3"
with_prm base.prm corner.prm Mesh "subsection Block" "set Upper corner = 0.02, 0.02, 0.01, 5" end
refused corner "'Mesh/Block/Upper corner' = '0.02, 0.02, 0.01, 5' needs 3"
with_prm base.prm scale.prm Mesh "set Type = file" "subsection File" "set File name = x.msh" "set Scale = 0" end
refused scale "'Mesh/File/Scale' is 0"
# A mesh file that deal.II cannot parse: a clean message, no banner.
printf '*Heading\n*Node\n1, 0, 0, 0\n2, 1, 0\n*Element, type=C3D8\n1, 1, 2, 3\n' > broken.inp
sed '/^  subsection Block/,/^  end/d' base.prm > no-block.prm
with_prm no-block.prm abaqus.prm Mesh "set Type = file" "subsection File" "set File name = broken.inp" end
refused abaqus "The mesh file 'broken.inp' cannot be read as a 3D Abaqus mesh"
# Entries of a mesh type that is not chosen would be ignored: refused.
with_prm base.prm manifolds-on-block.prm Mesh "subsection File" "set Manifolds = boundary 0: sphere 0, 0, 0" end
refused manifolds-on-block "'Mesh/Type' is 'block', but 'Mesh/File/Manifolds' belongs to mesh type 'file' and would be ignored"
# A layered limb of absurd size (a unit typed wrong) or cell counts.
limb() { local name=$1; shift
  with_prm no-block.prm "$name.prm" Mesh "set Type = layered limb" "subsection Layered limb" "$@" end; }
limb limb-mm "set Circumference = 342"
refused limb-mm "'Mesh/Layered limb/Circumference' = 342 m lies outside the range of human limbs"
expect_message limb-mm.log "'Mesh/Layered limb/Check human size = false'"
limb limb-micro "set Length = 1e-6"
refused limb-micro "'Mesh/Layered limb/Length' = 1e-06 m lies outside the range of human limbs"
limb limb-growth "set Axial growth = 1e6"
refused limb-growth "Mesh/Layered limb/Axial growth"
limb limb-around "set Circumferential cells = 4000000"
refused limb-around "[Integer range 8...4096 (inclusive)]"
limb limb-huge "set Circumferential cells = 4096" "set Radial cells = 16, 16, 16, 64" "set Grasp zone cells = 4000"
refused limb-huge "needs about"
with_prm base.prm friction.prm Contact "set Friction coefficient = 30"
refused friction "'Contact/Friction coefficient' = 30"
with_prm base.prm typo.prm Time "set End tim = 1"
refused typo "No entry with name <End tim> was declared"
with_prm base.prm unknown-model.prm Materials "subsection Material 0" "set Model = neo-hooke" end
refused unknown-model "neo-hooke"
# Constants far outside any tissue's (a modulus in MPa typed as Pa, ...):
# the run goes on, with a warning that names the material and the unit.
with_prm base.prm tiny-modulus.prm Materials "subsection Material 0" \
  "subsection neo-Hookean" "set Shear modulus = 1e-3" end end
run_expect 0 tiny-modulus.log "$exe" tiny-modulus.prm
expect_message tiny-modulus.log "Warning: Material 0 (soft tissue) has an initial shear modulus of 0.001 Pa, far outside any tissue's"

# Runs too large for the machine, or with millions of steps: refused up
# front with an estimate, unless the user overrides the check.
with_prm base.prm huge-mesh.prm Mesh "set Global refinements = 9"
refused huge-mesh "needs about"
expect_message huge-mesh.log "'Run limits/Check run size = false'"
with_prm base.prm many-steps.prm Time "set End time = 1e4" "set Time step = 1e-3"
refused many-steps "exceed 'Run limits/Maximum steps' = 1000000"
with_prm base.prm explicit-steps.prm Time "set Integrator = explicit dynamic" \
  && with_prm explicit-steps.prm tiny-step.prm "Explicit dynamics" "set Fixed time step = 1e-12"
run_expect 1 tiny-step.log "$exe" tiny-step.prm
expect_clean_error tiny-step.log
expect_message tiny-step.log "more than 'Run limits/Maximum explicit steps'"
with_prm many-steps.prm allowed-steps.prm "Run limits" "set Check run size = false" \
  && with_prm allowed-steps.prm allowed-steps-short.prm Time "set End time = 2e-3"
run_expect 0 allowed.log "$exe" allowed-steps-short.prm

# A body held by nothing: refused before the singular tangent is met.
without_boundary_conditions() { awk '/^subsection Boundary conditions/{skip=1} /^subsection Time/{skip=0} !skip' base.prm; }
without_boundary_conditions > free-body.prm
with_prm free-body.prm free-body-load.prm "Boundary conditions" "set Traction boundary ids = 5" \
  "subsection Traction boundary 5" "set Traction = 0; 0; -100 * t" end
refused free-body-load "nothing holds the body"

# A body held in x only: the tangent is singular; MUMPS fails or returns a
# useless update (an inverted element). Either way the step is cut back (a
# solver breakdown is a failed step), then the run stops with its last
# converged state written.
with_prm free-body.prm held-in-x.prm "Boundary conditions" "set Dirichlet boundary ids = 4" \
  "subsection Dirichlet boundary 4" "set Components = x" "set Displacement = 0; 0; 0" end \
  "set Traction boundary ids = 5" "subsection Traction boundary 5" "set Traction = 0; 0; -100 * t" end
run_expect 1 held-in-x.log "$exe" held-in-x.prm
expect_clean_error held-in-x.log
grep -qE "the direct solver \(MUMPS\) failed|an element inverted" held-in-x.log || {
  echo "FAIL: held-in-x: no failed step reported"; exit 1; }
expect_message held-in-x.log "-> cutting back"
expect_message held-in-x.log "The last converged state (step 0, t = 0 s) was written"
# Another program's .prm (a grasp study's 'Rigid environment'): the file
# is named whole and the message says it may belong to another program.
printf 'subsection Rigid environment\n  set Scene file = hand.xml\nend\n' > study.prm
refused study "Line <1> of file <study.prm>: There is no such subsection to be entered: Rigid environment"
expect_message study.log "the file is written for a grasp study (sphere_squeeze, arm_grasp, grasp_pull_sweep or mujoco_grasp)"
printf 'subsection Unknown part\n  set x = 1\nend\n' > unknown-part.prm
refused unknown-part "the file may be written for another softgrasp program"
# Bounds (issue 55): values that would wrap around, hide the output or run
# a single step are refused with the limit, never accepted silently.
for name in . ..; do
  with_prm base.prm "base-$name.prm" Output "set Base name = $name"
  refused "base-$name" "it must be an ordinary file name prefix, not '.' or '..'"
done
with_prm base.prm base-long.prm Output "set Base name = $(printf 'b%.0s' $(seq 300))"
refused base-long "'Output/Base name' has 300 characters: a file name may have at most 255 bytes"
with_prm base.prm phase-inf.prm Time "set Phases = 0.1: inf"
refused phase-inf "'0.1: inf' has a value that is not a finite number"
for id in -1 4294967296 4294967295; do
  with_prm no-block.prm "manifold-$id.prm" Mesh "set Type = file" "subsection File" \
    "set File name = broken.inp" "set Manifolds = boundary $id: sphere 0, 0, 0" end
  refused "manifold-$id" "has the id '$id', which is not a whole number from 0 to 4294967294 (deal.II's boundary ids)"
done
echo "bad input: all cases passed"
