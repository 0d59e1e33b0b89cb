#!/usr/bin/env bash
# `rigidreel lecture` end to end on a small pack of copies of scenes/: one job per scene, the
# outputs it plans (--list) are the ones it writes, the summary, `panels:` times and impacts; and
# the errors: a missing or empty directory, a bad scene file (exit 2 before anything renders),
# a scene failing mid-render while the others finish (exit 1, its message, the others' outputs).
#
# usage: bash tests/render/cli/lecture_cli_test.sh <path-to-rigidreel> <project-source-dir>
set -u

source "$(dirname "$0")/cli_harness.sh"
cli_setup lecture-cli-test "$@"
SMALL=(--size 160x90 --fps 10)

# the pack: the poll (2 variants: panels at its duration by default), the three collisions at their
# impacts, and a scene without variants (no panels)
mkdir pack
cp "$SRC/scenes/poll_bar_impulse.yaml" pack/a_poll.yaml
cp "$SRC/scenes/three_collisions_poll.yaml" pack/b_three.yaml
printf 'render: {panels: impacts, reveal: 0}\n' >>pack/b_three.yaml
cp "$SRC/scenes/two_bodies.yaml" pack/c_two.yaml

run lecture pack "${SMALL[@]}" -o o --list
sort out >planned
cat >want <<'LIST'
o/index.html
o/poll_bar_impulse/page.json
o/poll_bar_impulse/poll_bar_impulse-center.mp4
o/poll_bar_impulse/poll_bar_impulse-center.png
o/poll_bar_impulse/poll_bar_impulse-end.mp4
o/poll_bar_impulse/poll_bar_impulse-end.png
o/poll_bar_impulse/poll_bar_impulse-panels-t2.png
o/three_collisions_poll/page.json
o/three_collisions_poll/three_collisions_poll-A.mp4
o/three_collisions_poll/three_collisions_poll-A.png
o/three_collisions_poll/three_collisions_poll-B.mp4
o/three_collisions_poll/three_collisions_poll-B.png
o/three_collisions_poll/three_collisions_poll-C.mp4
o/three_collisions_poll/three_collisions_poll-C.png
o/three_collisions_poll/three_collisions_poll-panels-impact1.png
o/two_bodies/page.json
o/two_bodies/two_bodies.mp4
o/two_bodies/two_bodies.png
LIST
[ "$rc" -eq 0 ] && cmp -s planned want && [ ! -e o ]
check "--list plans each variant's video and poster, the panels, each scene's record and the page, and renders nothing" $? "$(diff planned want)"

run lecture pack "${SMALL[@]}" -o o -j 2
find o -type f | sort >written
[ "$rc" -eq 0 ] && cmp -s written want
check "the pack writes exactly what --list planned" $? "$(diff written want)"
[ "$(grep -c '^\[[0-9]/3\] .*: [0-9]* outputs in ' out)" -eq 3 ]
check "one line per scene as its job ends" $?
grep -q '^three_collisions_poll  *ok  *8  ' out && grep -q '^two_bodies  *ok  *3  ' out &&
  grep -q '^total: 3 scenes, 18 outputs with the page, .* s wall time (2 at a time)$' out
check "the summary: each scene with its outputs, then the total wall time" $?
grep -qx 'page: o/index.html (3 scenes)' out
check "the page is rebuilt from the pack's records once the jobs end" $?
[ "$(grep -c '<section id="scene-' o/index.html)" -eq 3 ] && grep -q '<video controls preload="metadata" width="160" height="90" poster="two_bodies/two_bodies.png"' o/index.html &&
  grep -q '<span class="answer">answer</span> · impact 1' o/index.html && grep -q '<td class="ok" data-label="">ok</td>' o/index.html
check "the page: a section per scene, its videos at their size with posters, panels, checks" $?
bad_png=0
for f in $(grep '\.png$' want); do
  [ "$(head -c 8 "$f" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || bad_png=1
done
[ "$bad_png" -eq 0 ] &&
  [ "$(ffprobe -v error -select_streams v:0 -show_entries stream=codec_name,width,height -of csv=p=0 o/two_bodies/two_bodies.mp4)" = "h264,160,90" ]
check "PNGs are PNGs and videos H.264 at the size asked" $?
! find o -name '*.part*' | grep -q .
check "no temporary files left" $?

# one scene is one job, in this process: the files it wrote, then its row
run lecture pack/c_two.yaml "${SMALL[@]}" -o one -j 1
[ "$rc" -eq 0 ] && grep -qx 'wrote one/two_bodies/two_bodies.mp4' out && grep -qx 'wrote one/two_bodies/two_bodies.png' out &&
  grep -qx 'wrote one/two_bodies/page.json' out && grep -q '^two_bodies  *ok  *3 ' out && grep -qx 'page: one/index.html (1 scene)' out
check "a single scene runs in process and says what it wrote, then the page" $?

# the page alone, from what a folder holds: the scenes rendered one by one, as GNU Parallel or a
# Slurm array runs them, then --page; a bad record is reported at FILE:LINE:COL, the page untouched
run lecture pack/a_poll.yaml "${SMALL[@]}" -o one -j 1
cp one/index.html before.html
rm one/index.html
run lecture --page one
[ "$rc" -eq 0 ] && grep -qx 'wrote one/index.html (2 scenes)' out && cmp -s one/index.html before.html
check "--page rebuilds the page alone, the same page the last job wrote" $? "exit $rc"
printf '{"scene": "two_bodies",\n "file": [7]}\n' >one/two_bodies/page.json
expect "--page with a malformed record: exit 2 at its FILE:LINE:COL" 2 "one/two_bodies/page.json:2:10: 'file' has the wrong type" \
  lecture --page one
cmp -s one/index.html before.html
check "a failed --page leaves the page as it was" $?
expect "--page on a missing folder" 2 "nope: no such directory" lecture --page nope
expect "--page with scenes too" 2 "leave out the scenes" lecture pack --page one
expect "no scenes and no --page" 2 "give scene files or directories" lecture -o one

# errors before anything renders: exit 2 with FILE:LINE:COL, nothing written
expect "a missing directory" 2 "nope: no such file or directory" lecture nope -o o2
mkdir empty
expect "a directory without scenes" 2 "no scene files (*.yaml)" lecture empty -o o2
mkdir badpack
cp pack/a_poll.yaml pack/c_two.yaml badpack/
printf 'render:\n  panels: [0.5, 7]\n' >>badpack/c_two.yaml
expect "panels on a scene without variants" 2 "badpack/c_two.yaml:" lecture badpack -o o2
grep -q "this scene has none" err && [ ! -e o2/poll_bar_impulse ]
check "a bad scene stops the pack before any scene renders" $?
cp pack/c_two.yaml badpack/c_two.yaml
printf 'bodies: oops\n' >badpack/b_bad.yaml
run lecture badpack -o o2
[ "$rc" -eq 2 ] && grep -q "^badpack/b_bad.yaml:[0-9]*:[0-9]*: " err && [ ! -e o2/poll_bar_impulse ]
check "a malformed scene is reported at FILE:LINE:COL, exit 2" $? "exit $rc"
rm badpack/b_bad.yaml
cp pack/c_two.yaml badpack/d_same.yaml
expect "two files naming one scene" 2 "also names its scene 'two_bodies'" lecture badpack -o o2
expect "-j 0" 2 "-j" lecture pack -j 0 -o o2
expect "an odd size" 2 "even" lecture pack --size 161x90 -o o2

# a scene failing mid-render (its ffmpeg fails) while the others finish: exit 1, its message
mkdir fakebin
printf '#!/bin/sh\ncase "$*" in *two_bodies*) echo "Unknown encoder libx264" >&2; exit 1;; esac\nexec %s "$@"\n' \
  "$(command -v ffmpeg)" >fakebin/ffmpeg
chmod +x fakebin/ffmpeg
PATH=$WORK/fakebin:$PATH run lecture pack "${SMALL[@]}" -o o3 -j 2
[ "$rc" -eq 1 ] && grep -q '^two_bodies  *FAILED ' out && grep -qx "failed: two_bodies (pack/c_two.yaml):" err &&
  grep -q "^  Unknown encoder libx264" err
check "a failing scene: exit 1, named in the summary with its message" $? "exit $rc"
[ -f o3/poll_bar_impulse/poll_bar_impulse-panels-t2.png ] && [ -f o3/three_collisions_poll/three_collisions_poll-C.mp4 ] &&
  [ ! -e o3/two_bodies/two_bodies.mp4 ] && ! find o3 -name '*.part*' | grep -q .
check "the other scenes finish; the failed one leaves no half file" $?
[ ! -e o3/two_bodies/page.json ] && grep -qx 'page: o3/index.html (2 scenes)' out && ! grep -q 'scene-two_bodies' o3/index.html
check "the page shows the scenes that finished, not the failed one" $?

# Ctrl-C: the jobs are told too; exit 130 and no half file
"$BIN" lecture pack --size 320x180 --fps 200 -o o4 >out 2>err &
pid=$!
sleep 1
kill -INT $pid
wait $pid
rc=$?
[ "$rc" -eq 130 ] && grep -q interrupted err && ! find o4 -name '*.part*' | grep -q .
check "Ctrl-C stops the jobs: exit 130, no half file" $? "exit $rc"

# panels that a variant cannot have: found before anything renders. A variant shorter than the scene
# moves the default panel to the shortest duration; an asked time beyond it, or `impacts` where a
# variant has none, is bad input at the `panels:` line
mkdir short
cat >short/s.yaml <<'YAML'
name: short
duration: 1
bodies:
  - {name: box, shape: {box: [1, 1]}, velocity: [1, 0]}
variants:
  long: {}
  brief: {duration: 0.5}
YAML
run lecture short/s.yaml "${SMALL[@]}" -o so --list
grep -qx 'so/short/short-panels-t0.5.png' out
check "the default panel is at the shortest variant's duration" $? "$(cat out)"
printf 'render: {panels: [0.8]}\n' >>short/s.yaml
expect "a panel after a variant's duration: exit 2 at the panels line, nothing rendered" 2 \
  "short/s.yaml:8:19: a panel at 0.8 s is after the scene's duration (0.5 s)" lecture short/s.yaml "${SMALL[@]}" -o so
[ ! -e so ]
check "nothing written for a scene whose panels cannot be drawn" $?
sed -i 's/panels: \[0.8\]/panels: impacts/' short/s.yaml
expect "panels at impacts where a variant has none: exit 2" 2 "'panels: impacts' needs an impact in every variant" \
  lecture short/s.yaml "${SMALL[@]}" -o so

# ---- the page's title and the folder's order ------------------------------------------------
mkdir ordered
cp "$SRC/scenes/poll_bar_impulse.yaml" ordered/a_poll.yaml
cp "$SRC/scenes/two_bodies.yaml" ordered/b_two.yaml
cp "$SRC/scenes/three_collisions_poll.yaml" ordered/c_three.yaml
printf '# the course order\nc_three.yaml\n\nb_two  # .yaml may be left out\n' >ordered/order.txt
run lecture ordered "${SMALL[@]}" -o ord --list
[ "$rc" -eq 0 ] && [ "$(grep '/page.json$' out | tr '\n' ' ')" = "ord/three_collisions_poll/page.json ord/two_bodies/page.json ord/poll_bar_impulse/page.json " ]
check "a folder's order.txt orders its scenes, those it leaves out after, by name" $? "$(cat out)"
run check ordered -q
[ "$rc" -eq 0 ]
check "check of a folder with an order.txt" $?
run lecture ordered/b_two.yaml ordered/c_three.yaml "${SMALL[@]}" -o ord -j 2 --title "Rigid body motion, week 3"
grep -q '<h1>Rigid body motion, week 3</h1>' ord/index.html && grep -q '<title>Rigid body motion, week 3: 2 scenes</title>' ord/index.html &&
  [ "$(cat ord/title.txt)" = "Rigid body motion, week 3" ]
check "lecture --title titles the page and keeps the title in DIR/title.txt" $?
[ "$(grep -o '<section id="scene-[a-z_]*"' ord/index.html | tr '\n' ' ')" = '<section id="scene-three_collisions_poll" <section id="scene-two_bodies" ' ]
check "the page follows order.txt, not the names" $?
run lecture ordered/a_poll.yaml "${SMALL[@]}" -o ord
grep -q '<h1>Rigid body motion, week 3</h1>' ord/index.html && [ "$(grep -c '<section id="scene-' ord/index.html)" -eq 3 ] &&
  [ "$(grep -o '<section id="scene-[a-z_]*"' ord/index.html | tail -1)" = '<section id="scene-poll_bar_impulse"' ]
check "a later job without --title keeps the pack's title; an unlisted scene comes last" $?
run lecture --page ord --title "Week 4"
[ "$rc" -eq 0 ] && grep -q '<h1>Week 4</h1>' ord/index.html
check "--page DIR --title retitles the page" $?
expect "a title of two lines is bad input" 2 "--title: give the page's title as one line" lecture --page ord --title "$(printf 'a\nb')"
printf 'c_three.yaml\nnone.yaml\n' >ordered/order.txt
expect "order.txt naming no scene file: exit 2 at its line" 2 "ordered/order.txt:2:1: no scene file 'none.yaml'" lecture ordered --list
printf 'c_three.yaml\nc_three\n' >ordered/order.txt
expect "order.txt naming a scene twice: exit 2 at its line" 2 "ordered/order.txt:2:1: 'c_three' is listed twice" check ordered

# a poll keeps its answer: every panel after t = 0 folds under the Answer, unless `reveal` makes its
# time a question time; a question sheet shows the impulses to come; the scene file is named as the
# pack names it, never by a path of this machine (the job is given an absolute one)
mkdir polls
sed -e 's/^  panels: \[0, 2.5\]/  panels: [0, 1, 2.5]/' -e '/^  reveal: 2.5/d' "$SRC/scenes/lecture/05_impulses.yaml" >polls/p_fold.yaml
sed -e 's/^  panels: \[0, 2.5\]/  panels: [0, 1, 2.5]/' -e 's/^  reveal: 2.5/  reveal: 2/' \
  "$SRC/scenes/lecture/05_impulses.yaml" >polls/p_reveal.yaml
run lecture "$WORK/polls/p_fold.yaml" "${SMALL[@]}" -o pp -j 1
# the section up to its Answer fold
above() { sed -n "/<section id=\"scene-$1\"/,/<\/section>/p" pp/index.html | sed '/<details class="poll-answer">/q'; }
[ "$rc" -eq 0 ] && above p_fold | grep -q 'question</span> · t = 0 s' && ! above p_fold | grep -q 't = 1 s' &&
  ! above p_fold | grep -q 't = 2.5 s' && grep -q 'answer</span> · t = 1 s' pp/index.html
check "a poll's panels after t = 0 fold under the Answer" $? "$(above p_fold | grep -o 't = [0-9.]* s' | tr '\n' ' ')"
! grep -q "$WORK" pp/index.html && ! grep -q "$WORK" pp/p_fold/page.json && grep -q '<code>p_fold.yaml</code>' pp/index.html
check "the page names the scene file as the pack does, never by this machine's path" $?
run lecture polls/p_reveal.yaml "${SMALL[@]}" -o pp -j 1
above p_reveal | grep -q 't = 1 s' && ! above p_reveal | grep -q 't = 2.5 s'
check "reveal keeps a time before it a question time, open above the fold" $?
run snapshot polls/p_fold.yaml --panels --at 0 -o pp --size 640x360 --draw-list
python3 - pp/p_fold/p_fold-panels-t0.json <<'PY'
import json, sys
calls = json.load(open(sys.argv[1]))["calls"]
# each variant's impulse to come: dashes and its time, the two cells struck at different heights
dashes = [c for c in calls if c["kind"] == "segment" and c["pen"].startswith("Impulse")]
heads = [c for c in calls if c["kind"] == "arrow" and c["pen"].startswith("Impulse")]
assert len(dashes) >= 6, len(dashes)
assert sum(c.get("text") == "j at t = 0.5 s" for c in calls) == 2
assert len(heads) == 2 and abs(heads[0]["numbers"][3] - heads[1]["numbers"][3]) > 20, heads
PY
check "a question sheet draws each variant's impulse to come, dashed, with its time" $?

cli_finish
