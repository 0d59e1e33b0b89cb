#!/usr/bin/env bash
# The fourth battery (issue 41), readers: what rigidreel reads back (traces, a record's manifest,
# states and baselines, a pack's order.txt and title.txt) goes through one bounded reader: a FIFO or
# a device is refused at open, a file past its size bound is refused, every value is checked at its
# FILE:LINE:COL, and what our own writers write reads back (names with commas and quotes,
# subnormals, a byte order mark). A record's trace must be complete for its state level to pass.
#
# usage: bash tests/hostile/hostile4_readers_test.sh <path-to-rigidreel> <project-source-dir>
set -u

HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/../render/cli/cli_harness.sh"
source "$HERE/hostile_harness.sh"
cli_setup hostile4-readers-test "$@"

cat >ball.yaml <<'YAML'
name: ball
duration: 1
world: {gravity: [0, -9.81]}
bodies: [{name: ball, shape: {circle: 0.2}, position: [0, 1], velocity: [1, 0]}]
golden: {size: [160, 90], impacts: false, at: [0.5, 1]}
YAML
run golden record ball.yaml -o golden
check "a record to read back" "$rc"
cp -r golden golden.kept
fresh() { rm -rf golden && cp -r golden.kept golden; }
# short runs: a blocked open() fails the case by its deadline (124) instead of hanging the suite
quick() {
  timeout -k 2 10 "$BIN" "$@" >out 2>err
  rc=$?
}

# --- FIFOs and devices refused at open, not waited on ---------------------------------------------
for file in manifest.json states.csv trace.csv frame-t1.png frame-t1.json; do
  fresh && rm golden/ball/$file && mkfifo golden/ball/$file
  quick golden check ball.yaml
  [ "$rc" -eq 2 ] && grep -q "golden/ball/$file: is a FIFO" err
  check "a FIFO as the record's $file: refused at once, exit 2" $? "exit $rc"
done
fresh
mkdir -p pack && cp ball.yaml pack/
mkfifo pack/order.txt
quick lecture pack --list
[ "$rc" -eq 2 ] && grep -q "order.txt: is a FIFO" err
check "a FIFO as a folder's order.txt: refused at once" $? "exit $rc"
rm pack/order.txt
quick lecture pack -o pk --size 160x90 --fps 10 --quiet
check "a small pack" "$rc"
rm -f pk/title.txt && mkfifo pk/title.txt
quick lecture --page pk
[ "$rc" -eq 2 ] && grep -q "title.txt: is a FIFO" err
check "a FIFO as a pack's title.txt: refused at once" $? "exit $rc"
quick compare ball.yaml --trace /dev/zero
[ "$rc" -eq 2 ] && grep -q "/dev/zero: is a device" err
check "compare --trace /dev/zero: refused at open" $? "exit $rc"
truncate -s 300M big.csv
(limit_memory && exec timeout -k 2 10 "$BIN" compare ball.yaml --trace big.csv >out 2>err)
rc=$?
[ "$rc" -eq 2 ] && grep -q "more than the limit of 256 MiB for a trace" err
check "a 300 MB trace: refused before it is read" $? "exit $rc: $(head -c 200 err)"

# --- a record's values checked where they stand -------------------------------------------------
manifest_case() {  # manifest_case NAME PYTHON-EDIT TEXT: the edited manifest refused at its line, exit 2, at once
  fresh
  python3 - "$2" <<'PY'
import json, sys
m = json.load(open("golden/ball/manifest.json"))
exec(sys.argv[1])
with open("golden/ball/manifest.json", "w") as f:
    f.write(json.dumps(m, indent=1))
PY
  quick golden check ball.yaml
  [ "$rc" -eq 2 ] && grep -q "golden/ball/manifest.json:[0-9]*:[0-9]*: .*$3" err && ! grep -q state out
  check "$1" $? "exit $rc"
}
manifest_case "a checkpoint of 1e300: refused at its line, nothing run" 'm["checkpoints"] = [1e300]' "'checkpoints' is 1e+300, outside 0 to 1"
manifest_case "a checkpoint of -5: refused at its line" 'm["checkpoints"] = [-5, 1]' "'checkpoints' is -5, outside 0 to 1"
manifest_case "a size of 100000 x 100000: refused at its line" 'm["size"] = [100000, 100000]' "'size' is 100000, outside 16 to 8192"
manifest_case "a frame outside the record's folder: refused" 'm["frames"][0]["png"] = "../../ball.yaml"' "'png' must name a file frame-t"
manifest_case "a frame at no checkpoint: refused" 'm["frames"][0]["t"] = 0.25' "the frame at t = 0.25 is at none of the checkpoints"
fresh
# a 120-byte PNG whose header claims 30000 x 30000 pixels (3.6 GB of RGBA)
python3 - <<'PY'
import struct, zlib
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 30000, 30000, 8, 6, 0, 0, 0))
png += chunk(b"IDAT", zlib.compress(b"\0" * 40)) + chunk(b"IEND", b"")
open("golden/ball/frame-t1.png", "wb").write(png)
PY
(limit_memory && exec "$BIN" golden check ball.yaml >out 2>err)
rc=$?
[ "$rc" -eq 1 ] && grep -q "pixels  FAIL.*recorded at 30000x30000" out
check "a baseline PNG claiming 30000 x 30000: a size difference, nothing decoded" $? "exit $rc: $(head -c 300 err)"
fresh && rm golden/ball/frame-t1.png
quick golden check ball.yaml
[ "$rc" -eq 2 ] && grep -q "frame-t1.png: missing" err && ! grep -q state out
check "a missing baseline PNG: exit 2 before the run, as a missing manifest" $? "exit $rc"
fresh
# the record's trace without its row at the end, and the ball started 0.3 m higher: the hashes differ
head -2 golden.kept/ball/trace.csv >golden/ball/trace.csv
sed 's/position: \[0, 1\]/position: [0, 1.3]/' ball.yaml >higher.yaml
quick golden check higher.yaml
[ "$rc" -eq 2 ] && grep -q "golden/ball/trace.csv.*has no row of body 'ball' at checkpoint t = 1" err && ! grep -q "state  ok" out
check "rows missing from a record's trace: refused, never 'state ok'" $? "exit $rc: $(head -c 300 out)"

# --- what our writers write reads back ------------------------------------------------------------
cat >names.yaml <<'YAML'
name: names
duration: 0.5
bodies:
- {name: "a,b", shape: {circle: 0.2}, velocity: [1, 0]}
- {name: "say \"hi\"", shape: {circle: 0.2}, position: [3, 0], velocity: [1, 0]}
- {name: "Stoß, zwei", shape: {circle: 0.2}, position: [6, 0], velocity: [1, 0]}
- {name: tiny, shape: {circle: 0.2}, position: [1.0e-310, 9], velocity: [0, 0]}
golden: {size: [160, 90], impacts: false}
YAML
run golden record names.yaml -o gn
check "a record of bodies named with commas, quotes, non-ASCII letters, at x = 1e-310" "$rc"
run golden check names.yaml --golden gn
[ "$rc" -eq 0 ] && grep -q "state  ok" out
check "  ... its own check passes" $? "exit $rc: $(head -c 300 err)"
run simulate names.yaml --trace names.csv
run compare names.yaml --trace names.csv
[ "$rc" -eq 0 ] && grep -q 'ok    a,b' out && grep -q 'ok    say "hi"' out && grep -q 'ok    tiny' out
check "compare of our own trace of those names and a subnormal: exit 0, every body" $? "exit $rc: $(head -c 300 err)"
printf '\xef\xbb\xbf' >bom.csv && cat names.csv >>bom.csv
run compare names.yaml --trace bom.csv
check "a trace with a byte order mark: read as without" "$rc" "exit $rc: $(head -c 300 err)"
printf '\xef\xbb\xbfb\na\n' >pack/order.txt && sed 's/^name: ball$/name: a/' ball.yaml >pack/a.yaml && mv pack/ball.yaml pack/b.yaml
sed -i 's/^name: ball$/name: b/' pack/b.yaml
quick lecture pack --list
[ "$rc" -eq 0 ] && [ -n "$(grep -m1 'b\.mp4$' out)" ] && [ "$(grep -m1 '\.mp4$' out)" = "$(grep -m1 'b\.mp4$' out)" ]
check "an order.txt with a byte order mark: its first scene first" $? "exit $rc: $(head -c 300 err)"

# --- compare against rows outside the run: bad input, not a pass ---------------------------------
printf 't,body,x,y,angle,vx,vy,omega\n5,ball,0,1,0,1,0,0\n6,ball,1,1,0,1,0,0\n' >late.csv
run compare ball.yaml --trace late.csv
[ "$rc" -eq 2 ] && grep -q "late.csv:2:1: no row of 'ball' meets the run" err
check "a trace whose rows all lie after the run: exit 2" $? "exit $rc: $(head -c 300 out)"
printf 't,body,x,y,angle,vx,vy,omega\n0.5005,ball,0,1,0,1,0,0\n' >between.csv
run compare ball.yaml --trace between.csv
[ "$rc" -eq 2 ] && grep -q "no row of 'ball' meets the run" err
check "a trace of one row between two steps: exit 2" $? "exit $rc: $(head -c 300 out)"

cli_finish
