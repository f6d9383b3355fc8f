# §4.1 refined where the chemical potential's front is (prm/constrained_swelling_front.prm,
# 'Background grid/Refinement mu range = 0.03'), 10 fixed steps of 0.01 tau_d with 4 points per
# cell, on two ranks against one: the spread of mu per cell is reduced over the ranks, the
# hierarchies rebuilt alike on every rank, the points split where the front arrives (8,672 ->
# 9,456 by step 2) and merged back where it has passed (8,784 at step 7, 5,616 at step 8). At
# step 7 some families of split points lie on both ranks; they are merged from what each rank
# holds (merge_points_to_leaves()): before, they waited for a common rank and the two-rank run
# kept 12 points more at steps 7-9. The unknowns, the number of points and every statistic agree.
source "$(dirname "$0")/common.sh"
fixed_steps 0.01 10
run_both "$source_dir/prm/constrained_swelling_front.prm" "${steps[@]}" \
  --set "Time stepping/Tolerance=0" --set "Output/Write particles=false" \
  --set "Material points/Points per cell=4"
compare_statistics
points() { statistic two/statistics.csv n_particles "$1"; }
[[ $(points 4) -gt $(points 2) && $(points 9) -lt $(points 4) && $(points 10) -lt $(points 9) ]]
check $? "points were split and then merged during the run on two ranks ($(points 2), $(points 4), $(points 9), $(points 10))"
finish
