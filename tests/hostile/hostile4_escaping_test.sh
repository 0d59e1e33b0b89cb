#!/usr/bin/env bash
# The fourth battery (issue 41), escaping by destination: XML (JUnit: control characters and bytes
# that are not UTF-8 replaced), an HTML attribute that is a URL (the report's <img src>), HTML ids
# (one per full name), YAML (expect's entries paste back), and the terminal (a refused name's ESC
# shown as \x1b).
#
# usage: bash tests/hostile/hostile4_escaping_test.sh <path-to-rigidreel> <project-source-dir>
set -u

HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/../render/cli/cli_harness.sh"
source "$HERE/hostile_harness.sh"
cli_setup hostile4-escaping-test "$@"

# a scene name that is a URL's '#', '?' and '%', a body name with an ESC, a path that is not UTF-8
cat >poll.yaml <<'YAML'
name: "poll#1?x=50%"
duration: 1
world: {gravity: [0, -9.81]}
bodies: [{name: "b\u001bx", shape: {circle: 0.2}, position: [0, 1], velocity: [1, 0]}]
golden: {size: [160, 90], impacts: false, at: [0.5, 1]}
YAML
odd=$'p\xff.yaml'
cp poll.yaml "$odd"
run golden record "$odd" -o golden
check "a record of a scene whose path is not UTF-8" "$rc"
# every level fails: the ball started higher (state, draw list), a baseline of another frame (pixels)
cp "golden/poll#1?x=50%/frame-t0.5.png" "golden/poll#1?x=50%/frame-t1.png"
sed -i 's/position: \[0, 1\]/position: [0, 1.1]/' "$odd"
run golden check "$odd" --junit j.xml --report report
[ "$rc" -eq 1 ] && grep -q "state  FAIL" out
check "a check that fails at every level" $? "exit $rc"

# --- JUnit: well-formed XML whatever the names -------------------------------------------------------
python3 -c 'import xml.etree.ElementTree as E, sys; E.parse(sys.argv[1])' j.xml 2>/dev/null
check "JUnit with an ESC in a body name and a path not UTF-8: well-formed XML" $? "$(head -c 400 j.xml | cat -v)"
grep -q $'file="p\xef\xbf\xbd.yaml"' j.xml && ! grep -q $'\x1b' j.xml
check "  ... the invalid byte and the ESC replaced by U+FFFD" $? "$(grep -a -m1 file= j.xml | cat -v)"

# --- the report's images: URL-encoded, then escaped ------------------------------------------------------
[ "$(grep -c '<img src="poll%231%3Fx%3D50%25/frame-t1-' report/index.html)" -eq 3 ] &&
  [ -f "report/poll#1?x=50%/frame-t1-diff.png" ]
check "report <img src> of a scene named poll#1?x=50%: URL-encoded, the files there" $? \
  "$(grep -o '<img src="[^"]*"' report/index.html | head -3)"

# --- the page: one id per full name, a title that is not UTF-8 replaced ------------------------------
mkdir pack
for n in Stoß Stoä; do
  printf 'name: %s\nduration: 0.5\nbodies: [{name: b, shape: {circle: 0.2}, velocity: [1, 0]}]\n' "$n" >"pack/$n.yaml"
done
run lecture pack -o pk --size 160x90 --fps 10 --quiet --title $'T\xff'
[ "$rc" -eq 0 ] && [ "$(grep -o '<section id="[^"]*"' pk/index.html | sort -u | wc -l)" -eq 2 ]
check "page sections of 'Stoß' and 'Stoä': two ids" $? "exit $rc: $(grep -o 'id="scene-[^"]*"' pk/index.html)"
grep -q $'<h1>T\xef\xbf\xbd</h1>' pk/index.html && ! grep -q $'T\xff' pk/index.html
check "a --title that is not UTF-8: replaced in the page" $? "$(grep -a '<h1>' pk/index.html | cat -v)"

# --- expect's entries paste back into the scene --------------------------------------------------------
python3 - <<'PY'
import json
names = ["a # b", "a, b", "k: v", "{}", "*x", "a]", "null", "esc\x1bq"]
bodies = "\n".join("- {name: %s, shape: {circle: 0.2}, position: [%d, 0], velocity: [1, 0]}" % (json.dumps(n), 3 * i)
                   for i, n in enumerate(names))
open("names.yaml", "w").write("name: names\nduration: 0.5\nbodies:\n" + bodies + "\n")
PY
run expect names.yaml
cp names.yaml pasted.yaml && tail -n +2 out >>pasted.yaml
run check pasted.yaml -v
[ "$rc" -eq 0 ] && [ "$(grep -c 'ok' out)" -ge 8 ]
check "expect of bodies named with '#', ', ', ': ', '{}', '*', ']', 'null', ESC: check takes them pasted" $? \
  "exit $rc: $(head -c 300 err)"
expect "expect --tolerance 1e309: refused, not printed as inf" 2 "--tolerance: give zero or a positive finite number" \
  expect names.yaml --tolerance 1e309

# --- the terminal: a refused name's ESC shown, not sent ------------------------------------------------
run simulate names.yaml --variant $'\e[31m'
[ "$rc" -eq 2 ] && grep -qF "unknown variant '\\x1b[31m'" err && ! grep -q $'\x1b' err
check "a refused --variant with an ESC: shown as \\x1b, never raw" $? "exit $rc: $(cat -v err)"

cli_finish
