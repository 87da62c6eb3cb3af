#!/bin/bash
# Fuzzed .prm files (a fixed seed, so every run tries the same cases): a
# valid file (block_compression, coarse) mutated at random. Mutations that
# make it invalid by construction (an 'end' deleted, a subsection opened
# twice, a number replaced by text, binary bytes inserted) must give exit
# code 1 with a clean message; any other mutation (truncation, swapped or
# deleted lines) may run or be refused, but never end in a signal or a hang.
#   fuzz_prm.sh <block_compression> <its .prm> <work dir> [cases]
set -euo pipefail
exe=$1 prm=$2 work=$3 cases=${4:-60}
. "$(dirname "$0")/common.sh"
start_in_work_dir "$work" "$prm"
sed -i -e 's/set End time  = 1/set End time = 0.1/' \
    -e 's/set Interval = 1/set Interval = 0/' \
    -e 's/set Directory      = .*/set Directory = out/' base.prm
with_prm base.prm valid.prm Output "set Existing results = replace"
run_expect 0 valid.log "$exe" valid.prm

RANDOM=20261130
n_lines=$(wc -l < valid.prm)
pick_line() { # a random line number matching $1
  local lines=($(grep -nE -- "$1" valid.prm | cut -d: -f1))
  echo "${lines[$((RANDOM % ${#lines[@]}))]}"
}
random_bytes() { # 24 bytes from the seeded generator, the first one NUL
  printf '\000'
  for _ in $(seq 1 23); do
    local b=$((RANDOM % 255 + 1))
    [ $b = 10 ] && b=0
    printf "\\$(printf %03o $b)"
  done
}
declare -A seen
for i in $(seq 1 "$cases"); do
  kind=$((RANDOM % 7))
  f=case-$i.prm
  case $kind in
    0) n=$(pick_line '^ *end *$'); sed "${n}d" valid.prm > $f; what="'end' on line $n deleted" ;;
    1) n=$(pick_line '^ *subsection'); sed "${n}p" valid.prm > $f; what="line $n doubled" ;;
    2) n=$(pick_line '^ *set [^=]*= *[-0-9.e, ]+$')
       sed -E "${n}s/=.*/= 1x!/" valid.prm > $f; what="number on line $n made text" ;;
    3) n=$((RANDOM % n_lines + 1))
       { head -n $((n - 1)) valid.prm; random_bytes; echo; tail -n +$n valid.prm; } > $f
       what="binary bytes at line $n" ;;
    4) bytes=$((RANDOM % $(wc -c < valid.prm)))
       head -c $bytes valid.prm > $f; what="truncated to $bytes bytes" ;;
    5) a=$((RANDOM % n_lines + 1)); b=$((RANDOM % n_lines + 1))
       awk -v a=$a -v b=$b 'NR==FNR{l[NR]=$0;next} {print (FNR==a?l[b]:(FNR==b?l[a]:$0))}' \
         valid.prm valid.prm > $f; what="lines $a and $b swapped" ;;
    6) n=$((RANDOM % n_lines + 1)); sed "${n}d" valid.prm > $f; what="line $n deleted" ;;
  esac
  seen[$kind]=1
  if [ $kind -le 3 ]; then
    run_expect 1 case-$i.log "$exe" $f
    expect_clean_error case-$i.log
  else
    code=0
    timeout --kill-after=10 300 "$exe" $f > case-$i.log 2>&1 || code=$?
    if [ $code != 0 ] && [ $code != 1 ]; then
      echo "FAIL: case $i ($what) ended with code $code"; cat case-$i.log; exit 1
    fi
    [ $code = 0 ] || expect_clean_error case-$i.log
  fi
  echo "case $i: $what: ok"
done
[ ${#seen[@]} = 7 ] || { echo "FAIL: not every kind of mutation was tried"; exit 1; }
echo "fuzzed .prm files: all $cases cases passed"
