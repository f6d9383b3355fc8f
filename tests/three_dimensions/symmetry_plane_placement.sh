# Where a 3D level-set body's planes of symmetry lie in the background grid, and what the code
# says about it (doc/own_scenes.md, "Planes of symmetry"). The body is prm/free_swelling_sphere_3d.prm
# (an eighth of a ball, its planes x = y = z = 0 selected by 'nx < -0.99' etc.) on grids of its
# cell size h = 0.0625 placed differently. Each advice must be exact: the entries the message
# gives are applied and the scene is then valid, without the message.
# - The planes on the grid's sides (Lower corner 0): one error that names the three planes "on
#   the grid's side" (not the extension's "let the body end on the edge", which it already does)
#   and gives 'Lower corner = -0.1875, ...', 3 = q + 1 cells beyond each plane.
# - The planes within cells (Lower corner -0.2, 3.2 cells beyond): valid, with a note that names
#   them and gives the entries that put them on grid lines.
# - An eighth of a hollow ball (radii 0.5 and 1), whose inner wall at (0.5, 0, 0) has the normal
#   -e_x that 'nx < -0.99' selects: a note that the piece's points lie between x = 0 and about 0.5,
#   with a selector by position; with that selector, no note.
set -u
gelmpm="$1"
source_dir="$3"
source "$(dirname "${BASH_SOURCE[0]}")/../scratch.sh"
scene="$source_dir/prm/free_swelling_sphere_3d.prm"
# Three points per direction instead of the scene's five: where the planes lie does not depend on
# them, and the checks take a third of the time.
grid() {
  local lower=$1 upper
  upper=$(awk -v l="$lower" 'BEGIN { print l + 20 * 0.0625 }')
  printf '%s\n' --set "Background grid/Lower corner=$lower,$lower,$lower" \
    --set "Background grid/Upper corner=$upper,$upper,$upper" --set "Material points/Points per cell=3"
}
# The entries of a message, "'Lower corner = a, b, c', 'Upper corner = ...', 'Cells = ...'", as
# --set arguments, one per line.
entries_as_sets() {
  grep -o "'\(Lower corner\|Upper corner\|Cells\) = [-0-9., ]*'" | tr -d "'" |
    sed 's/ = /=/; s/^/Background grid\//'
}

# 1. On the grid's sides.
mapfile -t args < <(grid 0)
"$gelmpm" --check "$scene" "${args[@]}" > edge.log 2>&1
status=$?
cat edge.log
[[ $status -eq 2 ]]
check $? "planes on the grid's sides: exit status 2 (got $status)"
[[ $(grep -c "error" edge.log) -eq 1 ]]
check $? "one error line"
grep -q "'xplane' at x = 0 (on the grid's side), 'yplane' at y = 0 (on the grid's side), 'zplane' at z = 0 (on the grid's side)" edge.log
check $? "the error names the three planes on the grid's sides"
! grep -q "let the body end on" edge.log
check $? "the error does not advise ending the body on the edge"
grep -q "'Lower corner = -0.1875, -0.1875, -0.1875'" edge.log
check $? "the fix puts the grid's lower corner 3 cells beyond the planes"
mapfile -t fix < <(entries_as_sets < edge.log)
[[ ${#fix[@]} -eq 3 ]]
check $? "the fix gives Lower corner, Upper corner and Cells (${#fix[@]})"
sets=()
for entry in "${fix[@]}"; do sets+=(--set "$entry"); done
"$gelmpm" --check "$scene" "${sets[@]}" --set "Material points/Points per cell=3" > edge_fixed.log 2>&1
check $? "with the fix the scene is valid ($(tail -1 edge_fixed.log))"
! grep -q "note: the plane(s) held" edge_fixed.log
check $? "with the fix no note on the planes"

# 2. Within cells.
mapfile -t args < <(grid -0.2)
"$gelmpm" --check "$scene" "${args[@]}" > within.log 2>&1
check $? "planes within cells: valid ($(tail -1 within.log))"
grep "note: the plane(s) held" within.log
grep -q "'xplane' at x = 0 (3.2 cells from the grid's side)" within.log
check $? "a note names the planes within cells"
mapfile -t fix < <(grep "note: the plane(s) held" within.log | entries_as_sets)
sets=()
for entry in "${fix[@]}"; do sets+=(--set "$entry"); done
[[ ${#fix[@]} -eq 3 ]] && grep -q "'Lower corner = -0.1875, -0.1875, -0.1875'" within.log
check $? "the note gives the grid with the planes on grid lines"
"$gelmpm" --check "$scene" "${sets[@]}" --set "Material points/Points per cell=3" > within_fixed.log 2>&1
check $? "with the note's grid the scene is valid"
! grep -q "note: the plane(s) held" within_fixed.log
check $? "with the note's grid no note on the planes"

# 3. A curved wall with the plane's normal.
hollow=(--set "Geometry/Level set=max(max(sqrt(x^2 + y^2 + z^2) - 1, 0.5 - sqrt(x^2 + y^2 + z^2)), max(-x, max(-y, -z)))"
        --set "Background grid/Lower corner=-0.375, -0.375, -0.375"
        --set "Background grid/Upper corner=1.625, 1.625, 1.625"
        --set "Background grid/Cells=16, 16, 16"
        --set "Material points/Points per cell=3")
"$gelmpm" --check "$scene" "${hollow[@]}" > hollow.log 2>&1
check $? "the hollow ball: valid ($(tail -1 hollow.log))"
grep "note: piece" hollow.log
note=$(grep "note: piece 'xplane'" hollow.log)
[[ -n $note ]]
check $? "a note on the piece 'xplane' that is not one plane"
awk -v line="$note" 'BEGIN {
  if (!match(line, /between x = [-0-9.e]+ and [-0-9.e]+/)) exit 1
  split(substr(line, RSTART + 12, RLENGTH - 12), v, " and ")
  exit !(v[1] == 0 && v[2] > 0.4 && v[2] <= 0.5)
}'
check $? "the note gives the points' range, from x = 0 to the inner wall near 0.5"
selector=$(grep -o "'x < [-0-9.e]* && nx < -0.99'" hollow.log | tr -d "'")
[[ -n $selector ]]
check $? "the note proposes a selector by position ($selector)"
"$gelmpm" --check "$scene" "${hollow[@]}" --set "Boundary conditions/xplane/Selector=$selector" > hollow_fixed.log 2>&1
check $? "with the proposed selector the scene is valid"
! grep -q "note: piece 'xplane'" hollow_fixed.log
check $? "with the proposed selector no note on 'xplane'"
exit $fail
