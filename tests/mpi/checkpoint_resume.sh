# Checkpoint and restart on two ranks: a run killed (SIGKILL to both ranks) at two moments and
# stopped once by SIGTERM, each time resumed with --resume on two ranks, and finished after a
# last resume on one rank (a checkpoint is not tied to its number of ranks), ends with the
# statistics of the uninterrupted run on two ranks (gelmpm-compare-statistics: 1e-10) and with
# as many material points.
source "$(dirname "$0")/common.sh"
scene="$source_dir/tests/simulator/free_swelling_scene.prm"
options=(--set "Time stepping/End time=20" --set "Output/Write particles=true"
         --set "Output/Interval steps=5" --set "Output/Directory=results")

"$mpiexec" -n 2 --oversubscribe "$gelmpm" "$scene" "${options[@]}" \
  --set "Output/Directory=whole" >whole.log 2>&1
check $? "the uninterrupted run on two ranks failed: $(tail -3 whole.log)"

# run_until SIGNAL STEPS [ARGS...]: start the run on two ranks with a checkpoint after every
# step, wait until statistics.csv has STEPS more rows and a random part of a second more, and
# send SIGNAL to both ranks (the children of the launcher).
run_until() {
  local signal=$1 rows=$(($2 + $(cat results/statistics.csv 2>/dev/null | wc -l)))
  shift 2
  "$mpiexec" -n 2 --oversubscribe "$gelmpm" "$scene" "${options[@]}" \
    --set "Checkpoint/Interval steps=1" "$@" >>killed.log 2>&1 &
  local pid=$!
  for _ in $(seq 1200); do
    [[ $(cat results/statistics.csv 2>/dev/null | wc -l) -ge $rows ]] && break
    sleep 0.05
  done
  sleep "0.$((RANDOM % 4))"
  pkill -"$signal" -P $pid
  wait $pid 2>/dev/null
  echo "SIG$signal after $(($(wc -l <results/statistics.csv) - 1)) steps"
}
run_until KILL 15
run_until KILL 15 --resume
run_until TERM 10 --resume
"$gelmpm" "$scene" "${options[@]}" --set "Checkpoint/Interval steps=1" --resume >>killed.log 2>&1
check $? "the last resumed run (one rank) failed: $(tail -3 killed.log)"
[[ $(grep -c "resumed from the checkpoint at step" killed.log) -eq 3 ]]
check $? "the log does not say three times that the run resumed"

"$compare" whole/statistics.csv results/statistics.csv
check $? "statistics.csv differs from the uninterrupted run's"
finish
