#!/usr/bin/env bash
# 3D in every course tool (issue 38): a ball bouncing on a plane recorded by `golden record` at the
# three levels and checked (a colour change fails what is shown and the pixels, a restitution change
# the state too), a testcase in JUnit and a row in the report; a folder's 3D scenes recorded beside
# its 2D ones; `compare` of a 3D trace and `expect` of a 3D scene, pasted back.
#
# usage: bash tests/render/cli/golden3d_cli_test.sh <path-to-rigidreel> <project-source-dir>
set -u

source "$(dirname "$0")/cli_harness.sh"
cli_setup golden3d-cli-test "$@"

# a ball dropped 0.8 m onto a floor (impacts at t = 0.40 and 1.05 s)
scene() {  # scene COLOR RESTITUTION: the scene's YAML
  cat <<YAML
name: drop
dimensions: 3
duration: 1.5
world: {gravity: [0, 0, -9.81], restitution: $2}
bodies:
  - {name: floor, shape: {plane: {point: [0, 0, 0], normal: [0, 0, 1]}}}
  - {name: ball, shape: {sphere: 0.2}, position: [0, 0, 1], color: "$1"}
golden: {at: [0.5, 1.5], size: [160, 90]}
YAML
}
scene "#c8553d" 0.8 >drop.yaml
G=golden/drop

# ---- record: the three levels of a 3D scene ---------------------------------------------------
run golden record drop.yaml
# the frames: at 0.5 and 1.5, and at the two impacts, t₁ = √(2·0.8/g) and t₁ + 2·0.8·g·t₁/g
python3 -c '
import json, math, sys
t = [f["t"] for f in json.load(open(sys.argv[1]))["frames"]]
t1 = math.sqrt(2 * 0.8 / 9.81)
assert len(t) == 4 and t[1] == 0.5 and t[3] == 1.5, t
assert abs(t[0] - t1) < 1e-3 and abs(t[2] - (t1 + 2 * 0.8 * t1)) < 1e-2, t' $G/manifest.json
frames=$?
[ "$rc" -eq 0 ] && [ -f $G/states.csv ] && [ -f $G/frame-t0.5.png ] && [ -f $G/frame-t1.5.json ] && [ "$frames" -eq 0 ]
check "golden record of a 3D scene: hashes, trace and the frames at 0.5, 1.5 and both impacts" $? "exit $rc: $(ls $G 2>/dev/null)"
head -1 $G/trace.csv | grep -qx "t,body,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,kinetic_energy" &&
  [ "$(grep -c ',ball,' $G/trace.csv)" -eq "$(($(wc -l <$G/states.csv) - 1))" ]
check "its trace has the 3D columns, a row of the ball per checkpoint" $?
grep -q '"kind":"solid","pen":"Body#0","color":"#c8553d"' $G/frame-t0.5.json
check "its draw list holds the ball's solid in its colour" $? "$(head -c 300 $G/frame-t0.5.json)"
run golden check drop.yaml --junit ok.xml
[ "$rc" -eq 0 ] && [ "$(grep -c '  ok: ' out)" -eq 3 ] && [ "$(junit ok.xml)" = "3 0" ]
check "record then check: the three levels ok, JUnit 3 testcases" $? "exit $rc, junit $(junit ok.xml)"

# ---- a colour: what is shown and the pixels fail, the state does not -------------------------
scene "#2ca02c" 0.8 >drop.yaml
run golden check drop.yaml --junit colour.xml
[ "$rc" -eq 1 ] && level state | grep -q "ok: .* state hashes equal" && level draw_list | grep -q "FAIL.*#2ca02c" &&
  level pixels | grep -q FAIL && [ "$(junit colour.xml)" = "3 2" ]
check "a colour change fails draw_list and pixels, not the state" $? "exit $rc, junit $(junit colour.xml)"

# ---- restitution: the state fails, named where -------------------------------------------------
scene "#c8553d" 0.5 >drop.yaml
run golden check drop.yaml --junit rest.xml --report rest
[ "$rc" -eq 1 ] && level state | grep -q "FAIL.*largest error: position .*'ball'.*the physics changed" &&
  [ "$(junit rest.xml)" = "3 3" ]
check "a restitution change fails the state level, naming the ball" $? "exit $rc: $(level state)"
grep -q '<td><a href="#drop">drop</a></td><td>state</td><td class="failed">' rest/index.html && [ -f rest/drop/frame-t1.5-diff.png ]
check "the report has the 3D scene's rows and its diff images" $?

# ---- a folder: its 3D scenes recorded and checked beside its 2D ones --------------------------
mkdir pack
scene "#c8553d" 0.8 >pack/drop.yaml
printf 'name: fall\nduration: 1\nworld: {gravity: [0, -9.81]}\nbodies: [{name: b, shape: {circle: 0.1}}]\ngolden: {size: [160, 90]}\n' >pack/fall.yaml
run golden record pack -o packgold
[ "$rc" -eq 0 ] && ! grep -q skipped err && [ -f packgold/drop/manifest.json ] && [ -f packgold/fall/manifest.json ]
check "golden record DIR records the 3D scene too, skipping nothing" $? "$(cat err)"
run golden check pack --golden packgold --junit pack.xml
[ "$rc" -eq 0 ] && [ "$(junit pack.xml)" = "6 0" ] &&
  python3 -c 'import sys, xml.etree.ElementTree as ET; names = {c.get("classname") for c in ET.parse(sys.argv[1]).iter("testcase")}; assert names == {"drop", "fall"}, names' pack.xml
check "golden check DIR: the 3D and the 2D scene each 3 testcases" $? "junit $(junit pack.xml)"

# ---- compare: a 3D trace ------------------------------------------------------------------------
scene "#c8553d" 0.8 >drop.yaml
run simulate drop.yaml --trace ours.csv
run compare drop.yaml --trace ours.csv
[ "$rc" -eq 0 ] && grep -q "^  ok    ball " out
check "compare of a 3D scene against its own simulate --trace passes" $? "$(cat out) $(cat err)"
awk -F, -v OFMT=%.17g -v CONVFMT=%.17g 'BEGIN { OFS = "," } NR > 1 && $1 > 1 { $5 = $5 + 0.01 } { print }' ours.csv >moved.csv
run compare drop.yaml --trace moved.csv
[ "$rc" -eq 1 ] && grep -Eq "^  FAIL  ball .*position 0.01 at t = 1.00[0-9]*, over 0.001 from t = 1.00" out
check "the ball's z moved by 0.01 after t = 1 fails, naming when" $? "$(cat out)"
# a quarter turn about x in their trace: the angle error is π/2
awk -F, -v OFMT=%.17g -v CONVFMT=%.17g 'BEGIN { OFS = "," } NR > 1 { $6 = sqrt(0.5); $7 = sqrt(0.5) } { print }' ours.csv >turned.csv
run compare drop.yaml --trace turned.csv
[ "$rc" -eq 1 ] && grep -q "angle 1.5708 at t = 0" out
check "an orientation a quarter turn off is an angle error of pi/2" $? "$(cat out)"

# ---- expect: a 3D scene's entries, pasted back --------------------------------------------------
run expect drop.yaml --at 0.3,1.2 --tolerance 1e-12
[ "$rc" -eq 0 ] && [ "$(grep -c '^  - {time: .*, body: ball, position: \[.*\], orientation: \[.*\], velocity: \[.*\], angular_velocity: \[.*\], tolerance: 1e-12, source: earlier_run}$' out)" -eq 2 ]
check "expect of a 3D scene: position, orientation, velocity and angular_velocity of the ball" $? "$(cat out)"
pasted drop.yaml 8 "the pasted 3D entries pass check (8 comparisons)"
sed -i '0,/velocity: \[0, 0, /s//velocity: [0.001, 0, /' pasted.yaml
run check pasted.yaml
[ "$rc" -eq 1 ]
check "one value altered fails it" $? "$(grep FAIL out)"

cli_finish
