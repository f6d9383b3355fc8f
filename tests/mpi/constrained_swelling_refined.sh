# §4.1 on its locally refined grid (prm/constrained_swelling_refined.prm, the top's cells halved
# once) for 0.01 tau_d on two ranks against one, with particle output: the hierarchical spaces
# are built alike on every rank from the scene's boxes, each rank splits and owns its points.
source "$(dirname "$0")/common.sh"
run_both "$source_dir/prm/constrained_swelling_refined.prm" \
  --set "Time stepping/End time=0.01" --set "Output/Write particles=true" \
  --set "Output/Interval steps=10"
compare_statistics
check_pieces
finish
