# Units round trip on paper §4.1 (the coarse scene of tests/scenes, to 0.002 tau_d):
# 1. constrained_swelling_lab.prm, the scene written by hand in mm, s and kPa (factors in its
#    header: length 2 mm, tau_d 1024 s, stress 100 kPa), writes the same statistics.csv as the
#    normalised scene, bit for bit (the factors are chosen so that the conversion is exact);
# 2. its statistics_units.csv is statistics.csv with each column times its factor (time and dt
#    1024 s, forces 100 kPa * 2 mm = 0.2 N/mm, inflows 4/1024 mm^3/s/mm, volumes 4 mm^3/mm, the
#    rest 1), to the 10 digits written, and its header names the units;
# 3. its parameters.prm is a normalised scene that runs the same and writes the same
#    statistics_units.csv; --check prints the conversion table, --print-parameters the
#    normalised values;
# 4. a chemical potential in J/mol is divided by R T;
# 5. every entry of the scene reference has a physical dimension in the conversion's table.
# Arguments: the gelmpm executable and the tests/ directory.
gelmpm="$1"
tests="$2"
source "$(dirname "${BASH_SOURCE[0]}")/../scratch.sh"
lab="$tests/units/constrained_swelling_lab.prm"

"$gelmpm" "$tests/scenes/constrained_swelling_short.prm" --set "Output/Directory=normalised" \
  --set "Time stepping/End time=0.002" --set "Stability/Inertia=false" \
  --set "Stability/Schur eigenvalues=0" --set "Observables/Forces and fluxes=all" \
  --set "Boundary conditions/top/Chemical potential value/Function expression=if(t < 0.0009765625, -0.146, 0)" \
  >normalised.log
check $? "the normalised scene runs"
"$gelmpm" "$lab" >lab.log
check $? "the scene in laboratory units runs"
cmp normalised/statistics.csv lab/statistics.csv
check $? "statistics.csv of the laboratory scene is the normalised scene's, bit for bit"
[[ $(wc -l <lab/statistics.csv) -ge 10 ]]
check $? "the run took steps ($(($(wc -l <lab/statistics.csv) - 2)))"
[[ ! -e normalised/statistics_units.csv ]]
check $? "a scene without units writes no statistics_units.csv"

# 2. The columns times the stated factors.
awk -F, '
  NR == FNR { if (FNR > 1) for (k = 1; k <= NF; ++k) value[FNR, k] = $k; next }
  FNR == 1 {
    for (k = 1; k <= NF; ++k) {
      name = $k; sub(/ \[.*/, "", name); unit = $k; sub(/^[^[]*\[/, "", unit); sub(/\]$/, "", unit)
      factor[k] = 1; want = "1"
      if (name == "time" || name == "dt") { factor[k] = 1024; want = "s" }
      else if (name == "t_over_tau_d") want = "tau_d"
      else if (name ~ /_force_[xy]$/) { factor[k] = 0.2; want = "N/mm" }
      else if (name ~ /_inflow$/) { factor[k] = 4 / 1024; want = "mm^3/s/mm" }
      else if (name ~ /_solvent_in$/ || name == "solvent_volume") { factor[k] = 4; want = "mm^3/mm" }
      if (unit != want) { print "FAIL: column " name " has the unit [" unit "], expected [" want "]"; bad = 1 }
    }
    next
  }
  {
    for (k = 1; k <= NF; ++k) {
      if ($k == "" && value[FNR, k] == "") continue
      expected = value[FNR, k] * factor[k]
      if (($k - expected) ^ 2 > (1e-9 * expected) ^ 2) {
        print "FAIL: row " FNR " column " k ": " $k " against " expected; bad = 1
      }
      ++compared
    }
  }
  END { print "compared " compared " values"; exit bad }' lab/statistics.csv lab/statistics_units.csv
check $? "statistics_units.csv is statistics.csv times the stated factors, with their units"

# 3. parameters.prm, --check and --print-parameters.
"$gelmpm" lab/parameters.prm --set "Output/Directory=rerun" >rerun.log
check $? "the run's parameters.prm runs"
cmp lab/statistics.csv rerun/statistics.csv && cmp lab/statistics_units.csv rerun/statistics_units.csv
check $? "parameters.prm (normalised values, the scales in 'Units') writes the same two files"
"$gelmpm" --check "$lab" >check.log
check $? "--check of the laboratory scene"
grep -q "^    Time stepping/End time: 2.048 s -> 0.002\$" check.log &&
  grep -q "^    Background grid/Upper corner: 1, 4 mm -> 0.5, 2\$" check.log &&
  grep -q "^    Material/Diffusivity: 0.00390625 mm^2/s -> 1\$" check.log &&
  grep -Fq "Chemical potential value/Function expression: if(t < 1, -0.146, 0) -> if((t*1024) < 1, -0.146, 0)" check.log
check $? "--check prints the entries converted, laboratory value -> normalised value"
"$gelmpm" --print-parameters "$lab" >listing
grep -q "set End time *= 0.002 " listing && grep -q "set Scene values *= normalised" listing &&
  grep -q "set Time scale *= 1024 " listing
check $? "--print-parameters shows the normalised values the run uses"

# 4. Chemical potentials per mole.
"$gelmpm" --check "$lab" --set "Units/Chemical potential unit=J/mol" \
  --set "Units/Temperature=300" >mole.log
check $? "--check with the chemical potential in J/mol"
awk '/Material\/Initial chemical potential: -0.1460 J\/mol -> / {
       x = $NF; expected = -0.146 / (8.314462618 * 300)
       found = 1; exit !((x - expected) ^ 2 < (1e-12 * expected) ^ 2) }
     END { if (!found) exit 1 }' mole.log
check $? "a chemical potential in J/mol is divided by R T"
grep -Fq -- "-> (if((t*1024) < 1, -0.146, 0))/2494.33" mole.log
check $? "a function's value in J/mol is divided by R T"

# 5. The table knows every entry.
"$gelmpm" --print-parameters >reference
check $? "--print-parameters without a scene"
entries=$(grep -c "^ *set " reference)
annotated=$(grep -c "^ *# Laboratory units: " reference)
[[ $entries -eq $annotated ]]
check $? "every entry says how it is converted ($annotated of $entries)"
! grep -q "NOT IN THE TABLE" reference
check $? "every entry has its physical dimension in the table of source/core/units.cc"
# On failure: the entries to add to the table (entry_rules() in source/core/units.cc).
grep -A1 "NOT IN THE TABLE" reference | grep "^ *set " | head
exit $fail
