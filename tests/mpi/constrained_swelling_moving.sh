# §4.1 (prm/constrained_swelling.prm) to 3 tau_d, on two ranks against one: long enough for the
# body to swell across the partition (Delta h/h_0 = 0.47), so that surface points move to the
# other rank and join blocks it did not write before (the pattern's writable rows change), and
# for the grid to be partitioned anew (the two-rank log must say so: 3 times measured). Steps of
# at most 0.05 tau_d (85 steps; the scene's caps give 259) and 3 x 3 points per cell (the scene's
# 6 x 6): the same motion across the partition at a third of the CPU time.
source "$(dirname "$0")/common.sh"
run_both "$source_dir/prm/constrained_swelling.prm" --set "Time stepping/End time=3" \
  --set "Time stepping/Step caps=5: 0.05" --set "Material points/Points per cell=3" \
  --set "Output/Write particles=false"
compare_statistics
grep -q "partitioned anew [1-9][0-9]* times" two.log
check $? "the grid was partitioned anew on two ranks ($(grep -o 'partitioned anew [0-9]* times' two.log))"
finish
