# Helpers of the reliability tests (sourced). Each helper asserts one thing
# and stops the test with "FAIL: ..." otherwise.

# Open MPI refuses to start as root unless told; harmless otherwise.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# run_expect <code> <log> <command...>: run with a time limit (no hang) and
# require the exit code <code> (never a signal, never the time limit).
run_expect() {
  local want=$1 log=$2
  shift 2
  local code=0
  timeout --kill-after=10 300 "$@" > "$log" 2>&1 || code=$?
  if [ "$code" = 124 ] || [ "$code" = 137 ]; then
    echo "FAIL: '$*' hung (killed after 300 s)"; cat "$log"; exit 1
  fi
  if [ "$code" -gt 128 ]; then
    echo "FAIL: '$*' died of signal $((code - 128))"; cat "$log"; exit 1
  fi
  if [ "$code" != "$want" ]; then
    echo "FAIL: '$*' exited with $code, expected $want"; cat "$log"; exit 1
  fi
}

# expect_message <log> <fixed string>: the log holds the message.
expect_message() {
  if ! grep -qF -- "$2" "$1"; then
    echo "FAIL: '$1' lacks the message: $2"; cat "$1"; exit 1
  fi
}

# expect_clean_error <log>: one error message, no C++ or deal.II noise.
expect_clean_error() {
  expect_message "$1" "Error"
  if grep -qE "An error occurred in line|uncaught exception|Aborting!" "$1"; then
    echo "FAIL: '$1' shows a library banner"; cat "$1"; exit 1
  fi
}

# with_prm <in> <out> <subsection> <entry line...>: append a subsection.
with_prm() {
  local in=$1 out=$2 section=$3
  shift 3
  { cat "$in"; echo "subsection $section"; for line in "$@"; do
      echo "  $line"; done; echo "end"; } > "$out"
}

# start_in_work_dir <work dir> <block_compression.prm> [VTU interval]: a
# fresh work directory holding base.prm, the example on its coarse mesh
# (no refinement) writing VTU files every [VTU interval] steps (0: last).
start_in_work_dir() {
  rm -rf "$1" && mkdir -p "$1" && cd "$1"
  sed -e 's/set Global refinements = 1/set Global refinements = 0/' \
      -e "s/set VTU interval   = 5/set VTU interval = ${3:-0}/" "$2" > base.prm
}
