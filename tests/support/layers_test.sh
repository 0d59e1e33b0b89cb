#!/usr/bin/env bash
# layers_test.sh BUILD SOURCE PROBE...: the layering of sim/ and render/ holds.
#   PROBE is verdict:target:layer:header; an "allow" probe must compile, a "deny" probe must fail
#   because the header is not found (the layer's include root does not hold it), in g++'s words or
#   clang's (make sanitize builds with clang).
#   Every .h and .cpp of a layer folder declares the folder's namespace (sim/core: sim::core).
set -u
build=$1 source=$2
shift 2
failures=0
for probe in "$@"; do
  IFS=: read -r verdict target layer header <<<"$probe"
  output=$(cmake --build "$build" --target "$target" 2>&1)
  status=$?
  if [ "$verdict" = allow ] && [ $status -ne 0 ]; then
    echo "FAIL: $layer cannot include $header, which it links:"; echo "$output" | grep -m3 error
    failures=$((failures + 1))
  elif [ "$verdict" = deny ] && ! { [ $status -ne 0 ] && grep -Eq "$header: No such file|'$header' file not found" <<<"$output"; }; then
    echo "FAIL: $layer includes $header, a layer it does not link (status $status)"
    failures=$((failures + 1))
  else
    echo "ok: $verdict $layer -> $header"
  fi
done
cd "$source" || exit 1
for folder in sim/*/ render/*/; do
  folder=${folder%/}
  namespace=${folder//\//::}
  for file in "$folder"/*.h "$folder"/*.cpp; do
    [ -e "$file" ] || continue
    case "$file" in */main.cpp | render/bench/*) continue ;; esac
    grep -Eq "^namespace $namespace(::[a-z_]+)? \{" "$file" || { echo "FAIL: $file does not declare namespace $namespace"; failures=$((failures + 1)); }
  done
done
# the simulator knows nothing of pictures: no colors, panels, videos, lectures or pixels, and
# "frame" only as a coordinate frame (a body's, the world's); in its code, not in sim/README.md,
# which tells a reader which pictures each model serves
pictures=$(grep -rniwE --exclude='*.md' 'colou?rs?|panels?|videos?|lectures?|pixels?' sim/)
frames=$(grep -rniw --exclude='*.md' 'frames\?' sim/ | grep -viE 'body|world|coordinate')
if [ -n "$pictures$frames" ]; then
  echo "FAIL: sim/ mentions pictures:"; printf '%s\n' "$pictures" "$frames" | grep .
  failures=$((failures + 1))
fi
[ $failures -eq 0 ] && echo "layers hold" || { echo "$failures failures"; exit 1; }
