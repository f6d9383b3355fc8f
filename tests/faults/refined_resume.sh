# A run on a locally refined grid (prm/constrained_swelling_refined.prm, whose points were split in
# the refined box at the start) stopped after 18 steps by 'Maximum steps' and resumed from its
# checkpoint ends with the statistics (but the wall time) and material points of the run that was
# not interrupted, bit for bit: the refined grid is rebuilt from the scene on resume and the split
# points come from the checkpoint. (The free-swelling scene given is not used.)
source "$(dirname "$0")/common.sh"
refined="$(dirname "$0")/../../prm/constrained_swelling_refined.prm"
options=(--set "Time stepping/End time=0.01" --set "Output/Write particles=true"
         --set "Output/Interval steps=0" --set "Output/Interval time=0")
fail=0
"$gelmpm" "$refined" "${options[@]}" --set "Output/Directory=whole" >whole.log 2>&1
check $? "the uninterrupted run failed: $(tail -n 3 whole.log)"
"$gelmpm" "$refined" "${options[@]}" --set "Output/Directory=results" \
  --set "Checkpoint/Interval steps=1" --set "Time stepping/Maximum steps=18" >first.log 2>&1
grep -q "checkpoint at step 18" first.log
check $? "the first part wrote no checkpoint at step 18: $(tail -n 3 first.log)"
"$gelmpm" "$refined" "${options[@]}" --set "Output/Directory=results" \
  --set "Checkpoint/Interval steps=1" --resume >resumed.log 2>&1
check $? "the resumed run failed: $(tail -n 3 resumed.log)"
grep -q "resumed from the checkpoint at step 18" resumed.log
check $? "the log does not say that the run resumed at step 18"
check_statistics
# without_wall FILE: statistics.csv less its wall_time column.
without_wall() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "wall_time") w = i }
           { s = ""; for (i = 1; i <= NF; ++i) if (i != w) s = s $i ","; print s }' "$1"
}
[[ $(wc -l <whole/statistics.csv) -gt 19 ]]
check $? "the uninterrupted run has not more than 18 steps"
cmp -s <(without_wall whole/statistics.csv) <(without_wall results/statistics.csv)
check $? "statistics.csv differs from the uninterrupted run's"
last=$(ls whole/particles-*.vtu | tail -n 1)
same_data() { cmp -s <(grep -v '^#This file was generated' "$1") <(grep -v '^#This file was generated' "$2"); }
same_data "$last" "results/$(basename "$last")"
check $? "the last material points ($(basename "$last")) differ from the uninterrupted run's"
finish
