#!/usr/bin/env bash
# No header in sim/ or render/ re-exports another namespace's names: a namespace-scope
# using-declaration (`using render::draw::Camera;`) or using-directive in a header would make
# render::frame::Camera a name of the frame layer, so that neither a reader nor the compiler could
# tell which layer a name belongs to. Headers spell the owning namespace; a .cpp file may declare
# the short names it wants for itself. (A using-declaration inside a class, indented, is not one.)
# usage: reexport_test.sh SOURCE_DIR
set -u
src=${1:-.}
cd "$src" || exit 2
mapfile -t headers < <(git ls-files --cached --others --exclude-standard -- 'sim/*.h' 'render/*.h' 2>/dev/null ||
  find sim render -name '*.h')
[ ${#headers[@]} -gt 0 ] || { echo "FAIL: no headers found under sim/ and render/ in $src"; exit 1; }
found=$(grep -nE '^using (namespace [a-z_0-9:]+|[a-z_0-9]+(::[a-z_0-9]+)*::[A-Za-z_0-9]+);' "${headers[@]}")
if [ -n "$found" ]; then
  echo "FAIL: headers that re-export another namespace's names (spell the namespace in the header; a .cpp may declare the short name):"
  echo "$found"
  exit 1
fi
echo "ok: ${#headers[@]} headers, none re-exports another namespace's names"
