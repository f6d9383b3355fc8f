# One step of 1000 tau_d on the free-swelling square, without caps: Newton converged (residual
# 1e-15) to a wrong state, J_mean 8.805 (range 8.38-9.44) against the 9.432 of normal steps, with
# exit status 0 and not a word; its points moved up to 9.9 cells. The default 'Largest increment'
# (5 cells, on the steps that no error estimate judges) now retakes such a step shorter, the log
# says why, and the run reaches the equilibrium of normal steps: J_mean 9.4309 in 17 steps, and
# with 'Displacement tolerance' (which cannot judge a first step) 9.4312 in 40. The ten digits of
# J_mean are not compared, only the 0.1 % that tells the equilibrium from the wrong state.
source "$(dirname "$0")/common.sh"
one_step() { # name, extra arguments...
  local name=$1
  shift
  "$gelmpm" "$scene" --set "Time stepping/Initial step=1000" --set "Time stepping/End time=1000" \
    --set "Time stepping/Step caps=" --set "Output/Directory=$name" "$@" >"$name.out" 2>"$name.err"
  local status=$?
  echo "$name: exit status $status"; cat "$name.err"
  check $status "$name: the run should reach its end"
  grep -q "failed (a material point moves .* cells, more than 'Time stepping/Largest increment' = 5)" \
    "$name.out"
  check $? "$name: the log does not say that the step was retaken for its motion"
  local j_mean
  j_mean=$(sed -n 's/^  final J_mean = //p' "$name.out")
  echo "$name: J_mean $j_mean (normal steps: 9.432)"
  awk -v j="$j_mean" 'BEGIN { exit !(j > 9.432 * 0.999 && j < 9.432 * 1.001) }'
  check $? "$name: J_mean $j_mean is not the equilibrium 9.432 (to 0.1 %)"
}
one_step plain
one_step estimated --set "Time stepping/Displacement tolerance=0.01"
finish
