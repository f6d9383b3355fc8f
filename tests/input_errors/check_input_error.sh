#!/usr/bin/env bash
# check_input_error.sh GELMPM CASE.prm: see CMakeLists.txt in this directory.
set -u
gelmpm="$1"
case_file="$2"
expect=$(sed -n '1s/^\xEF\xBB\xBF//; 1s/^# expect: //p' "$case_file")
args=$(sed -n 's/^# args: //p' "$case_file")
scene=$(sed -n 's/^# scene: //p' "$case_file")
setup=$(sed -n 's/^# setup: //p' "$case_file")
[[ -n "$scene" ]] || scene="$case_file"
[[ -n "$expect" ]] || { echo "FAIL: $case_file has no '# expect:' first line"; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
# A setup command prepares files the case needs (CASE is the case file); they are not output.
CASE="$case_file"
eval "$setup"
before=$(find . -mindepth 1 | sort)
eval "\"$gelmpm\" $args \"$scene\"" >stdout 2>stderr
status=$?

echo "exit status: $status"
echo "stderr:"; cut -c 1-2000 stderr
fail=0
[[ $status -eq 2 ]] || { echo "FAIL: exit status $status, expected 2"; fail=1; }
grep -qF -- "$expect" stderr || { echo "FAIL: stderr lacks '$expect'"; fail=1; }
[[ $(grep -c . stderr) -eq 1 ]] || { echo "FAIL: expected exactly one error line"; fail=1; }
[[ $(wc -L <stderr) -le 1000 ]] || { echo "FAIL: the error line is longer than 1000 characters"; fail=1; }
leftovers=$(comm -23 <(find . -mindepth 1 -not -name stdout -not -name stderr | sort) \
  <(echo "$before") | head -5)
[[ -z "$leftovers" ]] || { echo "FAIL: output was written: $leftovers"; fail=1; }
[[ $fail -eq 0 ]] && echo "PASS"
exit $fail
