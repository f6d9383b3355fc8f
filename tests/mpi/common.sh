# Sourced by the tests that run on MPI ranks: arguments, scratch directory, runs, checks.
set -u
gelmpm="$1"
compare="$2"
mpiexec="$3"
source_dir="$4"
source "$(dirname "${BASH_SOURCE[0]}")/../scratch.sh"

# run_both SCENE [--set ...]: the scene into one/ on one rank and two/ on two ranks.
run_both() {
  local scene="$1"
  shift
  "$gelmpm" --set "Output/Directory=one" "$@" "$scene" > one.log 2>&1
  check $? "the run on one rank failed: $(tail -3 one.log)"
  # --oversubscribe: a machine may report fewer slots than its two cores.
  "$mpiexec" -n 2 --oversubscribe "$gelmpm" --set "Output/Directory=two" "$@" "$scene" \
    > two.log 2>&1
  check $? "the run on two ranks failed: $(tail -3 two.log)"
}

# run_with_mumps NAME SCENE [--set ...]: prm/SCENE into NAME/ (its log NAME.log) with MUMPS and no
# particle files; checked to finish.
run_with_mumps() {
  local name="$1" scene="$2"
  shift 2
  "$gelmpm" "$source_dir/prm/$scene" --set "Output/Directory=$name" \
    --set "Output/Write particles=false" --set "Linear solver/Solver=MUMPS" "$@" > "$name.log" 2>&1
  check $? "$name finished ($(grep -m1 'reached\|error\|failed\|onset' "$name.log"))"
}

# fixed_steps DT STEPS: the entries for STEPS steps of DT, in ${steps[@]}.
fixed_steps() {
  steps=(--set "Time stepping/Initial step=$1" --set "Time stepping/Growth factor=1"
         --set "Time stepping/Step caps=" --set "Time stepping/Stop at times="
         --set "Time stepping/End time=$(awk -v d="$1" -v n="$2" 'BEGIN { print d * n }')")
}

# statistic FILE COLUMN ROW: the value of COLUMN (by its header) in line ROW of FILE (1: the header).
statistic() {
  awk -F, -v name="$2" -v row="$3" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) c = i }
                                    NR == row { print $c }' "$1"
}

# The statistics agree (the tool prints its judgement per column).
compare_statistics() {
  "$compare" "$@" one/statistics.csv two/statistics.csv
  check $? "statistics.csv on two ranks differs from one rank"
}

# stability.csv and events.csv, where written, are identical but for the eigenvalue columns.
compare_stability() {
  for f in stability.csv events.csv; do
    [[ -f one/$f ]] || continue
    [[ -f two/$f ]] || { echo "FAIL: two/$f missing"; fail=1; continue; }
    local columns
    columns=$(head -1 "one/$f" | tr ',' '\n' | grep -nv '^eig_' | cut -d: -f1 | paste -sd,)
    cmp -s <(cut -d, -f"$columns" "one/$f") <(cut -d, -f"$columns" "two/$f")
    check $? "$f on two ranks differs from one rank"
  done
}

# The last particle output on two ranks has two pieces, each with points, together as many as
# on one rank: the points were distributed and none was lost.
check_pieces() {
  local last pieces total=0 expected
  last=$(ls two/particles-*.pvtu 2>/dev/null | tail -1)
  [[ -n $last ]] || { echo "FAIL: no .pvtu record on two ranks"; fail=1; return; }
  grep -q '</VTKFile>' "$last" || { echo "FAIL: $last is torn"; fail=1; }
  pieces=$(sed -n 's/.*Source="\([^"]*\)".*/\1/p' "$last")
  [[ $(echo "$pieces" | wc -l) -eq 2 ]] || { echo "FAIL: $last has not two pieces"; fail=1; }
  for p in $pieces; do
    local n
    n=$(grep -o 'NumberOfPoints="[0-9]*"' "two/$p" | head -1 | tr -dc 0-9)
    [[ ${n:-0} -gt 0 ]] || { echo "FAIL: piece $p holds no point"; fail=1; }
    total=$((total + ${n:-0}))
  done
  expected=$(grep -o 'NumberOfPoints="[0-9]*"' "$(ls one/particles-*.vtu | tail -1)" | head -1 |
    tr -dc 0-9)
  [[ $total -eq $expected ]] ||
    { echo "FAIL: the pieces hold $total points, the run on one rank $expected"; fail=1; }
  echo "points: $expected on one rank, $total in the pieces of two ranks"
}

finish() {
  [[ $fail -eq 0 ]] && echo "PASS"
  exit $fail
}
