# Sourced by the shell tests: runs the rest of the test in a scratch directory that goes away at
# the end, and check CONDITION-STATUS MESSAGE, which prints PASS or FAIL and remembers a failure
# (the test ends with "exit $fail").
set -u
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail=0

check() {
  if [[ $1 -eq 0 ]]; then echo "PASS: $2"; else echo "FAIL: $2"; fail=1; fi
}
