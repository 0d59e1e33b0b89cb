#!/usr/bin/env bash
# The lecture pack end to end (ctest lecture_pack): `rigidreel lecture PACK` at a small size and
# frame rate writes every output that `rigidreel lecture PACK --list` plans (each variant's video
# and poster, each panel image, each scene's record, the page), every video H.264 at that size,
# every PNG a PNG, every record JSON, and the page valid HTML by Debian's tidy in its strict mode,
# with a section per scene. A missing or empty pack fails: a test that cannot fail is no test.
#
# usage: bash tests/render/cli/lecture_pack_test.sh <path-to-rigidreel> <pack-dir> <work-dir>
set -u

if [ $# -ne 3 ]; then
  echo "usage: $0 <path-to-rigidreel> <pack-dir> <work-dir>" >&2
  exit 2
fi
BIN=$1
PACK=$2
OUT=$3/out
OPTIONS=(--size 160x90 --fps 10)

if ! ls "$PACK"/*.yaml >/dev/null 2>&1; then
  echo "FAIL: $PACK is missing or has no scenes (*.yaml); the lecture pack belongs there"
  exit 1
fi
rm -rf "$OUT"
mkdir -p "$3"

if ! "$BIN" lecture "$PACK" "${OPTIONS[@]}" -o "$OUT" --list >"$3/expected" 2>"$3/err"; then
  echo "FAIL: rigidreel lecture --list: $(cat "$3/err")"
  exit 1
fi
echo "$(wc -l <"$3/expected") outputs planned for $(ls "$PACK"/*.yaml | wc -l) scenes"
"$BIN" lecture "$PACK" "${OPTIONS[@]}" -o "$OUT" --quiet >"$3/summary" 2>"$3/err"
rc=$?
cat "$3/summary"
if [ "$rc" -ne 0 ]; then
  echo "FAIL: rigidreel lecture exited $rc: $(cat "$3/err")"
  exit 1
fi

failed=0
while read -r path; do
  case "$path" in
    *.mp4) got=$(ffprobe -v error -select_streams v:0 -show_entries stream=codec_name,width,height -of csv=p=0 "$path" 2>&1)
           [ "$got" = "h264,160,90" ] || { echo "FAIL: $path: ffprobe says '$got', expected h264,160,90"; failed=1; } ;;
    *.png) [ "$(head -c 8 "$path" 2>/dev/null | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] ||
             { echo "FAIL: $path is missing or not a PNG"; failed=1; } ;;
    */page.json) python3 -c 'import json, sys; json.load(open(sys.argv[1]))' "$path" 2>/dev/null ||
             { echo "FAIL: $path is missing or not JSON"; failed=1; } ;;
    */index.html)
      # no error and no warning from tidy, tags and attributes checked against HTML5
      problems=$(tidy -q -e --strict-tags-attributes yes --warn-proprietary-attributes yes "$path" 2>&1)
      [ $? -eq 0 ] && [ -z "$problems" ] || { echo "FAIL: $path is not valid HTML: $problems"; failed=1; }
      [ "$(grep -c '<section id="scene-' "$path")" -eq "$(ls "$PACK"/*.yaml | wc -l)" ] ||
        { echo "FAIL: $path has not a section per scene"; failed=1; } ;;
    *) echo "FAIL: unexpected output $path"; failed=1 ;;
  esac
done <"$3/expected"
# the pack wrote what it planned, no more and no less
grep -q "outputs" "$3/summary" &&
  grep -q "^total: .* $(wc -l <"$3/expected") outputs" "$3/summary" || { echo "FAIL: the summary's count differs from --list"; failed=1; }
[ "$(find "$OUT" -type f | wc -l)" -eq "$(wc -l <"$3/expected")" ] || { echo "FAIL: files written differ from --list"; failed=1; }
[ "$failed" -eq 0 ] && echo "ok: every planned output exists and is valid, the page too"
exit "$failed"
