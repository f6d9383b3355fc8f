# The axisymmetric swelling sphere (prm/swelling_sphere.prm) with a band that follows its surface
# ('Background grid/Refinement band = 0.15'), 20 fixed steps of 0.1 tau_d, on two ranks against
# one: the band is marked from the surface points of every rank, the hierarchies rebuilt alike on
# every rank and the points split where they lie (the marking changes from step 13 on, points are
# split at step 17). The unknowns, the number of points and every statistic agree.
source "$(dirname "$0")/common.sh"
fixed_steps 0.1 20
run_both "$source_dir/prm/swelling_sphere.prm" "${steps[@]}" --set "Time stepping/Tolerance=0" \
  --set "Background grid/Refinement band=0.15" --set "Output/Write particles=false"
compare_statistics
last=$(wc -l <two/statistics.csv)
[[ $(statistic two/statistics.csv n_particles "$last") -gt $(statistic two/statistics.csv n_particles 2) ]]
check $? "points were split during the run on two ranks"
finish
