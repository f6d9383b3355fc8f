# §4.1 refined where the chemical potential's front is (prm/constrained_swelling_front.prm,
# 'Background grid/Refinement mu range = 0.03'), 20 fixed steps of 0.01 tau_d, on two ranks against
# one: the spread of mu per cell is reduced over the ranks, the hierarchies rebuilt alike on every
# rank, the points split where the front arrives (19,152 -> 20,904 by step 4) and merged back
# where it has passed (12,264 by step 10) on the rank that holds them. The unknowns, the number of
# points and every statistic agree.
source "$(dirname "$0")/common.sh"
fixed_steps 0.01 20
run_both "$source_dir/prm/constrained_swelling_front.prm" "${steps[@]}" \
  --set "Time stepping/Tolerance=0" --set "Output/Write particles=false"
compare_statistics
points() { statistic two/statistics.csv n_particles "$1"; }
[[ $(points 6) -gt $(points 2) && $(points 22) -lt $(points 6) ]]
check $? "points were split and then merged during the run on two ranks"
finish
