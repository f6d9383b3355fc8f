# Locally refined grids in 3D ('Background grid/Refinement region', truncated hierarchical
# B-splines with the extension at every level, doc/architecture.md "A refined scene").
#
# The cube: an eighth of a cube of side 0.375 swelling freely (prm/free_swelling_cube.prm's
# scene made small), on a grid of h = 0.125 refined once everywhere ('Refinement region = -1')
# against the uniform grid of h = 0.0625 over the same box. The two spaces are the same, and
# the split points are the fine grid's (a volume point's 8 children at the centres of its
# sub-cell's eighths, a face element's 4 children at the centres of its quarters), so:
# - the piece table (points, areas, normals; the one 'gelmpm --check' prints, read here from the
#   runs' logs, which print it after the same set-up) is the uniform grid's;
# - 7 steps to 0.01 tau_d give the uniform grid's statistics (steps, unknowns, points, Newton
#   iterations within one, every other column to 1e-6 of its largest value).
#
# The sphere: prm/free_swelling_sphere_3d.prm (a level-set body, an eighth of a ball of
# radius 0.5 cut by three planes of symmetry) with 3 points per cell and a band 0.35 <= r <= 0.65
# refined once: the level boundary crosses the body and the three planes. Checked against the
# uniform grid of the same base cells:
# - every surface element of the sphere lies in the band and is split into 4 over its facet (4
#   times the points), the planes' elements in the band too (more points); every piece keeps
#   its area and normals to the digits printed (the children's N_0 A_0 are the parent's / 4,
#   exactly), and the body keeps its volume (the volume points' children take 1/8 each);
# - its first step runs (Newton converges on the hierarchical spaces with the extension at both
#   levels, the level boundary crossing the sphere and the planes). Over 0.1 tau_d the band's
#   delta_h_over_h0 is within 3 % of the uniform grid's, but with 6,168 displacement unknowns and
#   51,619 volume points against 915 and 7,232 it takes 43 s instead of 9 s: too long here.
# The piece tables come from the runs' logs rather than from separate 'gelmpm --check' runs, which
# set the same scenes up once more (four runs of 1-2 s each, 40 % of the test's time).
set -u
gelmpm="$1"
compare="$2"
source_dir="$3"
source "$(dirname "${BASH_SOURCE[0]}")/../scratch.sh"

# --- the cube refined everywhere against the uniform fine grid -------------------------------
cube=("$source_dir/prm/free_swelling_cube.prm" --set "Geometry/Boxes=0, 0, 0 : 0.375, 0.375, 0.375"
      --set "Background grid/Lower corner=-0.25, -0.25, -0.25"
      --set "Background grid/Upper corner=1, 1, 1"
      --set "Time stepping/Characteristic length=0.375" --set "Time stepping/End time=0.01"
      --set "Time stepping/Stop at times=" --set "Output/Write particles=false")
# pieces LOG: the piece table a run's log prints (its heading and one row per piece).
pieces() { awk '/boundary pieces/ { on = 1; print; next } on && !/^    / { exit } on' "$1"; }

"$gelmpm" "${cube[@]}" --set "Background grid/Cells=20, 20, 20" \
  --set "Output/Directory=cube_uniform" > cube_uniform.log 2>&1
check $? "cube: the uniform run finished ($(grep -m1 reached cube_uniform.log))"
"$gelmpm" "${cube[@]}" --set "Background grid/Cells=10, 10, 10" \
  --set "Background grid/Refinement region=-1" --set "Output/Directory=cube_refined" \
  > cube_refined.log 2>&1
check $? "cube: the refined run finished ($(grep -m1 reached cube_refined.log))"
pieces cube_uniform.log > cube_uniform.pieces
pieces cube_refined.log > cube_refined.pieces
[[ $(wc -l < cube_uniform.pieces) -eq 5 ]] && diff cube_uniform.pieces cube_refined.pieces
check $? "cube: the refined grid's piece table is the uniform fine grid's"
[[ "$(grep 'material points' cube_uniform.log)" == "$(grep 'material points' cube_refined.log)" ]]
check $? "cube: the same points and volume ($(grep 'material points' cube_refined.log))"
"$compare" --relative 1e-6 --newton 1 \
  --ignore residual_u,residual_mu,solvent_imbalance,n_active_cells,wall_time \
  cube_uniform/statistics.csv cube_refined/statistics.csv
check $? "cube: the refined grid's statistics are the uniform fine grid's"

# --- the sphere with a refined band -------------------------------------------------------------
sphere=("$source_dir/prm/free_swelling_sphere_3d.prm" --set "Material points/Points per cell=3"
        --set "Output/Write particles=false" --set "Time stepping/End time=0.0001"
        --set "Time stepping/Stop at times=")
band="abs(sqrt(x^2 + y^2 + z^2) - 0.5) - 0.15"
"$gelmpm" "${sphere[@]}" --set "Output/Directory=sphere_uniform" > sphere_uniform.log 2>&1
check $? "sphere: the uniform run finished ($(grep -m1 reached sphere_uniform.log))"
"$gelmpm" "${sphere[@]}" --set "Background grid/Refinement region=$band" \
  --set "Output/Directory=sphere_refined" > sphere_refined.log 2>&1
check $? "sphere: the refined run finished ($(grep -m1 reached sphere_refined.log))"
pieces sphere_uniform.log > sphere_uniform.pieces
pieces sphere_refined.log > sphere_refined.pieces
cat sphere_refined.pieces

# Piece rows: name, points, area, then the low and high end of nx, ny, nz.
row() { awk -v p="$1" '$1 == p { print $2, $5, $7, $9, $11, $13, $15, $17 }' "$2"; }
for piece in xplane yplane zplane sphere; do
  read -r n_u rest_u <<< "$(row $piece sphere_uniform.pieces)"
  read -r n_r rest_r <<< "$(row $piece sphere_refined.pieces)"
  [[ -n "${rest_u:-}" && "$rest_u" == "$rest_r" ]]
  check $? "sphere: piece $piece keeps its area and normals ($rest_r)"
  if [[ $piece == sphere ]]; then
    [[ -n "${n_u:-}" && "$n_r" -eq $((4 * n_u)) ]]
    check $? "sphere: piece sphere has 4 times the points ($n_r against $n_u)"
  else
    [[ -n "${n_u:-}" && "$n_r" -gt "$n_u" ]]
    check $? "sphere: piece $piece has more points ($n_r against $n_u)"
  fi
done

volume() { sed -n 's/.*body volume \([0-9.e+-]*\).*/\1/p' "$1"; }
[[ -n "$(volume sphere_uniform.log)" && "$(volume sphere_uniform.log)" == "$(volume sphere_refined.log)" ]]
check $? "sphere: the same body volume ($(volume sphere_refined.log))"
awk -F, 'NR > 1 { t = $3; n = $5 } END { exit !(t == 0.0001 && n >= 1 && n <= 5) }' \
  sphere_refined/statistics.csv
check $? "sphere: the refined run's step converged ($(tail -1 sphere_refined/statistics.csv | cut -d, -f3,5))"
exit $fail
