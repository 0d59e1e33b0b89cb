#!/usr/bin/env bash
# The progress line of a long `check` or `simulate` (render/cli/run_progress.h): drawn on standard
# error when it is a terminal (a pseudo-terminal here, python3's pty), erased at the end; never on a
# pipe, and standard output the same either way.
#
# usage: bash tests/render/cli/run_progress_test.sh <path-to-rigidreel> <project-source-dir>
set -u

source "$(dirname "$0")/cli_harness.sh"
cli_setup run-progress-test "$@"

# a run of one body long enough to pass the line's first second, about 2.5 s in this build: 10⁶
# steps timed first (a sanitizer's build steps some 50 times slower than a release build); a run
# that still ends within 1.5 s is run again longer (below)
long_scene() {
  printf 'name: long\nduration: %s\nsim: {dt: 1.0e-6, max_steps: 1.0e10}\nbodies: [{name: ball, shape: {circle: 0.2}, velocity: [1, 0]}]\n' "$1" >long.yaml
}
long_scene 1
start=$(date +%s.%N)
"$BIN" simulate long.yaml >/dev/null
duration=$(python3 -c "import sys; t = float(sys.argv[2]) - float(sys.argv[1]); print(min(90, max(2, round(2.5 / max(t, 1e-3)))))" "$start" "$(date +%s.%N)")
long_scene "$duration"

# on_tty OUT ERR ARGS...: runs rigidreel with standard error on a pseudo-terminal, standard output
# to OUT; what the terminal showed goes to ERR; sets rc
on_tty() {
  local out=$1 err=$2
  shift 2
  python3 - "$out" "$err" "$BIN" "$@" <<'PY'
import os, pty, subprocess, sys
out_path, err_path, argv = sys.argv[1], sys.argv[2], sys.argv[3:]
master, slave = pty.openpty()
with open(out_path, "wb") as out:
    child = subprocess.Popen(argv, stdout=out, stderr=slave, stdin=subprocess.DEVNULL)
os.close(slave)
shown = b""
while True:
    try:
        chunk = os.read(master, 65536)
    except OSError:  # EIO: the child closed the terminal
        break
    if not chunk:
        break
    shown += chunk
open(err_path, "wb").write(shown)
sys.exit(child.wait())
PY
  rc=$?
}

for command in check simulate; do
  # a run that ended within 1.5 s (the load eased after the timing) proves nothing about a line
  # drawn after the first second: run it again eight times as long, up to three times more
  for attempt in 1 2 3 4; do
    start=$(date +%s.%N)
    on_tty tty-out tty-err $command long.yaml
    python3 -c "import sys; sys.exit(0 if float(sys.argv[2]) - float(sys.argv[1]) >= 1.5 else 1)" "$start" "$(date +%s.%N)" && break
    [ "$attempt" -lt 4 ] || break
    duration=$((duration * 8))
    long_scene "$duration"
  done
  check "$command on a terminal: exit 0" "$rc"
  grep -qaF $'\r'"long.yaml: t = " tty-err && grep -qa "of $duration s, .* steps/s" tty-err
  check "$command on a terminal: a progress line with the simulated time and steps/s" $? "$(od -c tty-err | head -5)"
  # the line is erased at the end: the last thing on the terminal is "\r" and "clear to end of line"
  [ "$(tail -c 4 tty-err | od -An -c | tr -d ' ')" = '\r033[K' ]
  check "$command on a terminal: the line erased at the end" $? "$(tail -c 40 tty-err | od -c)"
  "$BIN" $command long.yaml >pipe-out 2>pipe-err
  check "$command on a pipe: exit 0" $?
  [ ! -s pipe-err ]
  check "$command on a pipe: nothing on standard error" $? "$(head -c 200 pipe-err | od -c | head -3)"
  cmp -s pipe-out tty-out
  check "$command: standard output the same on a terminal and a pipe" $?
done

# a short run says nothing, even on a terminal
printf 'name: short\nbodies: [{name: ball, shape: {circle: 0.2}}]\n' >short.yaml
on_tty out tty-err check short.yaml
[ "$rc" -eq 0 ] && [ ! -s tty-err ]
check "a run shorter than a second draws no line on a terminal" $? "$(od -c tty-err | head -3)"

cli_finish
