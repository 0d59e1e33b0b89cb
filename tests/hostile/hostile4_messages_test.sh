#!/usr/bin/env bash
# The fourth battery (issue 41), messages and exit codes: every command says bad input the same way
# (FILE:LINE:COL, exit 2), numbers in a message tell apart what they compare, and advice fits the
# fault (no "install ffmpeg" when the machine is out of descriptors, no frame size blamed for a
# memory limit, a warning for more threads than cores).
#
# usage: bash tests/hostile/hostile4_messages_test.sh <path-to-rigidreel> <project-source-dir>
set -u

HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/../render/cli/cli_harness.sh"
source "$HERE/hostile_harness.sh"
cli_setup hostile4-messages-test "$@"

cat >ball.yaml <<'YAML'
name: ball
duration: 1
bodies: [{name: ball, shape: {circle: 0.2}, velocity: [1, 0]}]
YAML

# --- overlapping bodies: bad input at the second body's line, in every command ------------------
cat >overlap.yaml <<'YAML'
name: overlap
duration: 1
sim: {collisions: event}
bodies:
- {name: a, shape: {circle: 0.5}}
- {name: b, shape: {circle: 0.5}, position: [0.5, 0]}
YAML
expect "check of overlapping bodies: FILE:LINE:COL, exit 2" 2 "overlap.yaml:6:3: bodies 'a' and 'b' overlap" check overlap.yaml
expect "snapshot of them: the same" 2 "overlap.yaml:6:3: bodies 'a' and 'b' overlap" snapshot overlap.yaml --at 0.5 -o o
expect "render of them: the same" 2 "overlap.yaml:6:3: bodies 'a' and 'b' overlap" render overlap.yaml -o o --size 160x90 --fps 10 --quiet
[ ! -e o/overlap ]
check "  ... nothing drawn" $?

# --- numbers that tell apart what they compare ----------------------------------------------------
printf 'name: s\nduration: 100000001\nsim: {dt: 1}\nbodies: [{name: a, shape: {circle: 1}}]\n' >steps.yaml
expect "one step past max_steps: both counts in full" 2 "the run needs 100000001 steps (1e+08 s at dt = 1 s), more than the limit of 100000000" \
  check steps.yaml
# 10,000.0011 s at 1000 fps: one frame and a part past the limit of 10^7
printf 'name: f\nduration: 10000\nanswer: it stays\nsim: {dt: 1, max_steps: 1.0e10}\nbodies: [{name: a, shape: {circle: 1}}]\nrender: {fps: 1000, answer_card: 0.0011}\n' >frames.yaml
run render frames.yaml -o o --quiet
[ "$rc" -eq 2 ] && grep -q "10000002 frames" err && grep -q "more than the limit of 10000000" err && grep -q "answer_card" err
check "one frame past the video limit: both counts in full, answer_card among the remedies" $? "exit $rc: $(head -c 300 err)"

# --- advice that fits the fault --------------------------------------------------------------------
cores=$(nproc)
if [ "$cores" -lt 64 ]; then
  printf 'name: t\nduration: 0.01\nsim: {collisions: soft_step}\nbodies: [{name: a, shape: {circle: 1}}]\n' >threads.yaml
  run simulate threads.yaml --threads 64
  [ "$rc" -eq 0 ] && grep -q "warning: soft_step runs 64 threads on $cores core" err
  check "--threads 64 on $cores cores: said, with the cores to give" $? "exit $rc"
  run simulate threads.yaml --threads 1
  ! grep -q "threads on" err
  check "  ... and not for one thread" $?
fi
# out of file descriptors when ffmpeg is started: what to do is free some, not install ffmpeg
# (the fewest descriptors the run needs before it starts ffmpeg vary: the limit lowered until it fails there)
hit=0 advised=0
for n in 9 8 7 6 5; do
  (ulimit -n $n && exec "$BIN" render ball.yaml -o o --size 160x90 --fps 10 --quiet) >out 2>err
  grep -qi "too many open files" err && hit=1 && grep -q "install" err && advised=1
done
[ "$hit" -eq 1 ] && [ "$advised" -eq 0 ]
check "out of file descriptors: not 'install ffmpeg'" $? "hit $hit, advised $advised: $(head -c 300 err)"
if [ -z "${ASAN_OPTIONS:-}" ]; then
  (ulimit -v 400000 && exec "$BIN" snapshot ball.yaml --at 1 --size 8192x8192 -o big) >out 2>err
  rc=$?
  [ "$rc" -ne 0 ] && ! grep -q "OSMesa cannot draw frames of" err && grep -q "ulimit -v" err
  check "frames past a memory limit: not blamed on their size, the limit named" $? "exit $rc: $(head -c 300 err)"
else
  echo "# skipped: a memory limit under AddressSanitizer"
fi

cli_finish
