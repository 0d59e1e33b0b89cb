#!/usr/bin/env bash
# One run behind every output: `render` at any size and frame rate (with a title card and slow
# motion) and `snapshot` at any times write, with --trace, byte for byte the trace `simulate
# --trace` writes, since frames between steps are drawn from a copy of the run and never split its
# steps; a scene that `simulate` runs renders, and one it cannot run fails `render` too.
#
# usage: bash tests/render/cli/one_run_test.sh <path-to-rigidreel> <project-source-dir>
set -u

source "$(dirname "$0")/cli_harness.sh"
cli_setup one-run-test "$@"

# a ball thrown at a spinning box under the event method, a timed impulse at an instant between
# steps, coarse explicit Euler steps (where splitting a step shows in every later digit)
cat >throw.yaml <<'YAML'
name: throw
duration: 1
world: {gravity: [0, -9.81], restitution: 0.8}
sim: {collisions: event, dt: 0.004, integrator: explicit_euler}
bodies:
  - {name: floor, shape: {box: [6, 0.2]}, position: [0, -1], static: true}
  - {name: ball, shape: {circle: 0.15}, position: [-1.5, 0], velocity: [3, 1]}
  - {name: box, shape: {box: [0.4, 0.3]}, position: [0.3, -0.2], angular_velocity: 4}
events:
  - {time: 0.3333, body: box, point: [0.2, 0], impulse: [0, 0.5]}
render: {title_card: 0.3, slow_motion: {factor: 3, from: 0.4, to: 0.6}}
YAML
run simulate throw.yaml --trace sim.csv
check "simulate --trace writes a trace" $(( rc != 0 || $(wc -l <sim.csv) < 700 ))
run render throw.yaml -o o --size 320x180 --fps 10 --quiet --trace small.csv
check "render at 320x180 and 10 fps exits 0" "$rc"
cmp -s sim.csv small.csv
check "render at 320x180, 10 fps: the trace of simulate, byte for byte" $?
run render throw.yaml -o o --size 1280x720 --fps 60 --quiet --trace large.csv
check "render at 1280x720 and 60 fps exits 0" "$rc"
cmp -s sim.csv large.csv
check "render at 1280x720, 60 fps: the trace of simulate, byte for byte" $?
run snapshot throw.yaml -o o --size 160x90 --at 0.1234,0.5555,0.98765 --trace snap.csv
check "snapshot at three odd times exits 0" "$rc"
cmp -s sim.csv snap.csv
check "snapshot at three odd times: the trace of simulate, byte for byte" $?
# --duration ends the run where simulate --until does
run simulate throw.yaml --until 0.77 --trace until.csv
run render throw.yaml -o o --size 160x90 --fps 7 --duration 0.77 --quiet --trace short.csv
[ "$rc" -eq 0 ] && cmp -s until.csv short.csv
check "render --duration 0.77: the trace of simulate --until 0.77" $?
expect "a trace of several variants is refused" 2 "--trace" \
  snapshot "$SRC/scenes/three_collisions_poll.yaml" -o o --panels --at 1 --trace p.csv
[ ! -e p.csv ]
check "no trace file is left by a refused run" $?

# the spinning pentagon on a slab (event method, c_r 0.7, dt 1 ms, 3 s): it once failed `render` at
# 60 fps with "more than 10000 impacts in one step" at t = 2.381, where the frame times split its
# steps, while `simulate` ran it; the frame size never mattered, so a small one stands for 1280x720
cat >pentagon.yaml <<'YAML'
name: pentagon
duration: 3
world: {gravity: [0, -9.81], restitution: 0.7}
sim: {collisions: event, dt: 0.001}
bodies:
  - {name: slab, shape: {box: [4, 0.2]}, position: [0, 0], static: true}
  - name: pentagon
    shape: {polygon: [[0.3, 0], [0.0927, 0.2853], [-0.2427, 0.1763], [-0.2427, -0.1763], [0.0927, -0.2853]]}
    position: [0, 1]
    angular_velocity: 6
YAML
run simulate pentagon.yaml --trace pentagon-sim.csv
check "simulate runs the spinning pentagon" "$rc"
run render pentagon.yaml -o o --size 320x180 --fps 60 --quiet --trace pentagon-render.csv
check "render at 60 fps runs it too" "$rc"
cmp -s pentagon-sim.csv pentagon-render.csv
check "and its trace is simulate's" $?

# `check` runs every variant to its duration: a scene that diverges at t = 10.25, long after its last
# expect entry (t = 0), fails it, as it fails simulate and render
cat >diverge.yaml <<'YAML'
name: diverge
duration: 60
sim: {integrator: explicit_euler, dt: 0.05, collisions: none}
bodies:
  - {name: ball, shape: {circle: 0.1}, position: [1, 0]}
forces:
  - {type: spring, body: ball, anchor: [0, 0], stiffness: 400}
expect:
  - {time: 0, body: ball, position: [1, 0], tolerance: 1e-12}
YAML
expect "check fails a scene that diverges after its last expect entry" 1 "diverged at t = 10.25: body 'ball'" check diverge.yaml
grep -q "ok    t = 0  ball.position" out && grep -q "FAIL  the simulation diverged at t = 10.25" out
check "check prints the entry that passed and the failure that followed" $?
run simulate diverge.yaml
check "simulate fails it too" $(( rc != 1 ))

# quiet by default: the pentagon's many staying-in-contact records are one line per pair
run check pentagon.yaml
[ "$rc" -eq 0 ] && [ "$(grep -c "stay in contact" out)" -eq 1 ] && grep -q "stay in contact from t = .* to .* ([0-9]* times;" out
check "check merges the pentagon's staying-in-contact records into one line" $?
run check pentagon.yaml --verbose
[ "$rc" -eq 0 ] && [ "$(grep -c "stay in contact" out)" -gt 10 ]
check "check --verbose lists every record" $?
run simulate pentagon.yaml
[ "$rc" -eq 0 ] && [ "$(wc -c <out)" -lt 2000 ]
check "simulate's text stays short (one clause per pair)" $? "$(wc -c <out) bytes"
run simulate pentagon.yaml --json
python3 -c 'import json,sys; d=json.load(open("out")); r=d["resting"]; sys.exit(not (len(r)==1 and r[0]["count"]>10 and r[0]["last"]>r[0]["t"]))'
check "simulate --json: one resting entry per pair, with its last time and count" $?
run simulate pentagon.yaml --json --verbose
python3 -c 'import json,sys; d=json.load(open("out")); r=d["resting"]; sys.exit(not (len(r)>10 and all(e["count"]==1 for e in r)))'
check "simulate --json --verbose: every record" $?

# `check --render` plans what the scene's render block asks for: panels at impacts need an impact in
# every variant, and variant `miss` has none, so the scene checks but cannot render
cat >plan.yaml <<'YAML'
name: plan
duration: 1
sim: {collisions: event}
bodies:
  - {name: a, shape: {circle: 0.2}, position: [-1, 0], velocity: [2, 0]}
  - {name: b, shape: {circle: 0.2}, position: [0, 0]}
variants:
  hit: {}
  miss: {bodies: [{name: a, velocity: [0, 1]}]}
render: {panels: impacts}
YAML
run check plan.yaml
check "check alone passes the scene" "$rc"
expect "check --render refuses its render block at its line" 2 "plan.yaml:10:18: 'panels: impacts' needs an impact in every variant" check plan.yaml --render
run check throw.yaml --render
[ "$rc" -eq 0 ] && grep -q "render: 1 video (.* frames), 0 panel sheets planned" out
check "check --render plans a scene that renders" $?

cli_finish
