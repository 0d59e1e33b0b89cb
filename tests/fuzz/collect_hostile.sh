#!/usr/bin/env bash
# Grows the scene loader's corpus (tests/fuzz/scene_loader) by the hostile batteries' scene files:
# runs tests/hostile/*_test.sh through a wrapper that keeps each regular *.yaml file handed to
# rigidreel (named, or in a folder named; FIFOs, devices and links are not files to keep, and
# files past make fuzz's -max_len of 4096 bytes would be cut), then copies those not already in
# the corpus or in scenes/ as <battery>-<file>-<hash>.yaml.
# usage: tests/fuzz/collect_hostile.sh build/rigidreel
set -u
BIN=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
SRC=$(cd "$(dirname "$0")/../.." && pwd)
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
cat >"$WORK/rigidreel" <<WRAP
#!/usr/bin/env bash
keep() {
  if [ -f "\$1" ] && [ ! -L "\$1" ] && [ "\$(stat -c %s "\$1")" -le 4096 ]; then
    cp "\$1" "\$COLLECT/\$(basename "\${1%.*}")-\$(sha1sum "\$1" | cut -c1-8).yaml" 2>/dev/null
  fi
}
for a in "\$@"; do
  case "\$a" in *.yaml | *.yml) keep "\$a" ;; esac
  if [ -d "\$a" ]; then for f in "\$a"/*.yaml; do keep "\$f"; done; fi
done
exec "$BIN" "\$@"
WRAP
chmod +x "$WORK/rigidreel"
declare -A known
for f in "$SRC"/tests/fuzz/scene_loader/* "$SRC"/scenes/*.yaml "$SRC"/scenes/*/*.yaml; do known[$(sha1sum <"$f" | cut -c1-40)]=1; done
added=0
for test in "$SRC"/tests/hostile/*_test.sh; do
  battery=$(basename "$test" _test.sh)
  mkdir -p "$WORK/$battery"
  COLLECT="$WORK/$battery" bash "$test" "$WORK/rigidreel" "$SRC" >"$WORK/$battery.log" 2>&1 || echo "$battery: failed (see its log)" >&2
  for f in "$WORK/$battery"/*.yaml; do
    [ -f "$f" ] || continue
    h=$(sha1sum <"$f" | cut -c1-40)
    [ -n "${known[$h]:-}" ] && continue
    known[$h]=1
    cp "$f" "$SRC/tests/fuzz/scene_loader/$battery-$(basename "$f")"
    added=$((added + 1))
  done
done
echo "$added inputs added to tests/fuzz/scene_loader"
