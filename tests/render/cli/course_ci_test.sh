#!/usr/bin/env bash
# A course's CI in one command (issue 38): `check` ends with one summary line and writes JUnit (read
# by python's XML parser, its counts the summary's); -q and -v on golden, compare and expect; expect's
# entries marked `source: earlier_run`, read back by check; `golden check --update` leaves no stale
# "changed since it was recorded" warning on the variants it kept.
#
# usage: bash tests/render/cli/course_ci_test.sh <path-to-rigidreel> <project-source-dir>
set -u

source "$(dirname "$0")/cli_harness.sh"
cli_setup course-ci-test "$@"

# a ball falling freely: y = 2 - 4.905 t², the variant `wrong` expecting y = 0 at t = 0.5
mkdir pack
cat >pack/a_drop.yaml <<'YAML'
duration: 1
world: {gravity: [0, -9.81]}
sim: {integrator: rk4, dt: 0.01}
bodies:
  - {name: ball, shape: {circle: 0.1}, position: [0, 2]}
expect:
  - {time: 0.5, body: ball, position: [0, 0.77375], tolerance: 1e-9}
variants:
  right: {}
  wrong:
    expect:
      - {time: 0.5, body: ball, position: [0, 0], tolerance: 1e-9}
YAML
# a 3D box moving freely, a variant of its own
cat >pack/b_glide.yaml <<'YAML'
dimensions: 3
duration: 1
bodies:
  - {name: box, shape: {box: [0.2, 0.2, 0.2]}, velocity: [1, 0, 0]}
expect:
  - {time: 1, body: box, position: [1, 0, 0], tolerance: 1e-12}
YAML

# ---- check: the summary line and JUnit ------------------------------------------------------
run check pack --junit ci.xml
summary=$(tail -1 out)
[ "$rc" -eq 1 ] && [ "$summary" = "2 scenes, 3 variants: 2 passed, 1 failed" ]
check "check ends with the summary line: 2 scenes, 3 variants, the wrong one failed (exit 1)" $? "last line: $summary"
[ "$(junit ci.xml)" = "3 1" ]
check "its JUnit parses: a testcase per variant, one failure" $? "junit $(junit ci.xml)"
python3 -c '
import sys, xml.etree.ElementTree as ET
failed = [c for c in ET.parse(sys.argv[1]).getroot().iter("testcase") if c.find("failure") is not None]
assert len(failed) == 1, failed
c = failed[0]
assert c.get("classname") == "pack/a_drop.yaml" and c.get("name") == "wrong", c.attrib
assert "ball.position" in c.find("failure").get("message") and "expected (0, 0)" in c.find("failure").get("message")' ci.xml
check "the failed testcase is the file's variant 'wrong', its message the failed entry" $?
grep -c "^  FAIL  t = 0.5  ball.position" out | grep -qx 1
check "the failed entry is printed once" $?

# a file that cannot be read is a failed testcase of its own, counted in the summary (exit 2)
printf 'bodies: [{name: b, shape: {circle: -1}}]\n' >pack/c_bad.yaml
run check pack --junit bad.xml
[ "$rc" -eq 2 ] && [ "$(tail -1 out)" = "3 scenes, 4 variants: 2 passed, 2 failed" ] && [ "$(junit bad.xml)" = "4 2" ]
check "an unreadable scene: exit 2, counted as a failed variant in the summary and the JUnit" $? "$(tail -1 out), junit $(junit bad.xml)"
rm pack/c_bad.yaml

# -q: nothing when everything passes, else the failed entries and the summary
run check pack/b_glide.yaml -q
[ "$rc" -eq 0 ] && [ ! -s out ]
check "check -q of a passing scene prints nothing" $?
run check pack -q
[ "$rc" -eq 1 ] && [ "$(wc -l <out)" -eq 2 ] && grep -q "^pack/a_drop.yaml \[wrong\]:  FAIL" out &&
  [ "$(tail -1 out)" = "2 scenes, 3 variants: 2 passed, 1 failed" ]
check "check -q of a failing pack: the failed entry, then the summary" $? "$(cat out)"

# ---- expect: source: earlier_run, pasted back and read ----------------------------------------
run expect pack/a_drop.yaml --at 0.25,1
[ "$rc" -eq 0 ] && [ "$(grep -c '^  - {time: .*, source: earlier_run}$' out)" -eq 2 ]
check "expect marks every entry source: earlier_run" $? "$(cat out)"
{ sed '/^expect:/,$d' pack/a_drop.yaml; cat out; } >pasted.yaml
run check pasted.yaml
[ "$rc" -eq 0 ] && [ "$(grep -c '^  ok ' out)" -eq 8 ]
check "the pasted entries are read back and pass check (8 comparisons)" $? "$(cat out)"
# the lecture page lists the pasted entries apart from the scene's closed form (expect -q's entries
# appended under it): 4 rows a time
run expect pack/a_drop.yaml --at 0.25,1 -q
{ sed '/^variants:/,$d' pack/a_drop.yaml; cat out; } >mixed.yaml
run lecture mixed.yaml -o lect --size 160x90 --fps 10 -j 1 -q
python3 -c '
import re, sys
html = open(sys.argv[1]).read()
closed = html.split("<h3>Closed forms, checked</h3>")[1].split("</table>")[0]
earlier = html.split("<h3>Checked against an earlier run</h3>")[1].split("</table>")[0]
rows = lambda part: re.findall(r"<tr><td data-label=\"variant\">[^<]*</td><td class=\"number\" data-label=\"t \(s\)\">([^<]*)</td><td data-label=\"quantity\">([^<]*)</td>", part)
assert rows(closed) == [("0.5", "ball.position")], rows(closed)
assert len(rows(earlier)) == 8 and ("0.25", "ball.angular_velocity") in rows(earlier), rows(earlier)' lect/index.html
check "the lecture page lists them under 'Checked against an earlier run', the scene's own under closed forms" $? "exit $rc"
run expect pack/a_drop.yaml -q
[ "$rc" -eq 0 ] && [ "$(wc -l <out)" -eq 1 ] && grep -q '^  - {time: 1, body: ball' out
check "expect -q prints the entries alone, to append under a scene's expect:" $? "$(cat out)"
run expect pack/a_drop.yaml -v
[ "$rc" -eq 0 ] && grep -q "^# measured as check runs the scene: integrator rk4, dt 0.01 s" out && grep -q "^expect:" out
check "expect -v says how the entries were measured" $? "$(cat out)"

# ---- compare -q / -v --------------------------------------------------------------------------
run simulate pack/a_drop.yaml --trace ours.csv
rows=$(grep -c ',ball,' ours.csv)
run compare pack/a_drop.yaml --trace ours.csv -q
[ "$rc" -eq 0 ] && [ ! -s out ]
check "compare -q of a passing trace prints nothing" $?
awk -F, -v OFMT=%.17g 'BEGIN { OFS = "," } NR > 1 && $1 > 0.5 { $4 = $4 + 0.01 } { print }' ours.csv >moved.csv
run compare pack/a_drop.yaml --trace moved.csv -q
[ "$rc" -eq 1 ] && [ "$(wc -l <out)" -eq 1 ] && grep -q "^  FAIL  ball" out
check "compare -q of a failing trace prints the failed body alone" $? "$(cat out)"
run compare pack/a_drop.yaml --trace ours.csv -v
[ "$rc" -eq 0 ] && [ "$(grep -c '^  ball t = ' out)" -eq "$rows" ] && grep -q "^  ball t = 0.5: position 0, angle 0, velocity 0$" out
check "compare -v prints the errors at every instant compared ($rows rows)" $? "$(grep -c '^  ball t = ' out) lines"

# ---- golden -q / -v ---------------------------------------------------------------------------
cat >pair.yaml <<'YAML'
name: pair
duration: 1
world: {gravity: [0, -9.81]}
bodies:
  - {name: ball, shape: {circle: 0.2}, position: [0, 1], color: "#c8553d"}
golden: {at: [0.5], size: [160, 90], impacts: false}
variants:
  slow: {}
  fast: {bodies: [{name: ball, velocity: [1, 0], color: "#c8553d"}]}
YAML
run golden record pair.yaml -q
[ "$rc" -eq 0 ] && [ ! -s out ] && [ -f golden/pair-slow/manifest.json ] && [ -f golden/pair-fast/frame-t0.5.png ]
check "golden record -q prints nothing and writes the records" $?
run golden record pair.yaml -v
hash=$(sed -n 2p golden/pair-slow/states.csv | cut -d, -f2)
[ "$rc" -eq 0 ] && grep -q "^  checkpoint t = 0.5: state hash $hash$" out && grep -q "^  frame-t0.5.json, frame-t0.5.png$" out
check "golden record -v lists each checkpoint's hash (as states.csv) and each frame's files" $? "$(cat out)"
run golden check pair.yaml -q
[ "$rc" -eq 0 ] && [ ! -s out ]
check "golden check -q of passing records prints nothing" $?
run golden check pair.yaml -v
[ "$rc" -eq 0 ] && grep -q "^pair-slow: against golden/pair-slow (rigidreel .*)$" out && [ "$(grep -c '  ok: ' out)" -eq 6 ]
check "golden check -v names the record each variant is checked against" $? "$(cat out)"
expect "-q and -v together are bad input (golden check)" 2 "excludes" golden check pair.yaml -q -v

# ---- golden check --update: no stale warning on the variant it kept ---------------------------
sed -i '$s/#c8553d/#2ca02c/' pair.yaml
run golden check pair.yaml
[ "$rc" -eq 1 ] && grep -q "pair-slow: warning: pair.yaml changed since it was recorded" err
check "a changed file warns on the variant whose run did not change" $? "$(cat err)"
run golden check pair.yaml -q
[ "$rc" -eq 1 ] && ! grep -q "^pair-slow" out && grep -q "^pair-fast  draw_list  FAIL" out
check "golden check -q prints the failed levels alone" $? "$(cat out)"
run golden check pair.yaml --update
[ "$rc" -eq 0 ] && grep -q "^updated golden/pair-fast" out && grep -q "^restamped golden/pair-slow" out
check "--update records the changed variant anew and restamps the other" $? "$(cat out)"
sha=$(sha256sum pair.yaml | cut -d' ' -f1)
python3 -c 'import json,sys; assert json.load(open(sys.argv[1]))["scene_sha256"] == sys.argv[2]' golden/pair-slow/manifest.json "$sha"
check "the kept record's manifest has the file's new sha256" $?
run golden check pair.yaml
[ "$rc" -eq 0 ] && [ ! -s err ] && [ "$(grep -c '  ok: ' out)" -eq 6 ]
check "after --update, check passes with no warning" $? "$(cat err)"

# ---- the same flags everywhere ----------------------------------------------------------------
for sub in "golden record" "golden check" compare expect; do
  run $sub --help
  grep -q -- "-q,--quiet" out && grep -q -- "-v,--verbose" out
  check "$sub takes -q/--quiet and -v/--verbose" $?
done

cli_finish
