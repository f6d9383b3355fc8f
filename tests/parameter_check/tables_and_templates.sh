# What gelmpm prints about a scene before it runs:
# 1. --print-parameters without a scene shows one subsection of each kind a scene names (a piece,
#    a region, an obstacle) under a placeholder name, with its entries, each marked as a template;
# 2. --check prints the material regions' table for a scene with regions (volume points, initial
#    volume and the constants that differ from the section 'Material'), none for one gel;
# 3. the piece table's areas are per unit thickness in plane strain and revolved areas in an
#    axisymmetric scene.
# Arguments: the gelmpm executable and the prm/ directory.
gelmpm="$1"
prm="$2"
source "$(dirname "${BASH_SOURCE[0]}")/../scratch.sh"

"$gelmpm" --print-parameters >listing
check $? "--print-parameters without a scene succeeds"
for kind in piece region obstacle; do
  grep -B3 "^  subsection <$kind>\$" listing | grep -q "# TEMPLATE: one subsection like this per name"
  check $? "the template <$kind> is shown and marked as a template"
done
sed -n '/^  subsection <piece>$/,/^  end$/p' listing | grep -q "set Selector "
check $? "the piece template has its entries ('Selector')"
sed -n '/^  subsection <region>$/,/^  end$/p' listing | grep -q "set Flory-Huggins chi "
check $? "the region template has its entries ('Flory-Huggins chi')"
sed -n '/^  subsection <obstacle>$/,/^  end$/p' listing | grep -q "set Shape "
check $? "the obstacle template has its entries ('Shape')"

"$gelmpm" --check "$prm/bilayer_actuator.prm" >bilayer
check $? "--check of the bilayer"
grep -q "^  material regions (volume points, initial volume per unit thickness;" bilayer
check $? "the bilayer's log has a region table, its volumes per unit thickness"
grep -Eq "^    Material +2880 points  volume +0.2\$" bilayer
check $? "the section 'Material' is a row with its points and volume"
grep -Eq "^    passive +2880 points  volume +0.2  chi 0.3 \(0.1\), lambda_0 1.22897 \(1.2801\)\$" bilayer
check $? "the region 'passive' is a row with the constants that differ"
grep -q "initial area per unit thickness" bilayer
check $? "plane strain: the pieces' areas are per unit thickness"

"$gelmpm" --check "$prm/constrained_swelling.prm" >one_gel
check $? "--check of a scene of one gel"
! grep -q "material regions" one_gel
check $? "one gel: no region table"

"$gelmpm" --check "$prm/indentation_sphere.prm" >axisymmetric
check $? "--check of an axisymmetric scene"
grep -q "initial revolved area (2 pi R times the meridian's)" axisymmetric &&
  ! grep -q "per unit thickness" axisymmetric
check $? "axisymmetric: the pieces' areas are revolved areas, not per unit thickness"
exit $fail
