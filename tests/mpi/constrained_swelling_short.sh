# §4.1 for 0.02 tau_d (tests/scenes/constrained_swelling_short.prm: inertia and the smallest
# Schur-complement eigenvalue after every step) on two ranks against one, with particle output.
source "$(dirname "$0")/common.sh"
run_both "$source_dir/tests/scenes/constrained_swelling_short.prm" \
  --set "Output/Write particles=true" --set "Output/Interval steps=5"
compare_statistics
compare_stability
check_pieces
finish
