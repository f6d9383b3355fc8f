# §4.1 as a prism in 3D against the same layer in 2D: the solution is one-dimensional, so the 3D
# run (rollers on four sides) must give the 2D run's (rollers on two) thickness at the same step
# times. A small version of prm/constrained_swelling_3d.prm: h = 0.05, a 0.3-wide prism (three mu
# cells), 3 points per cell and direction, 12 steps to 0.02 tau_d under 'Time stepping/Tolerance'.
# Checked:
# - the same steps, at times equal to 1e-8 relative, Newton iterations within one (modified
#   Newton's reuse decisions see residuals at round-off), delta_h_over_h0 to 1e-6 of its largest
#   value (measured 1e-7: the Newton tolerance carried over the steps; the full scene agrees to
#   6e-10 Δh_eq, the ten digits written);
# - the 3D tangent has the signature of a stable state at every step, (n_dofs_u, n_dofs_mu, 0)
#   (the inertia of the LDL^T factorisation, doc/method.md), and so has the 2D one;
# - the prism's surface points: 4 sides + top + bottom of 0.3 x 0.3 x 1 in total area.
set -u
gelmpm="$1"
compare="$2"
source_dir="$3"
source "$(dirname "${BASH_SOURCE[0]}")/../scratch.sh"

common=(--set "Time stepping/End time=0.02" --set "Time stepping/Tolerance=1e-2"
        --set "Time stepping/Growth factor=2" --set "Time stepping/Step caps="
        --set "Time stepping/Stop at times=" --set "Material points/Points per cell=3"
        --set "Output/Write particles=false" --set "Stability/Inertia=true")
"$gelmpm" "${common[@]}" --set "Output/Directory=three" \
  --set "Background grid/Upper corner=0.5, 0.5, 1.5" --set "Background grid/Cells=10, 10, 30" \
  --set "Geometry/Boxes=0, 0, 0 : 0.3, 0.3, 1" "$source_dir/prm/constrained_swelling_3d.prm" \
  > three.log 2>&1
check $? "the 3D run finished ($(tail -1 three.log))"
"$gelmpm" "${common[@]}" --set "Output/Directory=two" \
  --set "Background grid/Upper corner=0.5, 1.5" --set "Background grid/Cells=10, 30" \
  --set "Geometry/Boxes=0, 0 : 0.3, 1" "$source_dir/prm/constrained_swelling.prm" > two.log 2>&1
check $? "the 2D run finished ($(tail -1 two.log))"

"$compare" --relative 1e-6 --newton 1 \
  --ignore residual_u,residual_mu,n_dofs_u,n_dofs_mu,n_active_cells,n_particles,n_pos,n_neg,n_zero,time,t_over_tau_d,dt,wall_time \
  two/statistics.csv three/statistics.csv
check $? "2D and 3D statistics agree (steps, Newton iterations within 1, delta_h_over_h0 to 1e-6)"
# Step times: equal but for the error estimate's round-off.
paste -d, <(cut -d, -f3 two/statistics.csv) <(cut -d, -f3 three/statistics.csv) |
  awk -F, 'NR > 1 { d = $1 - $2; if (d < 0) d = -d; if (d > 1e-8 * $1) bad = 1 } END { exit bad }'
check $? "2D and 3D step times equal to 1e-8 relative"

for d in two three; do
  # Columns by name: a stable state has n_pos = n_dofs_u, n_neg = n_dofs_mu, n_zero = 0.
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
           $c["n_dofs_u"] != "" { ++rows; if ($c["n_pos"] != $c["n_dofs_u"] || $c["n_neg"] != $c["n_dofs_mu"] || $c["n_zero"] != 0) bad = 1 }
           END { exit (bad || rows < 5) }' "$d/statistics.csv"
  check $? "$d: signature (n_dofs_u, n_dofs_mu, 0) at every step"
done

grep -q "material points: 19440 volume" three.log
check $? "3D: 6 x 6 x 20 cells of 27 volume points ($(grep 'material points' three.log))"
exit $fail
