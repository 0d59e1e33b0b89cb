#!/usr/bin/env bash
# The command line end to end: exit codes (0 ok, 1 failure/divergence, 2 bad input), messages,
# the JSON state and the CSV trace, and that a failed run never leaves or clobbers a trace file.
#
# usage: bash tests/render/cli/cli_test.sh <path-to-rigidreel> <project-source-dir>
# prints one "ok - ..." / "not ok - ..." line per case and "N passed, M failed"; exits 1 on any failure.
set -u

source "$(dirname "$0")/cli_harness.sh"
cli_setup cli-test "$@"
SCENES=$SRC/scenes
POLL=$SCENES/poll_bar_impulse.yaml
if [ ! -x "$BIN" ] || [ ! -f "$POLL" ]; then
  echo "cli_test.sh: no executable $BIN or no scene $POLL" >&2
  exit 2
fi

CAP=$WORK/.captured  # stdout and stderr of the last run, outside the directory the runs write to
mkdir "$CAP" || exit 2

passed=0
failed=0
ok() {
  echo "ok - $1"
  passed=$((passed + 1))
}
# not_ok NAME [DETAIL...]
not_ok() {
  echo "not ok - $1"
  shift
  local line
  for line in "$@"; do echo "#   $line"; done
  echo "#   stdout: $(head -c 400 "$CAP/out")"
  echo "#   stderr: $(head -c 400 "$CAP/err")"
  failed=$((failed + 1))
}

# run ARGS...: the binary with ARGS; sets $rc, $out and $err
run() {
  "$BIN" "$@" >"$CAP/out" 2>"$CAP/err"
  rc=$?
  out=$(<"$CAP/out")
  err=$(<"$CAP/err")
}

# expect NAME CODE STREAM TEXT ARGS...: running ARGS exits CODE and STREAM (out or err) contains TEXT
expect() {
  local name=$1 code=$2 stream=$3 text=$4
  shift 4
  run "$@"
  local got=$out
  [ "$stream" = err ] && got=$err
  if [ "$rc" -ne "$code" ]; then
    not_ok "$name" "exit code $rc, expected $code"
  elif [[ "$got" != *"$text"* ]]; then
    not_ok "$name" "std$stream does not contain: $text"
  else
    ok "$name"
  fi
}

# no leftover temporary trace files (AtomicFile writes PATH.part-PID) in the working directory
no_part_files() {
  compgen -G "$WORK/*.part-*" >/dev/null && return 1
  compgen -G "$WORK/.*.part-*" >/dev/null && return 1
  return 0
}

# ---- scenes written for the tests ----------------------------------------------------------

# invalid YAML: a second ':' on line 3, at column 12
cat >bad.yaml <<'EOF'
name: bad
description: the parser stops at the second colon below
duration: 1: 2
bodies:
  - {name: a, shape: {circle: 1}}
EOF

# a stiff spring with explicit Euler and a large step: grows by ~1e5 per step until it overflows
cat >diverge.yaml <<'EOF'
name: diverge
duration: 100
sim: {integrator: explicit_euler, dt: 0.1}
bodies:
  - name: bob
    shape: {circle: 0.1}
    mass: 1
    position: [1, 0]
forces:
  - {type: spring, body: bob, anchor: [0, 0], stiffness: 1e12}
EOF

# the poll scene with one wrong expected value (the end variant's angle at t = 1 is -0.25)
sed 's/angle: -0.25,/angle: -0.3,/' "$POLL" >wrong_expect.yaml

# ---- simulate: the poll's exact answers ----------------------------------------------------

# json_check NAME PYTHON-EXPRESSIONS...: each expression, over d (the JSON) and b (its first body), is true
json_check() {
  local name=$1
  shift
  local message
  if message=$(python3 - "$CAP/out" "$@" 2>&1 <<'EOF'
import json, sys
with open(sys.argv[1]) as f:
    d = json.load(f)
b = d["bodies"][0]
bad = [e + "  (x=" + repr(eval(e.split("==")[0], {}, {"d": d, "b": b})) + ")"
       for e in sys.argv[2:] if not eval(e, {}, {"d": d, "b": b})]
if bad:
    print("; ".join(bad))
    sys.exit(1)
EOF
  ); then
    ok "$name"
  else
    not_ok "$name" "$message"
  fi
}

run simulate "$POLL" --variant end --until 1 --json
if [ "$rc" -ne 0 ]; then
  not_ok "simulate --variant end --until 1 --json exits 0" "exit code $rc"
else
  ok "simulate --variant end --until 1 --json exits 0"
  for field in '"vx":0.3333333333333333' '"omega":-0.5' '"kinetic_energy":0.6666666666666666' '"variant":"end"'; do
    if [[ "$out" == *"$field"* ]]; then ok "end variant JSON has $field"; else not_ok "end variant JSON has $field"; fi
  done
  json_check "end variant: v = (1/3, 0), omega = -1/2, KE = 2/3 exactly" \
    'b["vx"] == 0.3333333333333333' 'b["vy"] == 0' 'b["omega"] == -0.5' \
    'b["kinetic_energy"] == 0.6666666666666666' 'd["t"] == 1' 'd["steps"] == 1000' 'd["integrator"] == "rk4"' \
    'd["momentum"] == [1, 0]' 'd["angular_momentum"] == -2'
fi

run simulate "$POLL" --variant center --until 1 --json
if [ "$rc" -ne 0 ]; then
  not_ok "simulate --variant center --json exits 0" "exit code $rc"
else
  ok "simulate --variant center --json exits 0"
  json_check "center variant: v = (1/3, 0), omega = 0, KE = 1/6 exactly" \
    'b["vx"] == 0.3333333333333333' 'b["omega"] == 0' 'b["kinetic_energy"] == 0.16666666666666666' \
    'd["variant"] == "center"'
fi

expect "simulate prints a text table by default" 0 out "poll_bar_impulse [end]: t = 1" \
  simulate "$POLL" --variant end --until 1

# a plastic contact that goes on sliding and turning stays in contact; a ball lying still came to rest
PLASTIC="$SRC/scenes/lecture/06_body_obstacle_collision.yaml"
expect "a bar that keeps turning on the floor stays in contact (not 'came to rest')" 0 out \
  "'floor' and 'bar' stay in contact from t = 0.70799" simulate "$PLASTIC" --variant plastic
[[ "$out" != *"came to rest"* ]] && ok "the turning bar is never said to have come to rest" ||
  not_ok "the turning bar is never said to have come to rest"
run simulate "$PLASTIC" --variant plastic --json
json_check "the JSON says the resting contact still moves" 'len(d["resting"]) >= 1' 'all(r["moving"] for r in d["resting"])'
expect "a ball bouncing to a stop came to rest" 0 out "'floor' and 'ball' came to rest at t = 3.63469" \
  check "$SRC/scenes/bouncing_ball.yaml"

# sim: {sleep: true}: a settled pile of three boxes sleeps, said by check and the JSON; refused beside event
cat >sleepy.yaml <<'EOF'
duration: 3
world: {gravity: [0, -10], friction: 0.6, restitution: 0}
sim: {collisions: soft_step, dt: 0.016666666666666667, sleep: true}
bodies:
  - {name: floor, shape: {box: [20, 1]}, static: true, position: [0, -0.5]}
  - {name: b0, shape: {box: [1, 1]}, position: [-0.55, 0.5]}
  - {name: b1, shape: {box: [1, 1]}, position: [0.55, 0.5]}
  - {name: top, shape: {box: [1, 1]}, position: [0, 1.5]}
EOF
expect "check says how many bodies sleep at the end" 0 out "sleep: on; 3 of 3 dynamic bodies asleep at the end" \
  check sleepy.yaml
run simulate sleepy.yaml --json
json_check "the JSON gives the sleeping bodies, each at rest exactly" 'd["sleep"] == True' 'd["sleeping_bodies"] == 3' \
  'all(x["vx"] == 0 and x["vy"] == 0 and x["omega"] == 0 for x in d["bodies"])' 'len(d["contacts"]) >= 3'
run simulate "$POLL" --variant end --until 1 --json
json_check "without sleep the JSON has no sleep fields" '"sleep" not in d' '"sleeping_bodies" not in d'
sed 's/collisions: soft_step/collisions: event/' sleepy.yaml >sleepy_event.yaml
expect "sleep beside collisions: event exits 2 at its line" 2 err "sleepy_event.yaml:3" simulate sleepy_event.yaml

# sim: {precision: float}: soft_step's contact solve in floats, said by check and the JSON (only
# then), a state other than the doubles', and --precision sets it for one run
sed 's/sleep: true/precision: float/' sleepy.yaml >floaty.yaml
expect "check says the contact solve is in floats" 0 out "precision: float (soft_step's contact solve)" check floaty.yaml
run simulate floaty.yaml --json
json_check "the JSON says precision: float" 'd["precision"] == "float"' 'd["collision_method"] == "soft_step"'
floaty_yaml=${out#*\"variant\"}
run simulate sleepy.yaml --json
json_check "without it the JSON has no precision field" '"precision" not in d'
sed 's/, sleep: true//' sleepy.yaml >doubly.yaml
run simulate doubly.yaml --json --precision float
if [ "$rc" -eq 0 ] && [ "${out#*\"variant\"}" = "$floaty_yaml" ]; then
  ok "--precision float runs the scene as sim: {precision: float} does"
else
  not_ok "--precision float runs the scene as sim: {precision: float} does"
fi
run simulate doubly.yaml --json
if [ "$rc" -eq 0 ] && [ "${out#*\"variant\"}" != "$floaty_yaml" ]; then ok "floats end in another state than doubles"; else not_ok "floats end in another state than doubles"; fi
expect "--precision half exits 2 naming the choices" 2 err "--precision: unknown precision 'half'; choose one of: double, float" \
  simulate doubly.yaml --precision half
sed 's/precision: float/precision: half/' floaty.yaml >halfy.yaml
expect "sim: {precision: half} exits 2 at its line" 2 err "halfy.yaml:3:67: unknown precision 'half'" simulate halfy.yaml

# right by default: a tilted box dropped on a rough floor, nothing named: `auto` starts with event,
# hands the run to sequential when the box rattles on the floor, says when and why, and the box
# comes to rest on a face; the energy ledger says where the energy went
cat >tilted_box.yaml <<'EOF'
duration: 4
world: {gravity: [0, -9.81], restitution: 0.5, friction: 0.5}
bodies:
  - {name: floor, shape: {plane: {point: [0, 0], normal: [0, 1]}}}
  - {name: box, shape: {box: [1, 0.5]}, mass: 1, position: [0, 1.5], angle: 0.5235987755982988}
expect:
  - {energy_never_rises: true, tolerance: 1e-6}
EOF
expect "check says when auto switched, to what, and why" 0 out \
  "switched: event until t = 0.576 s, then sequential: 'floor' and 'box' struck each other 4 times within 0.1 s" check tilted_box.yaml
expect "check checks that the energy never rises" 0 out "ok    t = 4  energy_never_rises = " check tilted_box.yaml
expect "check gives the energy ledger, nothing gained" 0 out \
  "energy: 14.7 J at the start, 2.45 J at the end; lost 12 J at impacts" check tilted_box.yaml
[[ "$out" == *"gained nothing beyond round-off"* ]] && ok "the ledger shows no round-off as a gain" ||
  not_ok "the ledger shows no round-off as a gain"
run simulate tilted_box.yaml --json
json_check "the JSON gives the switch, its time and the ledger; the box at rest on a face" \
  'd["collision_method"] == "sequential"' 'abs(d["collision_method_switch_time"] - 0.576) < 1e-12' \
  '"struck each other" in d["collision_method_switch"]' 'd["energy_ledger"]["gained"] == 0' \
  'abs(d["energy_ledger"]["start"] - d["energy_ledger"]["end"] - d["energy_ledger"]["lost_at_impacts"] - d["energy_ledger"]["lost_in_contacts"] - d["energy_ledger"]["lost_by_integrator"]) < 1e-9' \
  'd["bodies"][1]["vx"] ** 2 + d["bodies"][1]["vy"] ** 2 < 1e-18' 'abs(d["bodies"][1]["y"] - 0.25) < 0.005'
# energy_never_rises failing: explicit Euler on a spring gains energy every step
cat >gaining.yaml <<'EOF'
duration: 2
sim: {integrator: explicit_euler, dt: 0.01}
bodies: [{name: mass, shape: {circle: 0.1}, mass: 1, position: [1, 0]}]
forces: [{type: spring, body: mass, anchor: [0, 0], stiffness: 4}]
expect: [{energy_never_rises: true, tolerance: 0.05}]
EOF
expect "energy_never_rises fails with the first time and the amount" 1 out \
  "FAIL  t = 0.62  energy_never_rises (rose in free motion: the integrator's) = 0.0502" check gaining.yaml
# a method named that leaves out what the scene asks for: a warning at its key, the run goes on
sed 's/^bodies:/sim: {collisions: event}\nbodies:/' tilted_box.yaml >event_box.yaml
expect "collisions: event under friction and gravity warns at its key" 0 err \
  "event_box.yaml:3:19: warning: 'collisions: event': the scene names friction, and 'event' does not model sliding friction" \
  simulate event_box.yaml -q
expect "--integrator rk4 under soft_step warns naming the option" 0 err \
  "event_box.yaml: --integrator rk4: warning: 'soft_step' does not use it" simulate event_box.yaml -q --collisions soft_step --integrator rk4

# ---- simulate: bad input exits 2 -----------------------------------------------------------

expect "a missing scene file exits 2 naming the file" 2 err "missing.yaml: cannot open" simulate missing.yaml

run simulate bad.yaml
if [ "$rc" -eq 2 ] && [[ "$err" == "bad.yaml:3:12: "* ]] && [[ "$err" == *"invalid YAML"* ]]; then
  ok "a YAML syntax error exits 2 with stderr starting bad.yaml:3:12:"
else
  not_ok "a YAML syntax error exits 2 with stderr starting bad.yaml:3:12:" "exit code $rc"
fi

expect "an unknown variant exits 2 listing the variants" 2 err "center, end" simulate "$POLL" --variant nope
expect "an unknown variant names it" 2 err "unknown variant 'nope'" simulate "$POLL" --variant nope
expect "--integrator bogus exits 2 listing the integrators" 2 err "rk4" simulate "$POLL" --integrator bogus
expect "--integrator bogus names it" 2 err "'bogus'" simulate "$POLL" --integrator bogus
expect "--dt 0 exits 2" 2 err "--dt" simulate "$POLL" --dt 0
expect "--dt -1 exits 2" 2 err "--dt" simulate "$POLL" --dt -1
expect "--dt nan exits 2" 2 err "--dt" simulate "$POLL" --dt nan
expect "--until -1 exits 2" 2 err "--until" simulate "$POLL" --until -1
expect "--substeps 0 exits 2" 2 err "--substeps: give a whole number from 1 to 1000" simulate "$POLL" --substeps 0
expect "--substeps 1001 exits 2" 2 err "--substeps: give a whole number from 1 to 1000" simulate "$POLL" --substeps 1001
expect "--contact-hertz -3 exits 2" 2 err "--contact-hertz: the contact stiffness must be a positive" simulate "$POLL" --contact-hertz -3
expect "--contact-hertz inf exits 2" 2 err "--contact-hertz" simulate "$POLL" --contact-hertz inf

# --substeps and --contact-hertz set what the scene's sim: block sets: the arch's soft_step_stiff
# variant (sim: {substeps: 12, contact_hertz: 100}) and the base scene with both on the command line
# end in the same state, bit for bit, and not in the base scene's
ARCH=$SCENES/arch.yaml
state() { "$BIN" simulate "$ARCH" --json "$@" | sed 's/"variant":[^,]*,//'; }
stiff_yaml=$(state --variant soft_step_stiff)
stiff_cli=$(state --substeps 12 --contact-hertz 100)
base=$(state)
if [ -n "$stiff_cli" ] && [ "$stiff_cli" = "$stiff_yaml" ] && [ "$stiff_cli" != "$base" ]; then
  ok "--substeps 12 --contact-hertz 100 runs the arch as its variant with sim: {substeps: 12, contact_hertz: 100}"
else
  not_ok "--substeps 12 --contact-hertz 100 runs the arch as its variant with sim: {substeps: 12, contact_hertz: 100}"
fi
expect "--threads 0 exits 2" 2 err "--threads: give a whole number from 1 to 64" simulate "$POLL" --threads 0
expect "check --threads 65 exits 2" 2 err "--threads" check "$ARCH" --threads 65
# the soft_step sets split between two threads: the same state, bit for bit (and check passes). A
# step shares its threads only from 1,000 contacts per thread past the first (sim/core/settings.h),
# so the arch's 24 run on one: a packed pyramid of 465 boxes (about 1,400 contacts) shares them
pile="$WORK/pile465.yaml"
{
  printf 'name: pile465\nduration: 0.5\nworld: {gravity: [0, -10], friction: 0.6}\nsim: {collisions: soft_step, dt: 0.016666666666666667}\nbodies:\n'
  printf '  - {name: ground, shape: {plane: {point: [0, 0], normal: [0, 1]}}}\n'
  for r in $(seq 0 29); do
    for j in $(seq 0 $((29 - r))); do
      printf '  - {name: b%d_%d, shape: {box: [1, 1]}, position: [%d.%d, %d.5]}\n' "$r" "$j" $((j + r / 2)) $((r % 2 * 5)) "$r"
    done
  done
} >"$pile"
pile_state() { "$BIN" simulate "$pile" --json "$@"; }
pile_one=$(pile_state)
if [ -n "$pile_one" ] && [ "$(pile_state --threads 2)" = "$pile_one" ] && [ -n "$base" ] && [ "$(state --threads 2)" = "$base" ]; then
  ok "--threads 2 ends a 465-box pile (shared) and the arch (one thread) in the state of one thread"
else
  not_ok "--threads 2 ends a 465-box pile (shared) and the arch (one thread) in the state of one thread"
fi
expect "check --threads 2 passes the arch's expect entries" 0 out "" check "$ARCH" --threads 2 -q
expect "no subcommand exits 2" 2 err "subcommand" 
expect "an unknown subcommand exits 2" 2 err "" render-everything "$POLL"
expect "simulate without a scene exits 2" 2 err "scene" simulate

# ---- simulate --trace ----------------------------------------------------------------------

header='t,body,x,y,angle,vx,vy,omega,kinetic_energy'
run simulate "$POLL" --variant end --until 1 --json --trace out.csv
if [ "$rc" -ne 0 ] || [ ! -f out.csv ]; then
  not_ok "--trace out.csv exits 0 and writes out.csv" "exit code $rc"
else
  ok "--trace out.csv exits 0 and writes out.csv"
  first=$(head -n 1 out.csv)
  if [ "$first" = "$header" ]; then ok "the trace header is exactly $header"; else not_ok "the trace header is exactly $header" "got: $first"; fi
  # one row per body initially, after every step and after every event: 1 + (1000 + 1 + 1) * 1
  steps=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["steps"])' "$CAP/out")
  want=$((1 + (steps + 1 + 1) * 1))
  lines=$(wc -l <out.csv)
  if [ "$steps" = 1000 ] && [ "$lines" -eq "$want" ] && [ "$lines" -eq 1003 ]; then
    ok "the trace has 1 + (steps + 1 + events) * bodies = 1003 lines"
  else
    not_ok "the trace has 1 + (steps + 1 + events) * bodies = 1003 lines" "steps $steps, $lines lines, expected $want"
  fi
  # the event row: at t = 0.5, after the step row, with the impulse's velocities
  event_row=$(sed -n 503p out.csv)
  if [ "$(sed -n 502p out.csv | cut -d, -f1,2,8)" = "0.5,bar,0" ] && [ "$(echo "$event_row" | cut -d, -f1,2,6,8)" = "0.5,bar,0.3333333333333333,-0.5" ]; then
    ok "the trace has the step row and then the event row at t = 0.5"
  else
    not_ok "the trace has the step row and then the event row at t = 0.5" "line 503: $event_row"
  fi
  if [ "$(tail -n 1 out.csv | cut -d, -f1)" = 1 ]; then ok "the trace ends at t = 1"; else not_ok "the trace ends at t = 1" "$(tail -n 1 out.csv)"; fi
fi
if no_part_files; then ok "a good trace leaves no .part file"; else not_ok "a good trace leaves no .part file" "$(ls -a)"; fi

expect "--trace to an unwritable place exits 2 naming it" 2 err "/nonexistent-dir/x.csv" \
  simulate "$POLL" --until 0.1 --trace /nonexistent-dir/x.csv

# ---- a diverging simulation ----------------------------------------------------------------

run simulate diverge.yaml
if [ "$rc" -ne 1 ]; then
  not_ok "a diverging simulation exits 1" "exit code $rc"
else
  ok "a diverging simulation exits 1"
  t=$(sed -n 's/.*diverged at t = \([0-9.eE+-]*\).*/\1/p' <<<"$err")
  if [ -n "$t" ] && awk -v t="$t" 'BEGIN { exit !(t > 0 && t <= 100) }'; then
    ok "the divergence message names the time (t = $t)"
  else
    not_ok "the divergence message names the time"
  fi
  if [[ "$err" == *"'bob'"* ]]; then ok "the divergence message names the body"; else not_ok "the divergence message names the body"; fi
  if [[ "$err" == *"smaller step"* && "$err" == *"--dt 0.025"* ]]; then
    ok "the divergence message suggests a smaller dt (--dt 0.025)"
  else
    not_ok "the divergence message suggests a smaller dt (--dt 0.025)"
  fi
fi

run simulate diverge.yaml --trace diverged.csv
if [ "$rc" -eq 1 ] && [ ! -e diverged.csv ] && no_part_files; then
  ok "a diverging run with --trace exits 1 and leaves no trace and no .part file"
else
  not_ok "a diverging run with --trace exits 1 and leaves no trace and no .part file" "exit code $rc; $(ls -a | tr '\n' ' ')"
fi

run simulate "$POLL" --until 0.2 --trace keep.csv
if [ "$rc" -ne 0 ] || [ ! -s keep.csv ]; then
  not_ok "a good run writes keep.csv" "exit code $rc"
else
  before=$(cksum <keep.csv)
  run simulate diverge.yaml --trace keep.csv
  after=$(cksum <keep.csv)
  if [ "$rc" -eq 1 ] && [ "$before" = "$after" ] && no_part_files; then
    ok "a diverging run leaves an existing trace file unchanged"
  else
    not_ok "a diverging run leaves an existing trace file unchanged" "exit code $rc; cksum $before -> $after"
  fi
fi

# ---- check ---------------------------------------------------------------------------------

run check "$SCENES"/*.yaml
if [ "$rc" -eq 0 ] && [[ "$out" == *"  ok    "* ]] && [[ "$out" != *FAIL* ]]; then
  ok "check passes every scene in scenes/"
else
  not_ok "check passes every scene in scenes/" "exit code $rc"
fi

if ! grep -q 'angle: -0.3,' wrong_expect.yaml; then
  not_ok "check with a wrong expected value exits 1 and prints FAIL" "could not write wrong_expect.yaml"
else
  expect "check with a wrong expected value exits 1 and prints FAIL" 1 out "FAIL" check wrong_expect.yaml
  expect "check reports the failing quantity against its expected value" 1 out "expected -0.3" check wrong_expect.yaml
fi

run check bad.yaml
if [ "$rc" -eq 2 ] && [[ "$err" == "bad.yaml:3:12: "* ]]; then
  ok "check on a bad scene exits 2 with FILE:LINE:COL"
else
  not_ok "check on a bad scene exits 2 with FILE:LINE:COL" "exit code $rc"
fi
expect "check on a missing file exits 2" 2 err "missing.yaml" check missing.yaml
expect "check on a diverging scene exits 1" 1 err "diverged" check diverge.yaml
expect "check without files exits 2" 2 err "" check

# sweep and stability: their files, their header, their bad input
MASS=$SCENES/spring_mass.yaml
expect "sweep runs and names its reference" 0 out "error against: expect" sweep "$MASS" --integrators rk4,symplectic_euler --dt 0.1:0.05:2 --repeat 1 -o sw
if [ "$(head -n 1 sw/spring_mass-sweep.csv 2>/dev/null)" = "integrator,collisions,dt,iterations,steps,seconds_per_sim_second,error,energy_drift,max_penetration,reference" ] &&
   [ "$(wc -l < sw/spring_mass-sweep.csv)" -eq 5 ] && [ -s sw/spring_mass-sweep.png ]; then
  ok "sweep writes the CSV (header, a row per case) and the chart"
else
  not_ok "sweep writes the CSV (header, a row per case) and the chart" "$(ls sw 2>&1)"
fi
expect "sweep --dt without a count exits 2" 2 err "FROM:TO:COUNT" sweep "$MASS" --dt 0.1:0.01 -o sw
expect "sweep --integrators with an unknown name exits 2" 2 err "unknown name 'bogus'" sweep "$MASS" --integrators rk4,bogus -o sw
expect "stability prints the failure at the boundary" 0 out "symplectic_euler + auto: energy" stability "$MASS" --integrators symplectic_euler -o st
if [ "$(head -n 1 st/spring_mass-stability.csv 2>/dev/null)" = "integrator,collisions,parameter,largest_stable,first_failing,failure" ] &&
   [ -s st/spring_mass-stability.png ]; then
  ok "stability writes its CSV and chart"
else
  not_ok "stability writes its CSV and chart" "$(ls st 2>&1)"
fi
expect "stability --collisions with an unknown name exits 2" 2 err "unknown name" stability "$MASS" --collisions bogus -o st
# a stack: cost per step against the rest pose, over iterations and substeps
STACK=$SCENES/box_stack.yaml
expect "sweep --stack measures against the rest pose" 0 out "against: the rest pose" sweep "$STACK" --stack --integrators symplectic_euler \
  --collisions sequential,soft_step --iterations 4,8 --substeps 2,4 --dt 0.05:0.05:1 --repeat 1 -o sw
if [ "$(head -n 1 sw/box_stack-sweep.csv 2>/dev/null)" = "integrator,collisions,dt,iterations,substeps,steps,cpu_seconds_per_step,top_displacement,max_displacement,fastest" ] &&
   [ "$(wc -l < sw/box_stack-sweep.csv)" -eq 5 ] && [ -s sw/box_stack-sweep.png ]; then
  ok "sweep --stack writes a row per iteration and substep count, and the chart"
else
  not_ok "sweep --stack writes a row per iteration and substep count, and the chart" "$(ls sw 2>&1)"
fi
expect "sweep --substeps with a bad count exits 2" 2 err "--substeps: expected whole numbers" sweep "$STACK" --stack --substeps 2,0 -o sw
# every method failing at every value still gets its CSV and chart (gnuplot refused an empty log axis)
expect "stability where every method fails everywhere still writes its files" 0 out "fails at every value tried" \
  stability "$SCENES/pyramid.yaml" --integrators symplectic_euler --collisions isolated -o st_fail
if [ "$(tail -n 1 st_fail/pyramid-stability.csv 2>/dev/null)" = "symplectic_euler,isolated,pyramid_base,0,1,not at rest" ] &&
   [ -s st_fail/pyramid-stability.png ]; then
  ok "a pyramid_base search that fails everywhere writes its row and chart"
else
  not_ok "a pyramid_base search that fails everywhere writes its row and chart" "$(ls st_fail 2>&1)"
fi
printf 'bodies: [{name: a, shape: {circle: 1}}]\nstability: {parameter: iterations, within: -1}\n' > bad_within.yaml
expect "a stability block with a negative 'within' exits 2 naming it" 2 err "bad_within.yaml:2:" stability bad_within.yaml -o st
if compgen -G "sw/*.part-*" >/dev/null || compgen -G "st/*.part-*" >/dev/null; then
  not_ok "sweep and stability leave no partial files" "$(ls sw st)"
else
  ok "sweep and stability leave no partial files"
fi

# ---- 3D scenes (dimensions: 3): check, simulate --json/--trace, snapshot, and their bad input ----

TOP=$SCENES/lecture/13_symmetric_top.yaml
expect "check of a 3D scene passes its closed forms and says nothing collides" 0 out \
  "collisions: none (auto: no two bodies can meet, so no collision model is needed)" check "$TOP"
run simulate "$TOP" --variant oblate --until 0.5 --json --trace top.csv
json_check "simulate --json of a 3D scene names each quantity as the issue does" \
  'sorted(b.keys()) == ["angular_momentum", "angular_velocity", "kinetic_energy", "name", "orientation", "position", "velocity"]' \
  'len(b["position"]) == 3 and len(b["orientation"]) == 4 and len(b["angular_momentum"]) == 3' \
  'abs(sum(x * x for x in b["orientation"]) - 1) < 1e-12' \
  'sorted(d["energy"].keys()) == ["kinetic", "potential", "total"]' \
  'len(d["momentum"]) == 3 and len(d["angular_momentum"]) == 3' \
  'abs(d["energy"]["total"] - 1.2365308684529426) < 1e-5'
if [ "$(head -n 1 top.csv 2>/dev/null)" = "t,body,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,kinetic_energy" ] && [ "$(wc -l < top.csv)" -eq 502 ]; then
  ok "simulate --trace of a 3D scene: the issue's header, a row per step"
else
  not_ok "simulate --trace of a 3D scene: the issue's header, a row per step" "$(head -n 2 top.csv 2>&1)"
fi
cat >far_quaternion.yaml <<'EOF'
dimensions: 3
bodies:
  - name: a
    shape: {sphere: 1}
    orientation: [1, 1, 0, 0]
EOF
expect "a quaternion far from unit length is bad input at FILE:LINE:COL" 2 err "far_quaternion.yaml:5:18" check far_quaternion.yaml
expect "--collisions soft_step on a 3D scene exits 2 naming 3D's methods" 2 err \
  "takes the collision methods auto, none, event and sequential" simulate "$TOP" --collisions soft_step
cat >box_ball.yaml <<'EOF'
dimensions: 3
sim: {collisions: none}
bodies:
  - {name: floor, shape: {plane: {normal: [0, 0, 1]}}}
  - {name: box, shape: {box: [1, 1, 1]}, position: [0, 0, 2]}
  - {name: ball, shape: {sphere: 0.5}, position: [3, 0, 2]}
EOF
expect "--collisions that would let a box pass through a ball exits 2 naming the pair" 2 err \
  "'ball' and 'box' would pass through each other" simulate box_ball.yaml --collisions sequential
cat >diverging3d.yaml <<'EOF'
dimensions: 3
duration: 1
bodies:
  - {name: b, shape: {sphere: 1}, mass: 1e300, velocity: [0, 0, -1e200], angular_velocity: [1e200, 1e200, 0]}
EOF
expect "a 3D run that diverges under the splitting suggests another integrator than the one it ran" 1 out \
  "another integrator (--integrator rk4)" check diverging3d.yaml
expect "--contact-hertz on a 3D scene exits 2: 3D has no soft_step" 2 err "has no soft_step" simulate "$TOP" --contact-hertz 60
expect "--precision on a 3D scene exits 2: 3D has no soft_step" 2 err "--precision: " simulate "$TOP" --precision float
expect "snapshot --impacts of a 3D scene where nothing meets exits 2" 2 err "has no impacts" snapshot "$TOP" --impacts -o snap3
expect "snapshot of a 3D scene writes its PNG" 0 out "13_symmetric_top-oblate-t0.5.png" snapshot "$TOP" --variant oblate --at 0.5 --size 160x90 -o snap3

# ---- the GL library, loaded only to draw ---------------------------------------------------

# loads NAME ARGS...: the dynamic loader's record (LD_DEBUG=files) of running ARGS names libOSMesa
loads_gl() {
  LD_DEBUG=files "$BIN" "$@" >"$CAP/out" 2>"$CAP/err"
  grep -q "file=libOSMesa" "$CAP/err"
}
for command in "check $POLL" "simulate $POLL --json" "sweep $MASS --integrators rk4 --dt 0.1:0.05:2 --repeat 1 -o gl_sw" \
               "stability $MASS --integrators symplectic_euler -o gl_st"; do
  # shellcheck disable=SC2086
  if loads_gl $command; then not_ok "${command%% *} never loads libOSMesa"; else ok "${command%% *} never loads libOSMesa"; fi
done
if loads_gl snapshot "$POLL" --at 0.5 -o gl_snap; then
  ok "snapshot loads libOSMesa to draw"
else
  not_ok "snapshot loads libOSMesa to draw"
fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
