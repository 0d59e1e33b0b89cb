#!/usr/bin/env bash
# The hostile battery (issue 13): inputs a hostile user writes and faults a failing machine makes,
# each with its exit code and message, checking that nothing good is lost. Large inputs are
# generated here, small ones are inline.
#
# usage: bash tests/hostile/hostile_test.sh <path-to-rigidreel> <project-source-dir>
set -u

source "$(dirname "$0")/../render/cli/cli_harness.sh"
cli_setup hostile-test "$@"
# every run under a deadline: an unbounded one (10¹⁸ steps, /dev/zero) fails its case with exit 124
# instead of hanging the suite
run() {
  timeout -k 5 60 "$BIN" "$@" >out 2>err
  rc=$?
}
no_parts() { ! find "${1:-o}" -name '*.part*' | grep -q .; }
# signal_and_wait SIGNAL PID: sends SIGNAL every 0.5 s until PID ends (a background job starts
# with SIGINT ignored until rigidreel installs its handler, so one early signal may be lost), and
# kills it (exit 137) if it has not ended 10 s later: a signal that is not honoured shows as 137,
# not as a test that hangs; sets rc
signal_and_wait() {
  local k
  for ((k = 0; k < 20; k++)); do
    # an ended child stays a zombie (state Z) until waited for, and a zombie takes signals
    [ "$(cut -d' ' -f3 "/proc/$2/stat" 2>/dev/null)" = Z ] && break
    kill -"$1" "$2" 2>/dev/null || break
    sleep 0.5
  done
  kill -KILL "$2" 2>/dev/null
  wait "$2"
  rc=$?
}
# bounded memory: 1 GB of address space, except under AddressSanitizer (make sanitize sets
# ASAN_OPTIONS), which reserves terabytes of address space for its shadow memory at start
limit_memory() { [ -n "${ASAN_OPTIONS:-}" ] || ulimit -v 1000000; }
# a process id that has ended (a child that exited)
dead_pid() { sh -c 'echo $$'; }

cat >ball.yaml <<'YAML'
name: ball
duration: 1
world: {gravity: [0, -9.81]}
bodies: [{name: ball, shape: {circle: 0.2}, velocity: [1, 0]}]
YAML
V=o/ball/ball.mp4
RENDER=(render ball.yaml -o o --size 320x180 --fps 30 --quiet)

# --- item 1: a full disk while ffmpeg writes keeps the previous video ---------------------------
run "${RENDER[@]}"
check "a first render" "$rc"
cp $V good.mp4
# a file-size limit (RLIMIT_FSIZE, inherited by ffmpeg) with SIGXFSZ ignored makes every write past
# 4 KiB fail with EFBIG, as a full disk fails with ENOSPC: ffmpeg 5.1 then says "Error writing
# trailer" and exits 0. This needs no root, so it runs everywhere.
(trap '' XFSZ; ulimit -f 4; "$BIN" "${RENDER[@]}" >out 2>err)
rc=$?
[ "$rc" -eq 1 ] && grep -q "the video is incomplete" err && cmp -s good.mp4 $V && no_parts
check "a video cut short by a file-size limit: exit 1, the previous video kept, no half file" $? "exit $rc"
# the same on a real full disk: a 2 MB tmpfs filled to 4 KB free (needs root to mount)
mkdir tmpfs
if mount -t tmpfs -o size=2m tmpfs tmpfs 2>/dev/null; then
  run render ball.yaml -o tmpfs --size 320x180 --fps 30 --quiet
  cp tmpfs/ball/ball.mp4 good-tmpfs.mp4
  free_kb=$(df -k --output=avail tmpfs | tail -1)
  dd if=/dev/zero of=tmpfs/filler bs=1k count=$((free_kb - 4)) 2>/dev/null
  run render ball.yaml -o tmpfs --size 320x180 --fps 30 --quiet
  [ "$rc" -eq 1 ] && cmp -s good-tmpfs.mp4 tmpfs/ball/ball.mp4 && no_parts tmpfs
  check "a full disk (tmpfs): exit 1, the previous video kept, no half file" $? "exit $rc"
  umount tmpfs
else
  echo "# skipped: the full-disk case on a 2 MB tmpfs needs root to mount it"
fi

# --- item 4: scene and variant names are one safe path component ------------------------------
printf 'name: ../escaped\nbodies: [{name: a, shape: {box: [1, 1]}}]\n' >escape.yaml
expect "name: ../escaped is refused at its line" 2 "escape.yaml:1:7: the scene's name '../escaped'" render escape.yaml -o o --quiet
[ ! -e escaped ] && [ ! -e o/escaped ]
check "nothing is written outside -o" $?
printf 'name: /tmp/abs\nbodies: [{name: a, shape: {box: [1, 1]}}]\n' >abs.yaml
expect "an absolute name is refused" 2 "abs.yaml:1:7:" check abs.yaml
printf 'name: ""\nbodies: [{name: a, shape: {box: [1, 1]}}]\n' >empty.yaml
expect "an empty name is refused" 2 "empty.yaml:1:7: the scene's name '' names its output files but is empty" check empty.yaml
printf 'name: ok\nbodies: [{name: a, shape: {box: [1, 1]}}]\nvariants:\n  a/b: {duration: 2}\n' >variant.yaml
expect "a variant name with '/' is refused at its key, not by ffmpeg" 2 "variant.yaml:4:3: variant name 'a/b'" render variant.yaml --all-variants -o o --quiet

# --- item 5: signals during the survey and a stalled ffmpeg; stale temporary files -------------
# a survey of 10⁹ steps (about a minute) before the first frame
cat >long.yaml <<'YAML'
name: long
duration: 100
sim: {dt: 1.0e-7, max_steps: 1.0e10}
bodies: [{name: ball, shape: {circle: 0.2}, velocity: [1, 0]}]
YAML
"$BIN" render long.yaml -o o --size 160x90 --fps 10 --quiet >out 2>err &
pid=$!
sleep 1
signal_and_wait INT $pid
[ "$rc" -eq 130 ] && grep -q interrupted err && [ ! -e o/long/long.mp4 ] && no_parts
check "Ctrl-C during the survey: exit 130, no output" $? "exit $rc"
# an ffmpeg that reads nothing: the frames fill the pipe and the writer waits on it
mkdir -p stalled
printf '#!/bin/sh\necho $$ >%s/stalled.pid\nexec sleep 600\n' "$WORK" >stalled/ffmpeg
chmod +x stalled/ffmpeg
PATH=$WORK/stalled:$PATH "$BIN" "${RENDER[@]}" >out 2>err &
pid=$!
sleep 2
signal_and_wait TERM $pid
[ "$rc" -eq 130 ] && cmp -s good.mp4 $V && no_parts && ! kill -0 "$(cat stalled.pid)" 2>/dev/null
check "SIGTERM while ffmpeg is stalled: exit 130, ffmpeg stopped, the previous video kept" $? "exit $rc"
# temporary files of a run killed outright: removed by the next run of the same outputs, unless
# their process still runs
dead=$(dead_pid)
touch o/ball/.ball.part-$dead.mp4 o/ball/ball.png.part-$dead o/ball/.ball.part-$$.mp4
run "${RENDER[@]}"
[ "$rc" -eq 0 ] && [ ! -e o/ball/.ball.part-$dead.mp4 ] && [ ! -e o/ball/ball.png.part-$dead ] && [ -e o/ball/.ball.part-$$.mp4 ]
check "stale .part files of a dead process are removed, a live one's kept" $?
rm -f o/ball/.ball.part-$$.mp4

# --- item 8: concurrent renders of one scene into one folder ------------------------------------
# a whole PNG: the signature at the start and the IEND chunk (and its CRC) at the end
whole_png() { [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' ')" = 89504e470d0a1a0a ] && [ "$(tail -c 12 "$1" | head -c 8 | tail -c 4)" = IEND ]; }
# before the swap, 4 of 40 renders failed ("cannot remove all", "cannot rename: Directory not empty")
failures=0 broken=0
for ((round = 0; round < 10; round++)); do
  pids=()
  for ((k = 0; k < 4; k++)); do
    "$BIN" render ball.yaml -o race --size 160x90 --fps 60 --frames --quiet >race-out-$k 2>>race-err-$k &
    pids+=($!)
  done
  for pid in "${pids[@]}"; do wait "$pid" || failures=$((failures + 1)); done
  frames=(race/ball/ball-frames/*)
  [ "${#frames[@]}" -eq 60 ] || broken=$((broken + 1))
  for f in "${frames[@]}"; do whole_png "$f" || { broken=$((broken + 1)); break; }; done
done
cat race-err-* >err
[ "$failures" -eq 0 ] && [ "$broken" -eq 0 ] && no_parts race && [ -e race/ball/ball-frames/frame-00059.png ]
check "4 renders at once into one folder, 10 times: every run exits 0, the frames folder whole" $? \
  "$failures runs failed, $broken folders broken"

# --- item 6: bounds on work ---------------------------------------------------------------------
printf 'name: forever\nduration: 1.0e6\nsim: {dt: 1.0e-12}\nbodies: [{name: a, shape: {box: [1, 1]}}]\n' >forever.yaml
for command in check simulate render; do
  expect "$command: 10^18 steps are refused at dt's line, saying what to change" 2 \
    "forever.yaml:3:11: the run needs 1e+18 steps" $command forever.yaml
done
grep -q "max_steps" err
check "the message names the override, sim: {max_steps: N}" $?
expect "--dt past the limit is refused" 2 "--dt: the run needs" simulate ball.yaml --dt 1e-12
expect "--until past the limit is refused" 2 "--until: the run needs" simulate ball.yaml --until 1e9
expect "render --duration past the limit is refused" 2 "--duration: the run needs" render ball.yaml --duration 1e9 -o o

# --- item 7: loading is bounded -----------------------------------------------------------------
(limit_memory; timeout -k 5 60 "$BIN" check /dev/zero >out 2>err)
rc=$?
[ "$rc" -eq 2 ] && grep -q "/dev/zero: is larger than the limit of 16 MiB" err
check "check /dev/zero: exit 2 with the file-size limit, in bounded memory" $? "exit $rc"
# 17 MiB of bodies: refused before it is parsed
{
  echo "name: big"
  echo "bodies:"
  for ((k = 0; k < 17 * 1024; k++)); do printf '  - {name: b%07d, shape: {circle: 0.1}, position: [%d, 0]}  %1000s\n' $k $k ""; done
} >big.yaml
(limit_memory; timeout -k 5 60 "$BIN" check big.yaml >out 2>err)
rc=$?
[ "$rc" -eq 2 ] && grep -q "big.yaml: is larger than the limit" err
check "a 17 MiB scene is refused by the file-size limit" $? "exit $rc"

cli_finish
