#!/bin/bash
# A rigid body that starts inside the tissue is not accepted silently: the
# quasi-static and the explicit solver both warn with the number of nodes
# inside and the deepest overlap (hertz_indentation, coarse, the sphere
# started 0.5 mm deep instead of touching).
#   initial_overlap.sh <hertz_indentation> <its .prm> <work dir>
set -euo pipefail
exe=$1 prm=$2 work=$3
. "$(dirname "$0")/common.sh"
rm -rf "$work" && mkdir -p "$work" && cd "$work"
sed -e 's/set Global refinements = 1/set Global refinements = 0/' \
    -e 's/0: 0, 0, 0.01, 1, 0, 0, 0;/0: 0, 0, 0.0095, 1, 0, 0, 0;/' "$prm" > deep.prm
grep -q "0: 0, 0, 0.0095" deep.prm
with_prm deep.prm short.prm Time "set End time = 0.25"
code=0
timeout 300 "$exe" short.prm > quasi-static.log 2>&1 || code=$?
[ $code -le 1 ] || { echo "FAIL: exit code $code"; cat quasi-static.log; exit 1; }
expect_message quasi-static.log "contact node(s) start inside a rigid body (up to 0.000"
with_prm short.prm explicit.prm Time "set Integrator = explicit dynamic"
code=0
timeout 300 "$exe" explicit.prm > explicit.log 2>&1 || code=$?
[ $code -le 1 ] || { echo "FAIL: exit code $code"; cat explicit.log; exit 1; }
expect_message explicit.log "contact node(s) start inside a rigid body (up to 0.000"
echo "initial overlap: both solvers warn"
