# Sourced by the fault tests: the arguments, a scratch directory and checks of the output files.
set -u
gelmpm="$1"
scene="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail=0

check() { # check CONDITION-STATUS MESSAGE
  [[ $1 -eq 0 ]] || { echo "FAIL: $2"; fail=1; }
}

# Every row of results/statistics.csv has as many fields as the header and ends with a newline.
check_statistics() {
  local file=results/statistics.csv
  [[ -s $file ]] || { echo "FAIL: $file is missing or empty"; fail=1; return; }
  [[ $(tail -c 1 "$file" | od -An -c | tr -d ' ') == '\n' ]] ||
    { echo "FAIL: $file ends inside a row"; fail=1; }
  local widths
  widths=$(awk -F, '{print NF}' "$file" | sort -u | wc -l)
  [[ $widths -eq 1 ]] || { echo "FAIL: $file has rows of different widths"; fail=1; }
}

# Every .vtu that results/particles.pvd lists exists and is complete; no temporary file is left.
check_series() {
  local pvd=results/particles.pvd
  [[ -s $pvd ]] || { echo "FAIL: $pvd is missing"; fail=1; return; }
  grep -q '</VTKFile>' "$pvd" || { echo "FAIL: $pvd is torn"; fail=1; }
  for f in $(sed -n 's/.*file="\([^"]*\)".*/\1/p' "$pvd"); do
    [[ -f results/$f ]] || { echo "FAIL: $pvd lists the missing $f"; fail=1; continue; }
    tail -c 200 "results/$f" | grep -q '</VTKFile>' || { echo "FAIL: $f is torn"; fail=1; }
  done
  ! ls results/*.tmp >/dev/null 2>&1 || { echo "FAIL: temporary files left: $(ls results/*.tmp)"; fail=1; }
}

finish() {
  [[ $fail -eq 0 ]] && echo "PASS"
  exit $fail
}
