#!/usr/bin/env bash
# The fourth battery (issue 41), outputs: one rule for every output, checked before any work. A
# path an output would write is refused (exit 2, naming it) when it is or holds an input of the run,
# when it is a folder holding files the command did not write, or when it cannot be created; two
# outputs of one run never share a path; symlinked folders are written through; a trace to
# standard output is neither silenced by -q nor sent into -o's file.
#
# usage: bash tests/hostile/hostile4_outputs_test.sh <path-to-rigidreel> <project-source-dir>
set -u

HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/../render/cli/cli_harness.sh"
source "$HERE/hostile_harness.sh"
cli_setup hostile4-outputs-test "$@"

cat >ball.yaml <<'YAML'
name: ball
duration: 1
world: {gravity: [0, -9.81]}
bodies: [{name: ball, shape: {circle: 0.2}, position: [0, 1], velocity: [1, 0]}]
golden: {size: [160, 90], impacts: false, at: [1]}
YAML
cp ball.yaml ball.kept
run golden record ball.yaml -o golden
check "a record to check against" "$rc"
# unchanged: the file the case must not have destroyed
kept() { cmp -s ball.yaml ball.kept; }

# --- an output that is or holds an input ----------------------------------------------------------
run simulate ball.yaml -o ball.yaml
[ "$rc" -eq 2 ] && grep -q "^rigidreel: -o: ball.yaml is the scene file this run reads" err && kept
check "simulate S -o S: refused, the scene kept" $? "exit $rc"
run check ball.yaml -o ball.yaml
[ "$rc" -eq 2 ] && grep -q -- "-o: ball.yaml is the scene file" err && kept
check "check S -o S: refused, the scene kept" $? "exit $rc"
run golden check ball.yaml --junit ball.yaml
[ "$rc" -eq 2 ] && grep -q -- "--junit: ball.yaml is the scene file" err && kept && ! grep -q state out
check "golden check S --junit S: refused before the run, the scene kept" $? "exit $rc"
mkdir pend && sed 's/^name: ball$/name: pend/' ball.yaml >pend/pend.yaml
run golden record pend/pend.yaml -o .
[ "$rc" -eq 2 ] && grep -q -- "-o: ./pend holds the scene file pend/pend.yaml" err && [ -f pend/pend.yaml ]
check "golden record pend/pend.yaml -o .: refused, pend/ kept" $? "exit $rc"

# --- a report folder only where golden check may replace it ---------------------------------------
mkdir artifacts && echo mine >artifacts/notes.txt
run golden check ball.yaml --report artifacts
[ "$rc" -eq 2 ] && grep -q "artifacts holds files golden report did not write (notes.txt)" err && [ -f artifacts/notes.txt ] &&
  ! grep -q state out
check "--report artifacts holding notes.txt: refused before the run, the notes kept" $? "exit $rc"
run golden check ball.yaml --report golden
[ "$rc" -eq 2 ] && grep -q -- "--report: golden holds the golden record golden/ball" err && [ -f golden/ball/manifest.json ]
check "--report golden: refused, the records kept" $? "exit $rc"
run golden check ball.yaml --report ball.yaml
[ "$rc" -eq 2 ] && kept
check "--report naming the scene file: refused, the file kept" $? "exit $rc"
echo notes >notes.txt
run golden check ball.yaml --report notes.txt
[ "$rc" -eq 2 ] && grep -q "notes.txt is not a folder" err && [ -f notes.txt ]
check "--report naming a file: refused, the file kept" $? "exit $rc"
run golden check ball.yaml --report notes.txt/report
[ "$rc" -eq 2 ] && grep -q "cannot be created: notes.txt is not a folder" err && ! grep -q state out
check "--report that cannot be created: refused at once, exit 2" $? "exit $rc"
run golden check ball.yaml --junit notes.txt/j.xml
[ "$rc" -eq 2 ] && grep -q -- "--junit: notes.txt/j.xml cannot be created" err && ! grep -q state out
check "--junit that cannot be created: refused at once, exit 2" $? "exit $rc"
run golden record ball.yaml -o notes.txt/golden
[ "$rc" -eq 2 ] && grep -q "cannot be created" err && ! grep -q "filesystem error" err
check "golden record -o that cannot be created: refused at once, exit 2" $? "exit $rc"
run golden check ball.yaml --report rep/
[ "$rc" -eq 0 ] && [ -f rep/index.html ]
check "--report DIR/ (a trailing slash): written" $? "exit $rc"
run golden check ball.yaml --report rep
[ "$rc" -eq 0 ] && [ -f rep/index.html ]
check "  ... and again into its own report" $? "exit $rc"

# --- symlinked folders written through --------------------------------------------------------------
mkdir web && ln -s web site
run golden check ball.yaml --report site
[ "$rc" -eq 0 ] && [ -L site ] && [ -f web/index.html ]
check "a report folder reached through a symlink: the link kept, its target written" $? "exit $rc"
mkdir -p shared/ball gl && ln -s ../shared/ball gl/ball
run golden record ball.yaml -o gl
[ "$rc" -eq 0 ] && [ -L gl/ball ] && [ -f shared/ball/manifest.json ]
check "a record folder reached through a symlink: the link kept, its target written" $? "exit $rc"

# --- two outputs of one run never share a path ------------------------------------------------------
sed 's/position: \[0, 1\]/position: [0, 2]/' ball.yaml >twin.yaml
run golden record ball.yaml twin.yaml -o g2
[ "$rc" -eq 2 ] && grep -q "g2/ball would hold both the record of ball.yaml and the record of twin.yaml" err && [ ! -e g2/ball ]
check "two scenes with one name into one golden folder: refused" $? "exit $rc"
sed 's/^name: ball$/name: x/' ball.yaml >x.yaml && printf 'variants: {y: {}}\n' >>x.yaml
sed 's/^name: ball$/name: x-y/' ball.yaml >xy.yaml
run golden record x.yaml xy.yaml -o g3
[ "$rc" -eq 2 ] && grep -q "g3/x-y would hold both the record of x.yaml (variant y) and the record of xy.yaml" err
check "variant y of scene x and a scene x-y: refused" $? "exit $rc"
sed 's/at: \[1\]/at: [0.5, 0.5000004]/' ball.yaml >close.yaml
run golden record close.yaml -o g4
[ "$rc" -eq 0 ] && [ -f g4/ball/frame-t0.5.png ] && [ -f g4/ball/frame-t0.5000004.png ]
check "frames at 0.5 and 0.5000004: two files, named with the digits that tell them apart" $? "exit $rc"
run golden check close.yaml --golden g4
check "  ... and the fresh record passes its own check" "$rc"
run simulate ball.yaml --trace state.csv -o state.csv
[ "$rc" -eq 2 ] && grep -q -- "--trace: state.csv is also where -o writes" err
check "simulate --trace F -o F: refused" $? "exit $rc"
"$BIN" simulate ball.yaml --trace same.csv >same.csv 2>err
rc=$?
[ "$rc" -eq 2 ] && grep -q -- "--trace: same.csv is also where standard output writes" err
check "simulate --trace F > F: refused" $? "exit $rc"

# --- a trace to standard output goes there --------------------------------------------------------
"$BIN" simulate ball.yaml --trace /dev/stdout -q >out 2>err
rc=$?
[ "$rc" -eq 0 ] && [ "$(head -c 2 out)" = "t," ] && [ "$(wc -l <out)" -eq 1002 ]
check "simulate --trace /dev/stdout -q: the trace alone on standard output" $? "exit $rc, $(wc -l <out) lines"
"$BIN" simulate ball.yaml --trace /dev/stdout -o state.txt >out 2>err
rc=$?
[ "$rc" -eq 0 ] && [ "$(wc -l <out)" -eq 1002 ] && ! grep -q '^[0-9]' state.txt && grep -q "^ball: t = 1" state.txt
check "simulate --trace /dev/stdout -o state.txt: the trace on standard output, the state alone in the file" $? \
  "exit $rc, $(wc -l <out) lines"

# --- a long legal name ------------------------------------------------------------------------------
long=$(printf 'n%.0s' $(seq 1 246)).txt
run simulate ball.yaml -o "$long"
[ "$rc" -eq 0 ] && [ -f "$long" ]
check "a 250-byte output name: its temporary name shortened, not refused" $? "exit $rc"

cli_finish
