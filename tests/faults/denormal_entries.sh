# A number that a double cannot carry (a denormal such as 1e-320, one that underflows to 0, one
# beyond the largest double) in any numeric entry, alone, in a list or in step caps, given in the
# file or by --set, with or without --check: one error line naming the entry, exit status 2,
# nothing written. Every entry is tried with --check; a run without it reads the scene the same
# way (check_numbers_representable() when the scene is read, before anything is written), so two
# of them and the number in the file are tried without --check as well (each try starts gelmpm,
# about 0.4 s of CPU: every entry both ways took 22 tries).
source "$(dirname "$0")/common.sh"

# refused ENTRY VALUE [OPTIONS...]: the run with --set "ENTRY=VALUE" must be refused.
refused() {
  local entry=$1 value=$2
  shift 2
  "$gelmpm" "$scene" "$@" --set "$entry=$value" >stdout 2>stderr
  local status=$?
  echo "$entry=$value $*: exit status $status: $(cat stderr)"
  check $((status != 2)) "$entry=$value $*: exit status $status, expected 2"
  grep -qF -- "error: '$entry' is " stderr
  check $? "$entry=$value $*: stderr does not name the entry"
  grep -qF -- "smallest normal double" stderr || grep -qF -- "largest double" stderr
  check $? "$entry=$value $*: stderr does not say what is wrong with the number"
  [[ $(grep -c . stderr) -eq 1 ]]
  check $? "$entry=$value $*: expected exactly one error line"
  [[ -z $(find . -mindepth 1 -not -name stdout -not -name stderr -not -name scene.prm) ]]
  check $? "$entry=$value $*: output was written: $(ls)"
}

refused "Time stepping/Initial step" 1e-320 --check
refused "Time stepping/End time" 1e-320 --check
refused "Time stepping/Tolerance" 4.9e-324 --check
refused "Time stepping/Step caps" "1: 0.05, 20: 1e-320" --check
refused "Material/Shear modulus" 1e-400 --check
refused "Nitsche/Displacement penalty" 1e-320 --check
refused "Checkpoint/Interval minutes" 1e-320 --check
refused "Stability/Bisection tolerance" 1e-320 --check
refused "Stability/Perturbation direction" "1, -1e-320" --check
refused "Boundary conditions/exposed/Chemical potential value/Function expression" 1e999 --check
# Without --check: a run that would start.
refused "Time stepping/Step caps" "1: 0.05, 20: 1e-320"
refused "Boundary conditions/exposed/Chemical potential value/Function expression" 1e999

# In the scene file itself, not by --set.
sed 's/set Initial step          = 1e-3/set Initial step          = 2e-310/' "$scene" >scene.prm
"$gelmpm" scene.prm >stdout 2>stderr
status=$?
echo "in the file: exit status $status: $(cat stderr)"
check $((status != 2)) "in the file: exit status $status, expected 2"
grep -qF -- "error: 'Time stepping/Initial step' is 2e-310" stderr
check $? "in the file: stderr does not name the entry"

# A small number that a double carries is no error of this kind.
"$gelmpm" "$scene" --check --set "Stability/Perturbation direction=1, 1e-300" >stdout 2>stderr
check $? "1e-300 in a list is refused: $(cat stderr)"
finish
