#!/usr/bin/env bash
# `rigidreel golden record | check`, `compare` and `expect` end to end (issue 22): a record checks
# clean; a colour change fails what is shown and the pixels but not the state; a restitution change
# fails all three; a re-encoded PNG one pixel off passes; each failure writes its diff images and a
# JUnit XML that python's parser reads with the right failure count; --update and the renderer
# check; another simulator's trace graded; expect entries pasted back pass `check`.
#
# usage: bash tests/render/cli/golden_cli_test.sh <path-to-rigidreel> <project-source-dir>
set -u

source "$(dirname "$0")/cli_harness.sh"
cli_setup golden-cli-test "$@"
TOUCH=$SRC/tests/render/golden/png_touch.py

# a ball hitting a block off its center (an impact at t = 0.75, the block spinning off)
scene() {  # scene COLOR RESTITUTION: the scene's YAML
  cat <<YAML
name: pair
duration: 1.5
world: {restitution: $2}
sim: {collisions: event}
bodies:
  - {name: ball, shape: {circle: 0.25}, mass: 1, inertia: 0.2, position: [0, 0], velocity: [1, 0], color: "$1"}
  - {name: block, shape: {box: [1.0, 1.0]}, mass: 1, inertia: 0.2, position: [1.5, 0.4], color: "#3b6ea5"}
golden: {at: [0.5, 1.5], size: [320, 180]}
YAML
}
scene "#c8553d" 1 >pair.yaml
G=golden/pair

# --- record, then check: every level passes
run golden record pair.yaml
check "golden record exits 0" "$rc"
[ -f $G/manifest.json ] && [ -f $G/states.csv ] && [ -f $G/trace.csv ] &&
  [ -f $G/frame-t0.5.png ] && [ -f $G/frame-t0.75.json ] && [ -f $G/frame-t1.5.png ]
check "the record holds the manifest, hashes, trace and each golden frame (at, impact, end) as PNG and JSON" $? "$(ls $G)"
python3 -c '
import json, sys
m = json.load(open(sys.argv[1]))
assert m["size"] == [320, 180] and m["checkpoints"] == [0.5, 0.75, 1.5], m
assert len(m["scene_sha256"]) == 64 and m["renderer"] and m["renderer_version"], m
assert m["tolerance"]["pixel_tolerance"] == 24 and m["tolerance"]["position"] == 1e-9, m' $G/manifest.json
check "manifest.json: size, checkpoints, sha256, renderer and tolerances" $?
[ "$(sha256sum pair.yaml | cut -d' ' -f1)" = "$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["scene_sha256"])' $G/manifest.json)" ]
check "the manifest's sha256 is the scene file's (sha256sum)" $?
[ "$(wc -l <$G/states.csv)" -eq 4 ] && [ "$(wc -l <$G/trace.csv)" -eq 7 ] && head -1 $G/trace.csv | grep -qx "t,body,x,y,angle,vx,vy,omega,kinetic_energy"
check "a hash per checkpoint, a trace row per body and checkpoint in the --trace columns" $?
run golden check pair.yaml --junit ok.xml
[ "$rc" -eq 0 ] && [ "$(grep -c '  ok: ' out)" -eq 3 ] && [ "$(junit ok.xml)" = "3 0" ]
check "record then check: all three levels ok, exit 0, JUnit 3 testcases 0 failures" $? "exit $rc, junit $(junit ok.xml)"

# --- a body's colour: the draw list and the pixels fail, the state passes
scene "#2ca02c" 1 >pair.yaml
run golden check pair.yaml --report colour --junit colour.xml
[ "$rc" -eq 1 ] && level state | grep -q "ok: 3 state hashes equal" && level draw_list | grep -q "FAIL.*color #2ca02c, expected #c8553d" &&
  level pixels | grep -q "FAIL"
check "a colour change fails draw_list and pixels, not the state (exit 1)" $? "exit $rc"
[ "$(junit colour.xml)" = "3 2" ]
check "its JUnit XML parses with 2 failures of 3" $? "got $(junit colour.xml)"
[ -f colour/index.html ] && [ -f colour/pair/frame-t0.5-diff.png ] && [ -f colour/pair/frame-t0.5-actual.png ] &&
  [ -f colour/pair/frame-t0.5-expected.png ] && grep -q 'src="pair/frame-t1.5-diff.png"' colour/index.html
check "the report shows expected, actual and diff of each failed frame" $?
cmp -s colour/pair/frame-t0.5-expected.png $G/frame-t0.5.png && ! cmp -s colour/pair/frame-t0.5-actual.png $G/frame-t0.5.png
check "expected is the record's frame, actual the new one" $?

# --- restitution: all three levels fail; the state names the error and where
scene "#c8553d" 0.5 >pair.yaml
run golden check pair.yaml --report rest --junit rest.xml
[ "$rc" -eq 1 ] && level state | grep -q "FAIL.*first at t = 0.75.*the physics changed" && level draw_list | grep -q FAIL &&
  level pixels | grep -q FAIL && [ "$(junit rest.xml)" = "3 3" ] && [ -f rest/pair/frame-t1.5-diff.png ]
check "a restitution change fails all three levels, JUnit 3 failures, diff images written" $? "exit $rc, junit $(junit rest.xml)"

# --- a PNG re-encoded by another encoder with one pixel off by 10: within the pixel tolerance
scene "#c8553d" 1 >pair.yaml
python3 "$TOUCH" $G/frame-t0.5.png touched.png 160 90 10 && ! cmp -s touched.png $G/frame-t0.5.png && mv touched.png $G/frame-t0.5.png
check "png_touch re-encodes the frame with one pixel moved" $?
run golden check pair.yaml
[ "$rc" -eq 0 ] && level pixels | grep -q "ok: 3 frames within 24/255"
check "a re-encoded PNG with one pixel off by 10 passes the pixel level" $?
# a 40 x 40 square 100 off (1600 of 57,600 pixels, over 0.2%) fails it, and it alone
cp $G/frame-t0.5.png kept.png
python3 "$TOUCH" kept.png $G/frame-t0.5.png 100 50 100 40
run golden check pair.yaml --junit square.xml
[ "$rc" -eq 1 ] && level pixels | grep -q "FAIL  1 of 3 frames differ: frame-t0.5: 1600 pixels" && level state | grep -q ok &&
  level draw_list | grep -q ok && [ "$(junit square.xml)" = "3 1" ]
check "a 40 x 40 square 100/255 off fails the pixel level alone" $? "exit $rc"
cp kept.png $G/frame-t0.5.png

# --- a missing record names the command that makes it
expect "a missing golden folder is exit 2 and names the command that records it" 2 "rigidreel golden record pair.yaml -o nowhere" \
  golden check pair.yaml --golden nowhere

# --- --update records anew what differs and says what it replaced; the next check passes
scene "#2ca02c" 1 >pair.yaml
run golden check pair.yaml --update
[ "$rc" -eq 0 ] && grep -q "updated golden/pair.*replaced.*draw_list, pixels" out
check "--update replaces the differing record and says what it replaced" $?
run golden check pair.yaml
check "after --update the check passes" "$rc"

# --- another renderer in the manifest: pixels skipped with a warning; --strict compares them
sed -i 's/"renderer":"[^"]*"/"renderer":"another GPU"/' $G/manifest.json
run golden check pair.yaml
[ "$rc" -eq 0 ] && level pixels | grep -q "skipped: recorded with another GPU" && grep -q "warning" err
check "a record from another renderer skips the pixel level with a warning" $?
run golden check pair.yaml --strict
[ "$rc" -eq 0 ] && level pixels | grep -q "ok: 3 frames"
check "--strict compares the pixels anyway" $?

# --- the golden: block is checked where it is read, by every command
printf 'bodies: [{name: b, shape: {circle: 1}}]\ngolden: {at: [0.5], pixel_fraction: 2}\n' >badgolden.yaml
expect "a bad golden: key is refused at its line (check)" 2 "badgolden.yaml:2:37: 'pixel_fraction' must be from 0 to 1" check badgolden.yaml
printf 'bodies: [{name: b, shape: {circle: 1}}]\ngolden: {at: [0.5], sizes: [2, 2]}\n' >badgolden.yaml
expect "an unknown golden: key names the nearest (render)" 2 "did you mean 'size'" render badgolden.yaml

# --- compare: our own trace passes; one body 0.01 off after t = 1 fails, naming it and when
run simulate pair.yaml --trace ours.csv
run compare pair.yaml --trace ours.csv
[ "$rc" -eq 0 ] && [ "$(grep -c '^  ok    ' out)" -eq 2 ]
check "compare against its own simulate --trace passes for both bodies" $? "exit $rc"
awk -F, -v OFMT=%.17g -v CONVFMT=%.17g 'BEGIN { OFS = "," } NR > 1 && $2 == "block" && $1 > 1 { $3 = $3 + 0.01 } { print }' ours.csv >moved.csv
run compare pair.yaml --trace moved.csv
[ "$rc" -eq 1 ] && grep -q "^  ok    ball" out && grep -Eq "^  FAIL  block .*position 0.01 at t = 1.001, over 0.001 from t = 1.001;" out
check "block's x moved by 0.01 after t = 1 fails, naming block and t = 1.001" $? "$(cat out)"
# a student's simulator on its own grid (h = 0.0137 s): the closed form of a spinning throw
cat >throw.yaml <<'YAML'
name: throw
duration: 2
world: {gravity: [0, -9.81]}
sim: {integrator: rk4, dt: 0.01}
bodies:
  - {name: box, shape: {box: [0.5, 0.25]}, density: 8, position: [0, 1], angle: 0.3, velocity: [3, 8], angular_velocity: 5}
YAML
python3 - <<'PY'
# x = 3 t, y = 1 + 8 t - 4.905 t², θ = 0.3 + 5 t: what a student's code writes
with open("student.csv", "w") as f:
    f.write("t,body,x,y,angle,vx,vy,omega\n")
    n = int(2 / 0.0137) + 1
    for i in range(n + 1):
        t = min(i * 0.0137, 2.0)
        f.write(f"{t},box,{3 * t},{1 + 8 * t - 4.905 * t * t},{0.3 + 5 * t},3,{8 - 9.81 * t},5\n")
PY
run compare throw.yaml --trace student.csv --plot plot
[ "$rc" -eq 0 ] && grep -Eq "^  ok    box .*position 0.000[0-9]+" out && [ -s plot/throw-compare.png ]
check "a trace on another time grid is interpolated (error h²g/8 = 2.3e-4 m), within tolerance, and charted" $? "$(cat out)"
run compare throw.yaml --trace student.csv --tolerance position=1e-5
[ "$rc" -eq 1 ] && grep -q "FAIL  box" out
check "the same trace beyond a tighter --tolerance fails" $?
printf 't,body,x,y,angle,vx,vy,omega\n0,box,0,1,0.3,3,8,5\n0.5,box,1.5,two,2.8,3,3.1,5\n' >bad.csv
expect "a malformed CSV is refused at its line and column" 2 "bad.csv:3:13: expected a finite number for 'y', got 'two'" \
  compare throw.yaml --trace bad.csv
printf 't,body,x,y,angle,vx,vy,omega\n0,box,0,1,0.3,3,8,5\n0,lid,0,1,0.3,3,8,5\n' >ghost.csv
expect "a row for a body the scene lacks is refused at its line" 2 "ghost.csv:3:3: the scene has no body named 'lid'" \
  compare throw.yaml --trace ghost.csv
expect "a bad --tolerance is exit 2" 2 "--tolerance: expected position=X" compare throw.yaml --trace student.csv --tolerance speed=1

# --- --overlay: their trace drawn over ours (the frame test checks what it draws); bad input refused
run snapshot throw.yaml --at 1 --overlay student.csv -o shots --size 320x180
[ "$rc" -eq 0 ] && [ -s shots/throw/throw-t1.png ] && run snapshot throw.yaml --at 1 -o plain --size 320x180 &&
  ! cmp -s shots/throw/throw-t1.png plain/throw/throw-t1.png
check "snapshot --overlay draws a frame unlike the one without" $?
expect "an --overlay trace with a body the scene lacks is refused at its line" 2 "ghost.csv:3:3: the scene has no body named 'lid'" \
  render throw.yaml --overlay ghost.csv -o vids --size 320x180 --fps 10 --quiet

# --- expect: entries pasted into the scene make check pass (and one altered value fails it)
run expect pair.yaml --at 0.5,1,1.5 --tolerance 1e-12
[ "$rc" -eq 0 ] && [ "$(grep -c '^  - {time: ' out)" -eq 6 ]
check "expect prints an entry per moving body and time" $?
pasted pair.yaml 24 "the pasted entries pass check: 24 comparisons ok"
sed -i '0,/angular_velocity: 0,/s//angular_velocity: 1e-9,/' pasted.yaml
run check pasted.yaml
check "an entry off by 1e-9 fails with tolerance 1e-12" $([ "$rc" -eq 1 ]; echo $?)

cli_finish
