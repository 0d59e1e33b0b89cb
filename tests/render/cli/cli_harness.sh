# What the command-line test scripts share (sourced, not run): their arguments, a scratch
# directory removed at exit, the ok / not ok bookkeeping of the cases, and reading what `golden check`
# reports (a level's line, a JUnit file), and checking the entries `expect` printed.
#
# cli_setup NAME "$@": checks the arguments <path-to-rigidreel> <project-source-dir>; sets BIN and
# SRC (absolute), WORK (a new scratch directory, removed at exit) and changes into it
cli_setup() {
  local name=$1
  shift
  if [ $# -ne 2 ]; then
    echo "usage: $name <path-to-rigidreel> <project-source-dir>" >&2
    exit 2
  fi
  BIN=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
  SRC=$(cd "$2" && pwd)
  WORK=$(mktemp -d "${TMPDIR:-/tmp}/rigidreel-$name.XXXXXX") || exit 2
  trap 'rm -rf "$WORK"' EXIT
  cd "$WORK" || exit 2
  passed=0
  failed=0
}

check() {  # check NAME CONDITION-STATUS [DETAIL]: one case, with the last run's output when it failed
  if [ "$2" -eq 0 ]; then
    echo "ok - $1"
    passed=$((passed + 1))
  else
    echo "not ok - $1"
    [ -n "${3:-}" ] && echo "#   $3"
    echo "#   stdout: $(head -c 800 out 2>/dev/null)"
    echo "#   stderr: $(head -c 800 err 2>/dev/null)"
    failed=$((failed + 1))
  fi
}
run() {  # run ARGS...: sets rc; output in ./out and ./err
  "$BIN" "$@" >out 2>err
  rc=$?
}
expect() {  # expect NAME CODE TEXT ARGS...: exits CODE and stderr contains TEXT
  local name=$1 code=$2 text=$3
  shift 3
  run "$@"
  [ "$rc" -eq "$code" ] && grep -qF -- "$text" err
  check "$name" $? "exit $rc, expected $code with '$text'"
}
cli_finish() {  # the count, and the script's exit status
  echo "$passed passed, $failed failed"
  [ "$failed" -eq 0 ]
}
junit() {  # junit FILE: "tests failures", as python's XML parser counts the testcases and their failures
  python3 -c '
import sys, xml.etree.ElementTree as ET
cases = ET.parse(sys.argv[1]).getroot().findall(".//testcase")
print(len(cases), sum(1 for c in cases if c.find("failure") is not None))' "$1"
}
level() {  # level NAME: the line `golden check` printed (in ./out) for that level of the record in $G
  grep "^$(basename "$G")  $1  " out
}
pasted() {  # pasted SCENE OKS NAME: expect's entries (./out) appended to SCENE pass check, OKS comparisons ok
  { cat "$1"; cat out; } >pasted.yaml
  run check pasted.yaml
  [ "$rc" -eq 0 ] && [ "$(grep -c '^  ok ' out)" -eq "$2" ]
  check "$3" $? "exit $rc: $(head -c 400 out)"
}
