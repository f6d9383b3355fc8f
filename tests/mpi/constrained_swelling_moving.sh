# §4.1 at the paper setting (prm/constrained_swelling.prm) to 3 tau_d, on two ranks against one:
# long enough for the body to swell across the partition, so that surface points move to the
# other rank and join blocks it did not write before (the pattern's writable rows change), and
# for the grid to be partitioned anew.
source "$(dirname "$0")/common.sh"
run_both "$source_dir/prm/constrained_swelling.prm" --set "Time stepping/End time=3" \
  --set "Output/Write particles=false" --set "Output/Test mode=true"
compare_statistics
finish
