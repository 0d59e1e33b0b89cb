#!/usr/bin/env bash
# The fourth battery (issue 41), interrupts: Ctrl-C is exit 130 everywhere, also while a child blocks
# (ffmpeg stalled on its trailer, stopped by the same Ctrl-C) and while a FIFO waits for its reader.
#
# usage: bash tests/hostile/hostile4_interrupts_test.sh <path-to-rigidreel> <project-source-dir>
set -u

HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/../render/cli/cli_harness.sh"
source "$HERE/hostile_harness.sh"
cli_setup hostile4-interrupts-test "$@"

cat >ball.yaml <<'YAML'
name: ball
duration: 1
bodies: [{name: ball, shape: {circle: 0.2}, velocity: [1, 0]}]
YAML

# group_interrupt SECONDS ARGS...: runs ARGS in a process group of its own and, after SECONDS, sends
# SIGINT to the whole group, as Ctrl-C at a terminal does (ffmpeg gets it too); sets rc
group_interrupt() {
  local after=$1
  shift
  setsid "$BIN" "$@" >out 2>err &
  local pid=$!
  sleep "$after"
  kill -INT -- -"$pid" 2>/dev/null
  # sent again while it runs, and killed (137) if it has not ended 10 s later
  for ((k = 0; k < 20; k++)); do
    [ "$(cut -d' ' -f3 "/proc/$pid/stat" 2>/dev/null)" = Z ] && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.5
    kill -INT -- -"$pid" 2>/dev/null
  done
  kill -KILL -- -"$pid" 2>/dev/null
  wait "$pid"
  rc=$?
}

# an ffmpeg that reads every frame, then stalls on its trailer (a slow disk), until Ctrl-C stops it
mkdir -p slow
printf '#!/bin/sh\ncat >/dev/null\nexec sleep 600\n' >slow/ffmpeg
chmod +x slow/ffmpeg
PATH=$WORK/slow:$PATH group_interrupt 2 render ball.yaml -o o --size 160x90 --fps 10 --quiet
[ "$rc" -eq 130 ] && grep -q "rigidreel: render ball.yaml interrupted" err && ! grep -q "killed by signal" err && no_parts o
check "Ctrl-C to the group while ffmpeg finishes: exit 130, not 'ffmpeg killed by signal 2'" $? "exit $rc"
# an ffmpeg that reads nothing: the writer waits on the full pipe
printf '#!/bin/sh\nexec sleep 600\n' >slow/ffmpeg
PATH=$WORK/slow:$PATH group_interrupt 2 render ball.yaml -o o --size 160x90 --fps 10 --quiet
[ "$rc" -eq 130 ] && grep -q "interrupted" err && no_parts o
check "Ctrl-C to the group while ffmpeg reads nothing: exit 130" $? "exit $rc"

# --trace into a FIFO nobody reads: open() waits for a reader
mkfifo t.fifo
group_interrupt 1 simulate ball.yaml --trace t.fifo
[ "$rc" -eq 130 ] && grep -q "rigidreel: simulate ball.yaml interrupted" err && ! grep -q "Interrupted system call" err && [ -p t.fifo ]
check "Ctrl-C while --trace FIFO waits for its reader: exit 130, the FIFO kept" $? "exit $rc"
"$BIN" simulate ball.yaml --trace t.fifo >out 2>err &
pid=$!
sleep 1
signal_and_wait TERM $pid
[ "$rc" -eq 130 ] && grep -q interrupted err
check "  ... and SIGTERM there" $? "exit $rc"

cli_finish
