# What the command-line test scripts share (sourced, not run): their arguments, a scratch
# directory removed at exit, and the ok / not ok bookkeeping of the cases.
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
