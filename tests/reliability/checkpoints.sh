#!/bin/bash
# Checkpoints that cannot crash a resume (block_compression, coarse):
#  - a resume with another 'Polynomial degree' stops and names the setting;
#  - a damaged newest checkpoint falls back to the previous one, and the
#    resumed run ends equal to an uninterrupted one;
#  - empty, truncated or missing checkpoint files (state, p4est mesh, data)
#    stop with a message naming each file, never a signal;
#  - a checkpoint of another dimension or without a manifest is refused;
#  - a manifest edited to agree with the run does not get its data read:
#    the data's element and fields are checked first (no signal).
#   checkpoints.sh <block_compression> <its .prm> <work dir>
set -euo pipefail
exe=$1 prm=$2 work=$3
. "$(dirname "$0")/common.sh"
start_in_work_dir "$work" "$prm"
with_prm base.prm reference.prm Output "set Directory = reference"
with_prm base.prm run.prm Output "set Directory = run"
with_prm run.prm first.prm Time "set End time = 0.5"
with_prm run.prm resume.prm Checkpoint "set Resume = true"
run_expect 0 reference.log "$exe" reference.prm
run_expect 0 first.log "$exe" first.prm
cp -r run pristine

# Another degree: refused before anything is loaded, checkpoint untouched.
with_prm resume.prm degree.prm "Finite element" "set Polynomial degree = 1"
run_expect 1 degree.log "$exe" degree.prm
expect_clean_error degree.log
expect_message degree.log "'Finite element/Polynomial degree' = '1', the checkpoint was written with '2'"
diff -r pristine run > /dev/null || { echo "FAIL: a refused resume changed the checkpoint"; exit 1; }

# Another material parameter: refused likewise.
with_prm resume.prm material.prm Materials "subsection Material 0" \
  "subsection neo-Hookean" "set Shear modulus = 20e3" end end
run_expect 1 material.log "$exe" material.prm
expect_message material.log "'Materials/Material 0/neo-Hookean/Shear modulus' = '20e3'"

# Each file of the newest checkpoint damaged in turn (empty, truncated,
# missing): the run resumes from the previous checkpoint and ends as the
# uninterrupted run.
for file in state.txt mesh mesh_fixed.data mesh.info; do
  for damage in empty truncate remove; do
    rm -rf run && cp -r pristine run
    case $damage in
      empty) : > "run/checkpoint/$file" ;;
      truncate) truncate -s -7 "run/checkpoint/$file" ;;
      remove) rm "run/checkpoint/$file" ;;
    esac
    run_expect 0 fallback.log "$exe" resume.prm
    expect_message fallback.log "Warning: the newest checkpoint cannot be used"
    expect_message fallback.log "'$file'"
    cut -d, -f1-6,8- reference/block_history.csv > a.csv
    cut -d, -f1-6,8- run/block_history.csv > b.csv
    numdiff -q -a 1e-12 -r 1e-8 -s ', \n' a.csv b.csv > /dev/null || {
      echo "FAIL: resumed after '$damage $file' differs from the reference"; exit 1; }
  done
done

# Both checkpoints damaged: a clear stop naming both, nothing rewritten.
rm -rf run && cp -r pristine run
: > run/checkpoint/state.txt
rm run/checkpoint.old/mesh
cp -r run damaged
run_expect 1 both.log "$exe" resume.prm
expect_clean_error both.log
expect_message both.log "no usable checkpoint"
expect_message both.log "'state.txt' is damaged"
expect_message both.log "'mesh' is missing"
diff -r damaged run > /dev/null || { echo "FAIL: a failed resume changed the files"; exit 1; }

# A manifest of another format, and a checkpoint of a 2D run.
rm -rf run && cp -r pristine run
sed -i '1s/.*/softgrasp checkpoint 1/' run/checkpoint/manifest.txt run/checkpoint.old/manifest.txt
run_expect 1 version.log "$exe" resume.prm
expect_message version.log "of another format version"
rm -rf run && cp -r pristine run
sed -i 's/^dimension 3/dimension 2/' run/checkpoint/manifest.txt run/checkpoint.old/manifest.txt
run_expect 1 dimension.log "$exe" resume.prm
expect_message dimension.log "written by a 2D run, this run is 3D"

# A manifest edited to agree with the run (or of another run): the data
# are checked against the run's element and fields before they are read;
# a clear stop, never a signal.
rm -rf run && cp -r pristine run
sed -i 's@^setting Finite element/Polynomial degree = 2@setting Finite element/Polynomial degree = 1@' \
  run/checkpoint/manifest.txt run/checkpoint.old/manifest.txt
run_expect 1 edited.log "$exe" degree.prm
expect_clean_error edited.log
expect_message edited.log "its data are of degree 2 elements (81 dofs per cell"
expect_message edited.log "Its manifest does not describe its data"
rm -rf run && cp -r pristine run
sed -i 's@^setting Time/Integrator = quasi-static@setting Time/Integrator = explicit dynamic@' \
  run/checkpoint/manifest.txt run/checkpoint.old/manifest.txt
with_prm resume.prm explicit.prm Time "set Integrator = explicit dynamic"
run_expect 1 integrator.log mpirun -np 2 "$exe" explicit.prm
expect_clean_error integrator.log
expect_message integrator.log "it holds 0 field(s) besides the displacement, this run needs 2"

# A data file of another run (degree 1) copied into the checkpoint with its
# manifest line: the run state binds the data files to its layout, so the
# file is refused by name, whatever the manifest says.
with_prm first.prm first-degree-1.prm "Finite element" "set Polynomial degree = 1"
with_prm first-degree-1.prm degree-1.prm Output "set Directory = run-degree-1"
run_expect 0 degree-1.log "$exe" degree-1.prm
rm -rf run && cp -r pristine run
for folder in checkpoint checkpoint.old; do
  cp run-degree-1/checkpoint/mesh_fixed.data run/$folder/
  line=$(grep "^file mesh_fixed.data " run-degree-1/checkpoint/manifest.txt)
  sed -i "s@^file mesh_fixed.data .*@$line@" run/$folder/manifest.txt
done
cp -r run copied
run_expect 1 copied.log "$exe" resume.prm
expect_clean_error copied.log
expect_message copied.log "its data file 'mesh_fixed.data' is not the one written with its run state (a 3D mesh of"
diff -r copied run > /dev/null || { echo "FAIL: a refused resume changed the files"; exit 1; }

# No checkpoint at all.
rm -rf run
run_expect 1 none.log "$exe" resume.prm
expect_message none.log "no usable checkpoint"
echo "checkpoint validation: all cases passed"
