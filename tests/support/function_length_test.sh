#!/usr/bin/env bash
# No function in sim/ and render/ runs over 80 lines (the benchmarks' mains in render/bench aside):
# a longer one is split into named stages, each a function that fits on a screen, so that the top
# function reads as a list of them (Box2D-Lite's World::Step). Lengths are universal-ctags' (a
# function's first line to its last, lambdas within it counted in it).
# usage: function_length_test.sh SOURCE_DIR
set -u
src=$1
limit=80
cd "$src" || exit 2

# universal-ctags alone writes the `end:` field (Exuberant Ctags, the older `ctags`, does not)
if ! command -v ctags >/dev/null || ! ctags --version 2>/dev/null | grep -q 'Universal Ctags'; then
  echo "FAIL: this test needs universal-ctags; install it (apt-get install universal-ctags, or make deps)"
  exit 1
fi

# the C++ files git has, and those it does not track yet (a new file is checked before it is added)
mapfile -t files < <({ git ls-files --cached --others --exclude-standard -- 'sim/*.cpp' 'sim/*.h' 'render/*.cpp' \
  'render/*.h' 2>/dev/null || find sim render -name '*.cpp' -o -name '*.h'; } | grep -v '^render/bench/')
[ ${#files[@]} -gt 0 ] || { echo "FAIL: no C++ files found under sim/ and render/ in $src"; exit 1; }

tags=$(printf '%s\n' "${files[@]}" | ctags --languages=C++ --fields=+ne --c++-kinds=f -L - -f -) ||
  { echo "FAIL: ctags could not read the files"; exit 1; }
long=$(awk -F'\t' -v limit=$limit '{
    first = ""; last = ""
    for (i = 4; i <= NF; i++) { if ($i ~ /^line:/) first = substr($i, 6); if ($i ~ /^end:/) last = substr($i, 5) }
    if (first != "" && last != "" && last - first + 1 > limit) print $2 ":" first ": " $1 " is " last - first + 1 " lines"
  }' <<<"$tags" | sort)
if [ -n "$long" ]; then
  while read -r line; do echo "FAIL: $line; split it into named stages of at most $limit lines"; done <<<"$long"
  exit 1
fi
echo "every function in sim/ and render/ (render/bench aside) is at most $limit lines (${#files[@]} files)"
