# What the hostile batteries share (sourced after cli_harness.sh's cli_setup): runs under a
# deadline, signals sent until honoured, bounded memory, a dead process id.
# every run under a deadline: an unbounded one (10¹⁸ steps, /dev/zero) fails its case with exit 124
# instead of hanging the suite
run() {
  timeout -k 5 60 "$BIN" "$@" >out 2>err
  rc=$?
}
no_parts() { ! find "${1:-o}" -name '*.part*' | grep -q .; }
# signal_and_wait SIGNAL PID: sends SIGNAL every 0.5 s until PID ends (a background job starts
# with SIGINT ignored until rigidreel installs its handler, so one early signal may be lost), and
# kills it (exit 137) if it has not ended 10 s later: a signal that is not honoured shows as 137,
# not as a test that hangs; sets rc
signal_and_wait() {
  local k
  for ((k = 0; k < 20; k++)); do
    # an ended child stays a zombie (state Z) until waited for, and a zombie takes signals
    [ "$(cut -d' ' -f3 "/proc/$2/stat" 2>/dev/null)" = Z ] && break
    kill -"$1" "$2" 2>/dev/null || break
    sleep 0.5
  done
  kill -KILL "$2" 2>/dev/null
  wait "$2"
  rc=$?
}
# bounded memory: 1 GB of address space, except under AddressSanitizer (make sanitize sets
# ASAN_OPTIONS), which reserves terabytes of address space for its shadow memory at start
limit_memory() { [ -n "${ASAN_OPTIONS:-}" ] || ulimit -v 1000000; }
# a process id that has ended (a child that exited)
dead_pid() { sh -c 'echo $$'; }
