# Contact of the gel with itself on two ranks against one: the two blocks of one body of
# tests/simulator/self_contact_blocks_scene.prm, 0.2 (2.4 cells) apart, the upper one pressed onto
# the lower one within the first step, with 'Separate faces = false' (the faces' copies of
# functions are found on one rank only). p4est puts the blocks on different ranks (measured: one
# rank holds 33 of the 72 facing points and 159 of the 360 pairs), so the pairs couple the
# unknowns of two ranks: every rank gathers the facing points, finds the same pairs and active
# sets, and assembles the pairs of its own points. The statistics agree with one rank (the
# self-contact force, area and penetration included), the contact carries a force from the
# first step on, and no point is lost where the upper block moves 2.5 cells in one step (before,
# deal.II dropped the points that moved beyond the ghost layer: 55 of them, and the run stopped).
# With the default 'Separate faces = true' two ranks are refused with the entry named. The same
# agreement by Nitsche's method ('Method = nitsche', gamma_s = 1000), and in 3D.
source "$(dirname "$0")/common.sh"
scene="$source_dir/tests/simulator/self_contact_blocks_scene.prm"
run_both "$scene" --set "Contact/Self contact/Separate faces=false"
compare_statistics --ignore "wall_time,residual_u,residual_mu,solvent_imbalance"
force=$(statistic two/statistics.csv self_contact_force 3)
points=$(statistic two/statistics.csv self_contact_points 3)
awk -v f="${force:-0}" -v p="${points:-0}" 'BEGIN { exit !(f > 0 && p >= 30) }'
check $? "the faces touch after the first step on two ranks (force ${force:-none}, ${points:-no} points)"
"$mpiexec" -n 2 --oversubscribe "$gelmpm" "$scene" --set "Output/Directory=refused" \
  > refused.log 2>&1
status=$?
[[ $status -eq 2 ]] && grep -q "Contact/Self contact/Separate faces" refused.log && [[ ! -e refused ]]
check $? "separated faces on two ranks refused with the entry named (status $status: $(grep -m1 'Separate faces' refused.log))"
# By Nitsche's method: each rank evaluates the tractions of its own points, and every rank
# gathers them for the same active sets and statistics.
rm -rf one two
run_both "$scene" --set "Contact/Self contact/Separate faces=false" \
  --set "Contact/Self contact/Method=nitsche" --set "Contact/Self contact/Penalty=1000" \
  --set "Time stepping/End time=1e-3"
# The penetration (2.7e-6) is a difference of positions of order 1: its round-off is that of the
# positions (measured 1e-15 between the runs), compared in the length unit.
compare_statistics --ignore "wall_time,residual_u,residual_mu,solvent_imbalance,self_contact_penetration"
for row in 3; do
  one=$(statistic one/statistics.csv self_contact_penetration $row)
  two=$(statistic two/statistics.csv self_contact_penetration $row)
  awk -v a="${one:-0}" -v b="${two:-1}" 'BEGIN { d = a - b; exit !(a > 0 && d < 1e-12 && -d < 1e-12) }'
  check $? "Nitsche: the penetration on two ranks within 1e-12 of one rank's (row $row: $one, $two)"
done
# 3D (the pressed cubes, their first step): each point against the tangent plane of the nearest
# facing point; a pair whose point and plane lie on different ranks writes entries among the other
# rank's unknowns too (before its cell was coupled with itself, the first assembly stopped on an
# entry the pattern lacked).
# Against the closed form of the 3D obstacle block (tests/simulator/self_contact_blocks.cc) rather
# than a run on one rank, which that test makes.
rm -rf two
"$mpiexec" -n 2 --oversubscribe "$gelmpm" --set "Output/Directory=two" \
  --set "Contact/Self contact/Separate faces=false" --set "Time stepping/End time=1e-3" \
  "$source_dir/tests/simulator/self_contact_blocks_3d_scene.prm" > two.log 2>&1
check $? "the 3D run on two ranks failed: $(tail -3 two.log)"
top=$(statistic two/statistics.csv top_force_z 3)
force=$(statistic two/statistics.csv self_contact_force 3)
awk -v t="${top:-0}" -v f="${force:-0}" 'BEGIN { e = -0.0059183; d = t - e; s = f + t
  exit !(d < -5e-3 * e && -d < -5e-3 * e && s < -1e-6 * t && -s < -1e-6 * t) }'
check $? "3D on two ranks: the reaction within 0.5 % of the closed form -0.0059183, the self-contact force equal to it (1e-6) (${top:-none}, ${force:-none})"
finish
