#!/usr/bin/env bash
# One command line (issue 27): -o/--output, -q/--quiet and -v/--verbose on every subcommand,
# --version, `check` of a folder, an unknown subcommand listing the subcommands, --help naming 2D
# and 3D and the exit statuses, and "did you mean" only for a near miss (else the valid keys).
#
# usage: bash command_line_test.sh <path-to-rigidreel> <project-source-dir>
set -u

source "$(dirname "$0")/cli_harness.sh"
cli_setup command-line-test "$@"
POLL="$SRC/scenes/poll_bar_impulse.yaml"
THREE="$SRC/scenes/three_collisions_poll.yaml"
MASS="$SRC/scenes/mass_ratio.yaml"
SUBCOMMANDS="simulate, check, sweep, stability, render, snapshot, lecture"

# ---- the program ---------------------------------------------------------------------------
run --version
[ "$rc" -eq 0 ] && grep -qE '^rigidreel [0-9]+\.[0-9]+\.[0-9]+$' out
check "--version prints the version, exit 0" $?
expect "an unknown subcommand lists the subcommands, exit 2" 2 "unknown subcommand 'foo'; choose one of: $SUBCOMMANDS" foo
expect "no subcommand lists them too, exit 2" 2 "choose one of: $SUBCOMMANDS"
run --help
[ "$rc" -eq 0 ] && grep -q "2D and 3D" out && grep -q "Exit status: 0 success; 1 " out && grep -q "2 bad input" out &&
  grep -q "130 interrupted" out
check "--help names 2D and 3D and the exit statuses 0, 1, 2 and 130" $?

# ---- the same flags everywhere --------------------------------------------------------------
for sub in simulate check sweep stability render snapshot lecture; do
  run "$sub" --help
  grep -q -- "-q,--quiet" out && grep -q -- "-v,--verbose" out && grep -q -- "-o,--output" out
  check "$sub takes -o/--output, -q/--quiet and -v/--verbose" $?
done
expect "-q and -v together are bad input" 2 "excludes" simulate "$POLL" -q -v

# simulate: -q prints nothing, -o writes what it would print, -v adds every impulse
run simulate "$THREE" --variant A
cp out plain
run simulate "$THREE" --variant A -q
[ "$rc" -eq 0 ] && [ ! -s out ] && [ ! -s err ]
check "simulate -q prints nothing (exit 0)" $?
run simulate "$THREE" --variant A --output state.txt
[ "$rc" -eq 0 ] && [ ! -s out ] && cmp -s state.txt plain
check "simulate --output FILE writes there what it prints" $?
run simulate "$THREE" --variant A --json -o state.json
[ "$rc" -eq 0 ] && python3 -c 'import json,sys; json.load(open("state.json"))'
check "simulate --json -o FILE writes one JSON object" $?
run simulate "$THREE" --variant A -v
impulses=$(grep -c "^  impulse t = " out)
json=$("$BIN" simulate "$THREE" --variant A --json | python3 -c 'import json,sys; print(len(json.load(sys.stdin)["collisions"]))')
[ "$rc" -eq 0 ] && [ "$impulses" -ge 1 ] && [ "$impulses" -eq "$json" ] && grep -q "^  impulse t = .*'ball' and 'block'" out
check "simulate -v lists every impulse the JSON has ($impulses of $json)" $?
printf 'bodies:\n  - {name: a, shape: {circle: 1}}\n' >ok.yaml
run simulate "$THREE" --variant A -o missing/dir/state.txt
[ "$rc" -eq 2 ] && grep -q -- "-o: " err
check "simulate -o into a folder that does not exist is bad input" $?

# check: folders, -q, -v, -o
mkdir pack
cp "$POLL" pack/b_poll.yaml
cp ok.yaml pack/a_free.yaml
echo "not a scene" >pack/notes.txt
run check pack
first=$(grep -n "pack/a_free.yaml" out | head -1 | cut -d: -f1)
second=$(grep -n "pack/b_poll.yaml" out | head -1 | cut -d: -f1)
[ "$rc" -eq 0 ] && [ -n "$first" ] && [ -n "$second" ] && [ "$first" -lt "$second" ] && ! grep -q notes out
check "check DIR checks every *.yaml in it, sorted" $?
expect "check of an empty folder is bad input" 2 "" check "$(mkdir -p empty && echo empty)"
run check pack -q
[ "$rc" -eq 0 ] && [ ! -s out ]
check "check -q of passing scenes prints nothing" $?
sed 's/angular_velocity: -0.5,/angular_velocity: -0.25,/' "$POLL" >wrong.yaml
run check wrong.yaml -q
[ "$rc" -eq 1 ] && grep -q "^wrong.yaml \[end\]:  FAIL" out && ! grep -q "  ok  " out
check "check -q prints the failed entries alone, each after its file and variant (exit 1)" $?
run check "$THREE" -v
[ "$rc" -eq 0 ] && grep -q "^  impulse t = " out
check "check -v lists every impulse" $?
run check pack --output report.txt
[ "$rc" -eq 0 ] && [ ! -s out ] && grep -q "pack/b_poll.yaml \[end\]" report.txt
check "check --output FILE writes the report there" $?

# sweep and stability: --output as -o, -q prints nothing, -v the CSV after the table
run sweep "$MASS" --integrators rk4 --dt 0.1:0.05:2 --repeat 1 --output sw
[ "$rc" -eq 0 ] && ls sw/*-sweep.csv >/dev/null 2>&1
check "sweep --output DIR writes there" $?
run sweep "$MASS" --integrators rk4 --dt 0.1:0.05:2 --repeat 1 --output swq -q
[ "$rc" -eq 0 ] && [ ! -s out ] && ls swq/*-sweep.csv >/dev/null 2>&1
check "sweep -q prints nothing and writes its files" $?
run sweep "$MASS" --integrators rk4 --dt 0.1:0.05:2 --repeat 1 -o swv -v
[ "$rc" -eq 0 ] && grep -qF "$(head -1 swv/*-sweep.csv)" out && [ "$(grep -c '^rk4,' out)" -eq 2 ]
check "sweep -v prints the CSV's rows" $?
run stability "$MASS" --integrators symplectic_euler --output st -q
[ "$rc" -eq 0 ] && [ ! -s out ] && ls st/*-stability.csv >/dev/null 2>&1
check "stability --output DIR -q writes there and prints nothing" $?

# snapshot and render: -q and -v
run snapshot "$POLL" --at 0.5 --size 160x90 --output snap -q
[ "$rc" -eq 0 ] && [ ! -s out ] && ls snap/*/*t0.5.png >/dev/null 2>&1
check "snapshot -q writes its PNG and prints nothing" $?
run snapshot "$POLL" --at 0.5 --size 160x90 -o snap
[ "$rc" -eq 0 ] && grep -q "t0.5.png$" out
check "snapshot prints each path it writes" $?
run render "$POLL" --variant end --size 160x90 --fps 10 -o vid -v
[ "$rc" -eq 0 ] && grep -q "^wrote .*\.mp4$" out && grep -q "^wrote .*\.png$" out
check "render -v names each file it writes" $?

# ---- did you mean, only when near ------------------------------------------------------------
for shape in rectangle capsule; do
  printf 'bodies:\n  - name: a\n    shape: {%s: 1}\n' "$shape" >"$shape.yaml"
  run check "$shape.yaml"
  [ "$rc" -eq 2 ] && grep -qF "$shape.yaml:3:13: unknown key '$shape' in shape; choose one of: box, polygon, circle, plane" err &&
    ! grep -q "did you mean" err
  check "an unknown shape '$shape' lists the four shapes, no guess" $?
done
printf 'bodies:\n  - {name: a, shape: {circle: 1}}\nrender: {annotations: true}\n' >annotations.yaml
run check annotations.yaml
[ "$rc" -eq 2 ] && grep -q "unknown key 'annotations'" err && grep -q "choose one of: size, fps" err && ! grep -q "did you mean" err
check "render: {annotations} lists the render keys, not 'contacts'" $?
printf 'bodies:\n  - {name: a, shape: {circle: 1}, desity: 2}\n' >near.yaml
expect "a near miss still gets its hint" 2 "did you mean 'density'?" check near.yaml

cli_finish
