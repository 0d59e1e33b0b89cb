#!/usr/bin/env bash
# `make sanitize`'s run of the suite: ctest in the sanitizer build, and one more run of the tests
# that failed only because LeakSanitizer's own tracer crashed while it stopped the process's threads
# at exit ("Tracer caught signal 11", then "LeakSanitizer has encountered a fatal error"). That is a
# known intermittent fault of the sanitizer runtime on a loaded machine (google/sanitizers#1353),
# not a finding: it reports no leak and no error of ours. Any other failure fails at once, and a
# test that fails again on its second run fails the suite.
#
# usage: tests/sanitize/sanitized_ctest.sh BUILD_DIR JOBS (the sanitizer options in the environment)
set -u
build=$1
jobs=$2
ctest --test-dir "$build" --output-on-failure -j "$jobs" && exit 0

log=$build/Testing/Temporary/LastTest.log
# each failed test's name, and whether its output is the tracer's crash and nothing else of note
verdicts=$(awk '
  /^[0-9]+\/[0-9]+ Test: / { name = $3; out = "" }
  { out = out "\n" $0 }
  /^Test Failed\./ {
    tracer = out ~ /LeakSanitizer has encountered a fatal error/ && out ~ /Tracer caught signal/
    finding = out ~ /ERROR: (Address|Leak)Sanitizer:|runtime error:|SUMMARY: /
    print name, (tracer && !finding) ? "tracer" : "other"
  }' "$log")
echo "$verdicts" | sed 's/^/sanitize: failed: /'
if [ -z "$verdicts" ] || echo "$verdicts" | grep -qv ' tracer$'; then
  exit 1
fi
echo "sanitize: only LeakSanitizer's tracer crashed (google/sanitizers#1353); running the failed tests once more"
ctest --test-dir "$build" --output-on-failure -j "$jobs" --rerun-failed
