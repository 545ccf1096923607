# Shared by the CLI case tables (hostile_inputs.sh, forged_certificates.sh): one case runs contactcert under a
# memory cap (prlimit --as=$mem, default 2G) and a time cap (timeout, $secs s, default 20) and must end with
# an expected exit code and a message. Needs $cc (the executable) and $work (a scratch folder).
failures=0
cases=0
# run WANT TEXT STDIN STDOUT ARGS...: contactcert ARGS with the given standard input and output; WANT is an
# exit code or several separated by | ("0|3"); TEXT must occur in stderr (with stdout unless stdout is
# redirected elsewhere).
run() {
  local want=$1 text=$2 in=$3 out=$4
  shift 4
  cases=$((cases + 1))
  timeout -s KILL "${secs:-20}" prlimit --as="$(numfmt --from=iec "${mem:-2G}")" -- "$cc" "$@" > "$out" 2> "$work/err" < "$in"
  local rc=$?
  local msg
  msg="$(cat "$work/err")"
  [ "$out" = "$work/out" ] && msg="$(cat "$work/out") $msg"
  local why=""
  if [ "$rc" -ge 124 ]; then
    why="exit $rc (signal, time or memory cap)"
  elif ! [[ "|$want|" == *"|$rc|"* ]]; then
    why="exit $rc, expected $want"
  elif ! grep -qF -- "$text" <<< "$msg"; then
    why="message does not contain: $text"
  fi
  if [ -n "$why" ]; then
    failures=$((failures + 1))
    echo "FAIL: contactcert $*: $why"
    echo "  output: $(head -c 400 <<< "$msg")"
  fi
}
# check WANT TEXT ARGS...: as run, with no input, stdout and stderr searched for TEXT.
check() {
  local want=$1 text=$2
  shift 2
  run "$want" "$text" /dev/null "$work/out" "$@"
}
# summary NAME: prints the count and fails if a case failed.
summary() {
  echo "$1: $((cases - failures)) of $cases cases passed"
  [ "$failures" -eq 0 ]
}
