#!/usr/bin/env bash
# render/README.md's GNU Parallel recipe (ctest lecture_parallel): one `rigidreel lecture SCENE -j 1` job
# per scene, run by GNU Parallel into one folder, then `rigidreel lecture --page DIR`. Each job
# writes its scene's record and rebuilds the page under a lock on the folder, so the page after the
# jobs already shows every scene; --page rebuilds the same page alone; the folder holds what
# `--list` plans, and the page is valid HTML (tidy, strict). The pack it leaves is the browser
# test's (page_browser).
#
# usage: bash tests/render/cli/lecture_parallel_test.sh <path-to-rigidreel> <project-source-dir> <out-dir>
set -u

if [ $# -ne 3 ]; then
  echo "usage: $0 <path-to-rigidreel> <project-source-dir> <out-dir>" >&2
  exit 2
fi
BIN=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
SRC=$2
mkdir -p "$3"
OUT=$(cd "$3" && pwd)
# from the project, as render/README.md runs it: the page names the scene files as given, the same on
# every machine (the browser test's screenshot shows them). A poll with question and answer panels
# and checks, a scene without variants, and a failure case
cd "$SRC" || exit 2
SCENES=(scenes/lecture/05_impulses.yaml scenes/lecture/09_separating_axes.yaml scenes/lecture/10b_tunneling.yaml)
SMALL=(--size 160x90 --fps 10)
failed=0
fail() { echo "FAIL: $*"; failed=1; }

if ! command -v parallel >/dev/null; then
  echo "FAIL: GNU Parallel is missing (Debian: apt-get install parallel; \`make test\` installs it)"
  exit 1
fi
rm -rf "$OUT"
mkdir -p "$OUT"
LOG=$(mktemp -d "${TMPDIR:-/tmp}/rigidreel-parallel.XXXXXX")
trap 'rm -rf "$LOG"' EXIT

# the recipe, as render/README.md gives it (with the small size and rate), two jobs at a time
start=$(date +%s%N)
parallel --will-cite -j 2 --joblog "$LOG/jobs" "$BIN" lecture {} "${SMALL[@]}" -o "$OUT" -j 1 ::: "${SCENES[@]}" >"$LOG/out" 2>"$LOG/err"
rc=$?
echo "3 jobs under GNU Parallel: $(( ($(date +%s%N) - start) / 1000000 )) ms"
[ "$rc" -eq 0 ] || fail "GNU Parallel exited $rc: $(cat "$LOG/err")"
[ "$(awk 'NR > 1 && $7 == 0' "$LOG/jobs" | wc -l)" -eq 3 ] || fail "not every job exited 0: $(cat "$LOG/jobs")"
[ "$(grep -c '^page: .*/index.html' "$LOG/out")" -eq 3 ] || fail "each job rebuilds the page: $(grep '^page' "$LOG/out")"
# the jobs took the lock in turn: whichever wrote last saw every record
[ "$(grep -c '<section id="scene-' "$OUT/index.html")" -eq 3 ] || fail "the page after the jobs lacks a scene"
cp "$OUT/index.html" "$LOG/after-jobs.html"

# the recipe's last step: the page alone, from the folder
"$BIN" lecture --page "$OUT" >"$LOG/page" 2>&1 || fail "lecture --page: $(cat "$LOG/page")"
grep -qx "wrote $OUT/index.html (3 scenes)" "$LOG/page" || fail "lecture --page says: $(cat "$LOG/page")"
cmp -s "$OUT/index.html" "$LOG/after-jobs.html" || fail "--page wrote another page than the last job did"

# the folder holds what the same pack plans, no more (no lock file, no temporary file)
"$BIN" lecture "${SCENES[@]}" "${SMALL[@]}" -o "$OUT" --list | sort >"$LOG/planned"
find "$OUT" -type f | sort >"$LOG/written"
cmp -s "$LOG/planned" "$LOG/written" || fail "the folder differs from --list: $(diff "$LOG/planned" "$LOG/written")"
problems=$(tidy -q -e --strict-tags-attributes yes --warn-proprietary-attributes yes "$OUT/index.html" 2>&1) && [ -z "$problems" ] ||
  fail "the page is not valid HTML: $problems"

[ "$failed" -eq 0 ] && echo "ok: the GNU Parallel recipe renders the pack and its page, which --page rebuilds alike"
exit "$failed"
