# A run with a checkpoint after every step, killed with SIGKILL at two moments and stopped by
# SIGTERM once (which writes a checkpoint and an output that the uninterrupted run does not
# have), each time resumed with --resume, ends with the same statistics.csv, .pvd series and
# material points (the .vtu data) as the run that was not interrupted: bit for bit.
source "$(dirname "$0")/common.sh"
options=(--set "Time stepping/End time=20" --set "Output/Write particles=true"
         --set "Output/Interval steps=5")

"$gelmpm" "$scene" "${options[@]}" --set "Output/Directory=whole" >whole.log 2>&1
check $? "the uninterrupted run failed"

# run_until SIGNAL STEPS [ARGS...]: start the run with checkpoints, wait until statistics.csv has
# STEPS more rows, wait a random part of a second more (so that the kill falls anywhere in a step,
# also into the writing of a checkpoint or a .vtu), and send it SIGNAL.
run_until() {
  local signal=$1 rows=$(($2 + $(cat results/statistics.csv 2>/dev/null | wc -l)))
  shift 2
  "$gelmpm" "$scene" "${options[@]}" --set "Checkpoint/Interval steps=1" "$@" >>killed.log 2>&1 &
  local pid=$!
  for _ in $(seq 600); do
    [[ $(cat results/statistics.csv 2>/dev/null | wc -l) -ge $rows ]] && break
    # A run that has ended (it reached the end time first) gives no more rows.
    kill -0 $pid 2>/dev/null || break
    sleep 0.05
  done
  sleep "0.$((RANDOM % 4))"
  kill -"$signal" $pid
  wait $pid 2>/dev/null
  echo "SIG$signal after $(($(wc -l <results/statistics.csv) - 1)) steps"
}
run_until KILL 15
run_until KILL 15 --resume
run_until TERM 10 --resume
"$gelmpm" "$scene" "${options[@]}" --set "Checkpoint/Interval steps=1" --resume >>killed.log 2>&1
check $? "the resumed run failed"
grep -q "resumed from the checkpoint at step" killed.log
check $? "the log does not say that the run resumed"

cmp whole/statistics.csv results/statistics.csv
check $? "statistics.csv differs from the uninterrupted run's"
# deal.II stamps each .vtu and .pvd with the time it was written: compare the rest.
same_data() { cmp -s <(grep -v '^#This file was generated' "$1") <(grep -v '^#This file was generated' "$2"); }
same_data whole/particles.pvd results/particles.pvd
check $? "particles.pvd differs from the uninterrupted run's"
[[ $(cd whole && ls particles-*.vtu) == $(cd results && ls particles-*.vtu) ]]
check $? "the .vtu files are not those of the uninterrupted run"
for f in whole/particles-*.vtu; do
  same_data "$f" "results/${f#whole/}"
  check $? "${f#whole/} differs from the uninterrupted run's"
done
check_statistics
check_series
finish
