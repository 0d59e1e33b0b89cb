#!/usr/bin/env bash
# Drawing bounded by the frame (issue 23): scenes whose numbers would make a drawing loop run
# without end (hatching a view 1e308 m high, stripes 1e-6 px apart, a box at 1e16 m, gravity that
# flings a body past what a double can show) each end quickly or are refused at their line, and a
# long frame stops at a signal.
#
# usage: bash tests/hostile/frame_bounds_test.sh <path-to-rigidreel> <project-source-dir>
set -u

source "$(dirname "$0")/../render/cli/cli_harness.sh"
cli_setup frame-bounds-test "$@"
# every run under a deadline of 10 s (an unbounded loop fails its case with exit 124), at 64x36
run() {
  timeout -k 2 10 "$BIN" "$@" >out 2>err
  rc=$?
}
no_parts() { ! find "${1:-o}" -name '*.part*' | grep -q .; }
ends() {  # ends NAME SCENE: a snapshot and a render each end within the deadline, exit 0
  run snapshot "$2" -o o --size 64x36 --at 0.1
  [ "$rc" -eq 0 ]
  check "$1: snapshot ends within 10 s" $? "exit $rc"
  run render "$2" -o o --size 64x36 --fps 10 --quiet
  [ "$rc" -eq 0 ] && no_parts
  check "$1: render ends within 10 s" $? "exit $rc"
}

cat >far_box.yaml <<'YAML'
name: far_box
duration: 0.2
bodies:
  - {name: ball, shape: {circle: 0.2}}
  - {name: far, shape: {box: [1, 1]}, position: [1e16, 0], static: true}
YAML
ends "a static box at x = 1e16" far_box.yaml
# a box 1e16 m out seen from near: its stripes, half a metre apart, are 1.4e16 stripes from the
# origin, past 2^53, where counting them one by one (k += 1) stalls
cat >far_view.yaml <<'YAML'
name: far_view
duration: 0.2
render: {line_width: 0.1, camera: {center: [1e16, 0], height: 50}}
bodies:
  - {name: ball, shape: {circle: 0.2}, position: [1e16, 12]}
  - {name: far, shape: {box: [80, 20]}, position: [1e16, 0], static: true}
YAML
ends "a static box at x = 1e16 seen from 50 m" far_view.yaml

cat >thin_lines.yaml <<'YAML'
name: thin_lines
duration: 0.2
render: {line_width: 1e-6}
bodies:
  - {name: ground, shape: {box: [4, 0.2]}, static: true}
  - {name: ball, shape: {circle: 0.2}, position: [0, 1]}
  - {name: floor, shape: {plane: {point: [0, -1], normal: [0, 1]}}}
YAML
ends "line_width 1e-6" thin_lines.yaml

cat >tall_camera.yaml <<'YAML'
name: tall_camera
duration: 0.2
render:
  camera: {center: [0, 0], height: 1e308}
bodies:
  - {name: ground, shape: {box: [4, 0.2]}, static: true}
  - {name: ball, shape: {circle: 0.2}, position: [0, 1]}
YAML
for cmd in check snapshot render; do
  args=(--size 64x36 -o o --quiet)
  [ $cmd = snapshot ] && args=(--size 64x36 -o o --at 0.1)
  [ $cmd = check ] && args=()
  run $cmd tall_camera.yaml "${args[@]}"
  [ "$rc" -eq 2 ] && grep -qF "tall_camera.yaml:4:11: a fixed camera's center and height are at most 1e150 m" err
  check "camera height 1e308: $cmd refuses it at the camera key, exit 2" $? "exit $rc"
done

cat >huge_gravity.yaml <<'YAML'
name: huge_gravity
duration: 0.2
world: {gravity: [0, -1e308]}
bodies:
  - {name: ground, shape: {box: [4, 0.2]}, static: true}
  - {name: ball, shape: {circle: 0.2}, position: [0, 1]}
YAML
for cmd in snapshot render; do
  args=(--size 64x36 -o o --quiet)
  [ $cmd = snapshot ] && args=(--size 64x36 -o o --at 0.1)
  run $cmd huge_gravity.yaml "${args[@]}"
  # refused at the body the automatic camera could not hold, or the run stopped as diverged (exit
  # 1, naming the body): either way within the deadline and without output
  { [ "$rc" -eq 2 ] && grep -qF "huge_gravity.yaml:6:5: body 'ball'" err; } ||
    { [ "$rc" -eq 1 ] && grep -q "ball" err; }
  check "gravity 1e308: $cmd refused at the body, or diverged, within 10 s" $? "exit $rc: $(head -c 300 err)"
  [ ! -e o/huge_gravity ] || [ -z "$(find o/huge_gravity -type f)" ]
  check "gravity 1e308: $cmd writes nothing" $?
done

# --- a signal during a long frame: 30,000 circles, every label drawn ----------------------------
python3 - <<'PY'
with open("crowd.yaml", "w") as f:
    f.write("name: crowd\nduration: 0.02\nworld: {gravity: [0, 0]}\nrender: {labels: true, contacts: true}\n")
    f.write("sim: {collisions: none, max_bodies: 40000}\nbodies:\n")
    for i in range(30000):
        f.write("  - {name: c%d, shape: {circle: 0.4}, position: [%d, %d]}\n" % (i, i % 200, i // 200))
PY
cpu_ticks() { awk '{print $14 + $15}' "/proc/$1/stat" 2>/dev/null; }  # user + system, in clock ticks
tick=$(getconf CLK_TCK)
# what the frame comes after costs about as much as `check` (reading the file, the run): the signal is
# sent once the snapshot has spent that and 1.5 s more, so that it lands while the frame is drawn
# (labels: true places 30,000 labels, minutes of work), whatever the machine's load
/usr/bin/time -f %U -o check.cpu "$BIN" check crowd.yaml >/dev/null 2>&1
before=$(awk -v t="$tick" '{printf "%d", ($1 + 1.5) * t}' check.cpu)
"$BIN" snapshot crowd.yaml -o o --size 1280x720 --at 0.02 >out 2>err &
pid=$!
for ((k = 0; k < 6000; k++)); do
  ticks=$(cpu_ticks $pid)
  [ -z "$ticks" ] || [ "$ticks" -ge "$before" ] && break
  sleep 0.1
done
at_signal=$(cpu_ticks $pid)
sent=$(date +%s.%N)
kill -TERM $pid
# until it has exited (a zombie keeps its times), SIGKILL after 30 s: an unheeded signal shows as 137
last=$at_signal
for ((k = 0; k < 600; k++)); do
  state=$(cut -d' ' -f3 "/proc/$pid/stat" 2>/dev/null)
  [ -n "$state" ] && last=$(cpu_ticks $pid)
  [ -z "$state" ] || [ "$state" = Z ] && break
  sleep 0.05
done
kill -KILL $pid 2>/dev/null
wait $pid
rc=$?
took=$(echo "$(date +%s.%N) - $sent" | bc)
spent=$(echo "scale=2; (${last:-0} - ${at_signal:-0}) / $tick" | bc)
# within a second of processor time after the signal (its wall time is the machine's load's: allowed 30 s)
[ "$rc" -eq 130 ] && grep -q interrupted err && no_parts && [ ! -e o/crowd/crowd-t0.02.png ] && (($(echo "$spent < 1" | bc)))
check "SIGTERM during a frame of 30,000 circles: exit 130, $spent s of processor time after it ($took s wall), no output, no temporary" $? "exit $rc"

cli_finish
