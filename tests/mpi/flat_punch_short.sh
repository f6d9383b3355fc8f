# The flat punch (prm/flat_punch.prm, Q2-Q2SD on 30 x 30 cells) through its ramp to 0.01 tau_d,
# on two ranks against one: the statistics with the observables that gather over all points
# (J range, Dirichlet errors, mu oscillation along rows of points), and the points of the last
# output.
source "$(dirname "$0")/common.sh"
run_both "$source_dir/prm/flat_punch.prm" --set "Background grid/Cells=30, 30" \
  --set "Time stepping/End time=0.01" --set "Output/Interval steps=10" \
  --set "Output/Test mode=true" --set "Observables/Volume ratio range=true" \
  --set "Observables/Boundary condition error=true" \
  --set "Observables/Chemical potential oscillation=true"
compare_statistics
check_pieces
finish
