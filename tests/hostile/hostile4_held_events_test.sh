#!/usr/bin/env bash
# The fourth battery (issue 41), bounded work for held events: each event's arrow stays on screen for
# contact_hold, and a step touches only what it adds or forgets, so a snapshot of a scene with as
# many events as max_entries allows costs about what simulating it costs (each step copied every
# held afterimage: 100,000 events took over a minute to draw where the run took 2 s).
#
# usage: bash tests/hostile/hostile4_held_events_test.sh <path-to-rigidreel> <project-source-dir>
set -u

HERE=$(cd "$(dirname "$0")" && pwd)
source "$HERE/../render/cli/cli_harness.sh"
source "$HERE/hostile_harness.sh"
cli_setup hostile4-held-events-test "$@"

# events: N impulses of 1e-9 N·s on one ball, spread over 10 s (1,000 steps), so that about 5,000
# are held at once (contact_hold 0.5 s)
events() {
  awk -v n="$1" 'BEGIN {
    print "name: held\nduration: 10\nsim: {dt: 0.01}\nbodies: [{name: ball, shape: {circle: 0.2}, velocity: [1, 0]}]\nevents:"
    for (k = 1; k <= n; k++) printf "- {time: %.9g, body: ball, impulse: [1.0e-9, 0]}\n", 10 * k / (n + 1)
  }' >held.yaml
}

events 100000
run simulate held.yaml
check "a ball with 100,000 impulse events simulates" "$rc" "exit $rc"
# under the deadline of run (60 s): it took over a minute when each step copied the held arrows
run snapshot held.yaml --at 10 -o o --size 320x180
[ "$rc" -eq 0 ] && [ -s o/held/held-t10.png ]
check "  ... and its snapshot at the end is drawn within the deadline" $? "exit $rc"
run render held.yaml -o o --size 160x90 --fps 2 --quiet
[ "$rc" -eq 0 ] && [ -s o/held/held.mp4 ]
check "  ... and its video (held arrows in every frame) within the deadline" $? "exit $rc"

cli_finish
