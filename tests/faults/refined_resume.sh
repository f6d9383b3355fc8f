# A run on a locally refined grid stopped by 'Maximum steps' and resumed from its checkpoint ends
# with the statistics (but the wall time) and material points of the run that was not
# interrupted, bit for bit, in two cases:
# - prm/constrained_swelling_refined.prm (a fixed box, whose points were split at the start), 18
#   steps: the refined grid is rebuilt from the scene on resume and the split points come from the
#   checkpoint;
# - prm/swelling_sphere.prm with 'Background grid/Refinement band = 0.15' (a band that follows the
#   surface), 13 of 18 steps: the marking changes at steps 13, 15, 16, 17 and 18 and points are
#   split at 17; on resume the band is marked from the resumed points, and Newton starts step 14
#   from the mu coefficients of step 13 ('Initial chemical potential = grid'), which are kept for
#   the marking they were stored with.
# (The free-swelling scene given is not used.)
source "$(dirname "$0")/common.sh"
fail=0
# without_wall FILE: statistics.csv less its wall_time column.
without_wall() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "wall_time") w = i }
           { s = ""; for (i = 1; i <= NF; ++i) if (i != w) s = s $i ","; print s }' "$1"
}
same_data() { cmp -s <(grep -v '^#This file was generated' "$1") <(grep -v '^#This file was generated' "$2"); }

# resume_matches_whole NAME SCENE STEPS OPTIONS...: the run stopped after STEPS steps and resumed
# against the uninterrupted run, in NAME/.
resume_matches_whole() {
  local name=$1 file=$2 steps=$3
  shift 3
  local options=("$@" --set "Output/Write particles=true" --set "Output/Interval steps=0"
                 --set "Output/Interval time=0")
  mkdir -p "$name" && pushd "$name" >/dev/null || return
  "$gelmpm" "$file" "${options[@]}" --set "Output/Directory=whole" >whole.log 2>&1
  check $? "$name: the uninterrupted run failed: $(tail -n 3 whole.log)"
  "$gelmpm" "$file" "${options[@]}" --set "Output/Directory=results" \
    --set "Checkpoint/Interval steps=1" --set "Time stepping/Maximum steps=$steps" >first.log 2>&1
  grep -q "checkpoint at step $steps" first.log
  check $? "$name: the first part wrote no checkpoint at step $steps: $(tail -n 3 first.log)"
  "$gelmpm" "$file" "${options[@]}" --set "Output/Directory=results" \
    --set "Checkpoint/Interval steps=1" --resume >resumed.log 2>&1
  check $? "$name: the resumed run failed: $(tail -n 3 resumed.log)"
  grep -q "resumed from the checkpoint at step $steps" resumed.log
  check $? "$name: the log does not say that the run resumed at step $steps"
  check_statistics
  [[ $(wc -l <whole/statistics.csv) -gt $((steps + 1)) ]]
  check $? "$name: the uninterrupted run has not more than $steps steps"
  cmp -s <(without_wall whole/statistics.csv) <(without_wall results/statistics.csv)
  check $? "$name: statistics.csv differs from the uninterrupted run's"
  local last
  last=$(ls whole/particles-*.vtu | tail -n 1)
  same_data "$last" "results/$(basename "$last")"
  check $? "$name: the last material points ($(basename "$last")) differ from the uninterrupted run's"
  popd >/dev/null || return
}

prm="$(cd "$(dirname "$0")/../../prm" && pwd)"
resume_matches_whole box "$prm/constrained_swelling_refined.prm" 18 \
  --set "Time stepping/End time=0.01"
resume_matches_whole band "$prm/swelling_sphere.prm" 13 \
  --set "Time stepping/End time=1.5" --set "Time stepping/Stop at times=" \
  --set "Background grid/Refinement band=0.15" --set "Newton/Initial chemical potential=grid"
finish
