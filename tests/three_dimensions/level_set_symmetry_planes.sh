# A 3D body from a level set with three planes of symmetry (prm/free_swelling_sphere_3d.prm: an
# eighth of a ball of radius R = 0.5, max(sqrt(x^2 + y^2 + z^2) - R, max(-x, max(-y, -z)))), cut
# into pieces by selectors on the normal alone, as a box would be: 'nx < -0.99', 'ny < -0.99',
# 'nz < -0.99' and the rest. The surface points where a plane meets the sphere must get the
# normal of their face (doc/material_points.md, "Surface points in 3D"), so that, from the piece
# table of 'gelmpm --check':
# - each plane's piece has the area of a quarter disk, pi R^2 / 4, within 0.5% (0.07% measured on
#   the scene's grid of h = 0.0625, 0.12% on h = 0.05), and normals within 0.05 of its axis (on
#   h = 0.05, 4 of 732 points on the rim kept a tilt of up to 0.044: their cube held a sliver of the
#   sphere that crosses none of its edges; on h = 0.0625 the largest tilt is 0.007);
# - the sphere's piece has the area of an eighth of the sphere, pi R^2 / 2, within 0.5% (0.01%
#   measured), and no normal component below -1e-3 (before the split, the edges' blended normals
#   reached -0.965, the planes' pieces missed 12% of their area and the sphere's had 11% too
#   much);
# - no surface point is left without a piece.
set -u
gelmpm="$1"
source_dir="$3"
source "$(dirname "${BASH_SOURCE[0]}")/../scratch.sh"

"$gelmpm" --check "$source_dir/prm/free_swelling_sphere_3d.prm" > check.log 2>&1
check $? "the scene is valid ($(tail -1 check.log))"
cat check.log

# One row per piece: name, points, area, then the low and high end of nx, ny, nz.
row() { awk -v p="$1" '$1 == p { print $5, $7, $9, $11, $13, $15, $17 }' check.log; }
for plane in xplane:1 yplane:2 zplane:3; do
  name=${plane%%:*}
  axis=${plane##*:}
  read -r area lo_x hi_x lo_y hi_y lo_z hi_z <<< "$(row "$name")"
  [[ -n ${hi_z:-} ]]
  check $? "$name: a row in the piece table"
  awk -v a="$area" 'BEGIN { q = 3.14159265358979 * 0.25 / 4; exit !(a > 0.995 * q && a < 1.005 * q) }'
  check $? "$name: area $area within 0.5% of pi R^2/4 = 0.19635"
  awk -v ax="$axis" -v lx="$lo_x" -v hx="$hi_x" -v ly="$lo_y" -v hy="$hi_y" -v lz="$lo_z" -v hz="$hi_z" '
    function abs(v) { return v < 0 ? -v : v }
    BEGIN {
      lo[1] = lx; hi[1] = hx; lo[2] = ly; hi[2] = hy; lo[3] = lz; hi[3] = hz
      for (d = 1; d <= 3; ++d) {
        if (d == ax) { if (lo[d] > -0.999 || hi[d] > -0.999) exit 1 }
        else if (abs(lo[d]) > 0.05 || abs(hi[d]) > 0.05) exit 1
      }
    }'
  check $? "$name: every normal within 0.05 of -e_$axis (its component along e_$axis at most -0.999)"
done
read -r area lo_x hi_x lo_y hi_y lo_z hi_z <<< "$(row sphere)"
[[ -n ${hi_z:-} ]]
check $? "sphere: a row in the piece table"
awk -v a="$area" 'BEGIN { q = 3.14159265358979 * 0.25 / 2; exit !(a > 0.995 * q && a < 1.005 * q) }'
check $? "sphere: area $area within 0.5% of pi R^2/2 = 0.39270"
awk -v x="$lo_x" -v y="$lo_y" -v z="$lo_z" 'BEGIN { exit !(x > -1e-3 && y > -1e-3 && z > -1e-3) }'
check $? "sphere: no normal component below -1e-3 (lowest $lo_x, $lo_y, $lo_z)"
! grep -q "(none)" check.log
check $? "every surface point belongs to a piece"
exit $fail
