#!/usr/bin/env bash
# `rigidreel render` and `rigidreel snapshot` end to end: the video ffprobe sees (codec, pixel
# format, size, frame count), the poster and the PNG frames, byte-identical snapshots, bad input
# (exit 2), a missing or failing ffmpeg (exit 1) and Ctrl-C (exit 130) that leave no half file and
# keep the previous video.
#
# usage: bash tests/render/cli/render_cli_test.sh <path-to-rigidreel> <project-source-dir>
set -u

source "$(dirname "$0")/cli_harness.sh"
cli_setup render-cli-test "$@"
POLL=$SRC/scenes/poll_bar_impulse.yaml
# no half files anywhere under the output
no_parts() { ! find o -name '*.part*' | grep -q .; }
probe() {  # probe FILE: codec,width,height,pix_fmt,frames
  ffprobe -v error -select_streams v:0 -count_frames -show_entries \
    stream=codec_name,width,height,pix_fmt,nb_read_frames -of csv=p=0 "$1"
}

V=o/poll_bar_impulse/poll_bar_impulse-end.mp4

# a video: H.264, yuv420p, the size asked for, fps × duration frames; a poster; PNG frames
run render "$POLL" --variant end -o o --size 320x180 --fps 10 --duration 1.5 --frames --quiet
check "render exits 0" "$rc"
[ "$(probe $V)" = "h264,320,180,yuv420p,15" ]
check "ffprobe sees H.264 yuv420p 320x180 with 15 frames" $? "got $(probe $V)"
ffprobe -v error -show_entries format_tags=major_brand -of csv=p=0 $V >/dev/null
[ -f o/poll_bar_impulse/poll_bar_impulse-end.png ]
check "a poster PNG beside the video" $?
[ "$(ls o/poll_bar_impulse/poll_bar_impulse-end-frames | wc -l)" -eq 15 ] &&
  [ -f o/poll_bar_impulse/poll_bar_impulse-end-frames/frame-00014.png ]
check "15 numbered PNG frames" $?
no_parts
check "no temporary files left" $?
# +faststart: the index (moov) comes before the data (mdat)
head -c 4096 $V | grep -aq moov
check "the mp4 index is at the start (+faststart)" $?

# a lecture video: a 1 s title card, then 1.5 s of run whose [0.5, 0.7) plays 4 times slower:
# 1 + 1.5 + 3 × 0.2 = 3.1 s, 31 frames at 10 fps; the poster keeps simulation time
cat >lecture.yaml <<'YAML'
name: lecture
description: A ball rolls. It stops.
duration: 1.5
bodies:
  - {name: ball, shape: {circle: 0.2}, velocity: [1, 0]}
render: {title_card: 1, caption: true, slow_motion: {factor: 4, from: 0.5, to: 0.7}}
YAML
run render lecture.yaml -o o --size 160x90 --fps 10 --quiet
[ "$rc" -eq 0 ] && [ "$(probe o/lecture/lecture.mp4)" = "h264,160,90,yuv420p,31" ]
check "title_card and slow_motion lengthen the video to 31 frames" $? "got $(probe o/lecture/lecture.mp4)"
sed -i 's/slow_motion: {factor: 4, from: 0.5, to: 0.7}/slow_motion: {factor: 4, from: 0.7, to: 0.5}/' lecture.yaml
expect "a slow-motion window that ends before it starts is bad input" 2 "lecture.yaml:6:" render lecture.yaml -o o --quiet

# every variant, webm
run render "$POLL" --all-variants -o o --size 160x90 --fps 5 --duration 0.4 --format webm --quiet
[ "$rc" -eq 0 ] && [ -f o/poll_bar_impulse/poll_bar_impulse-center.webm ] && [ -f o/poll_bar_impulse/poll_bar_impulse-end.webm ]
check "--all-variants --format webm writes one video per variant" $?

# snapshots: one PNG per time, byte-identical when repeated; panels; strobe
run snapshot "$POLL" --variant end --at 0.5,1 -o o --size 160x90
[ "$rc" -eq 0 ] && [ -f o/poll_bar_impulse/poll_bar_impulse-end-t0.5.png ] && [ -f o/poll_bar_impulse/poll_bar_impulse-end-t1.png ]
check "snapshot --at writes one PNG per time" $?
cp o/poll_bar_impulse/poll_bar_impulse-end-t1.png first.png
run snapshot "$POLL" --variant end --at 1 -o o --size 160x90
cmp -s first.png o/poll_bar_impulse/poll_bar_impulse-end-t1.png
check "the same snapshot twice is byte-identical" $?
run snapshot "$POLL" --panels --at 1.5 -o o --size 160x90
[ "$rc" -eq 0 ] && [ -f o/poll_bar_impulse/poll_bar_impulse-panels-t1.5.png ]
check "snapshot --panels writes one image of every variant" $?
run snapshot "$POLL" --variant end --at 2 --strobe 5 -o o --size 160x90
[ "$rc" -eq 0 ] && [ -f o/poll_bar_impulse/poll_bar_impulse-end-t2-strobe5.png ]
check "snapshot --strobe names the ghost count" $?
# --draw-list: beside each PNG its draw list in the image's pixels, a sheet's with its titles' boxes
run snapshot "$POLL" --panels --at 1.5 -o o --size 640x360 --draw-list
python3 - o/poll_bar_impulse/poll_bar_impulse-panels-t1.5.json <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
assert (d["width"], d["height"]) == (640, 360), d["width"]
texts = [c for c in d["calls"] if c["kind"] == "text"]
assert any(c["text"] == "A: center" for c in texts), [c["text"] for c in texts]
assert all(len(c["box"]) == 4 and 0 <= c["box"][0] < c["box"][2] <= 640 for c in texts)
assert any(c["pen"].startswith("Body#") for c in d["calls"])
PY
check "snapshot --draw-list writes the sheet's draw list in pixels beside it" $?
grep -q "poll_bar_impulse-panels-t1.5.json" out
check "snapshot names the draw list it wrote" $?
expect "--draw-list of a 3D scene" 2 "2D scenes only" snapshot "$SRC/scenes/lecture/11_state_in_3d.yaml" -o o --at 1 --draw-list

# bad input: exit 2 with a message naming the fault, nothing written
expect "odd size" 2 "even" render "$POLL" -o o --size 321x180
expect "huge size" 2 "8192" render "$POLL" -o o --size 10000x720
expect "malformed size" 2 "WIDTHxHEIGHT" snapshot "$POLL" -o o --at 1 --size big
expect "fps 0" 2 "--fps" render "$POLL" -o o --fps 0
expect "negative duration" 2 "--duration" render "$POLL" -o o --duration -1
expect "unknown format" 2 "mp4, webm or gif" render "$POLL" -o o --format avi
expect "unknown variant" 2 "unknown variant 'nope'" render "$POLL" -o o --variant nope
touch blocker
expect "unwritable output directory" 2 "cannot create the output directory" render "$POLL" -o blocker/x
expect "snapshot time outside the duration" 2 "outside the scene's duration" snapshot "$POLL" -o o --at 0.5,7
expect "snapshot without times" 2 "--at" snapshot "$POLL" -o o
expect "snapshot --impacts of a scene without impacts" 2 "has no impacts" snapshot "$POLL" -o o --impacts
expect "--panels with --variant" 2 "leave out --variant" snapshot "$POLL" -o o --panels --variant end --at 1
expect "--all-variants with --variant" 2 "excludes" render "$POLL" -o o --all-variants --variant end

# ffmpeg missing or failing: exit 1 with its message; the previous video is kept
cp $V before.mp4
mkdir emptybin
env PATH="$WORK/emptybin" "$BIN" render "$POLL" --variant end -o o --size 320x180 --fps 10 --duration 1.5 --quiet >out 2>err
rc=$?
[ "$rc" -eq 1 ] && grep -q "apt-get install ffmpeg" err
check "ffmpeg missing: exit 1, saying what to install" $? "exit $rc"
mkdir fakebin
printf '#!/bin/sh\necho "Unknown encoder libx264" >&2\nexit 1\n' >fakebin/ffmpeg
chmod +x fakebin/ffmpeg
PATH=$WORK/fakebin:$PATH expect "ffmpeg failing" 1 "Unknown encoder libx264" render "$POLL" --variant end -o o --size 320x180 --fps 10 --duration 1.5 --quiet
cmp -s before.mp4 $V && no_parts
check "a failed render keeps the previous video and leaves no half file" $?

# Ctrl-C: exit 130, nothing half-written, the previous video kept
"$BIN" render "$POLL" --variant end -o o --size 320x180 --fps 200 --duration 60 --quiet >out 2>err &
pid=$!
sleep 1.5
kill -INT $pid
wait $pid
rc=$?
[ "$rc" -eq 130 ] && grep -q interrupted err && cmp -s before.mp4 $V && no_parts
check "Ctrl-C exits 130, keeps the previous video, leaves no half file" $? "exit $rc"

cli_finish
