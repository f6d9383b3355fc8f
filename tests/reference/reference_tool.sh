#!/usr/bin/env bash
# gelmpm-reference reads the scene the user runs and prints its gels' references (--csv here).
# Checked, each with its tolerance:
# - prm/free_swelling_cube.prm: lambda_0 = 1.2801 maps to mu_0 = -0.14597453 (1e-6), and the scene
#   given by that mu_0 ('Initial state = chemical potential') back to lambda_0 = 1.2801 (1e-6); the
#   bath mu_b = 0 is read from the pieces at 'End time', and lambda_eq = 2.348902 there (the scene's
#   comment, 1e-6);
# - prm/creasing_film.prm (2D): the plane-strain J at mu = 0 is 9.432 (doc/own_scenes.md section 7,
#   5e-4), the film's s = 2.72722 (tests/material/flory_rehner, 1e-5), s = 2.4 at mu = -0.0066
#   (5e-5);
# - prm/creasing_film.prm with --bath 0.005, between N nu/lambda_0^3 = 0.0034796 and the plane-strain
#   limit N nu/lambda_0 = 0.0057019 (tests/material/swelling_limit): accepted, the plane-strain
#   J = 29.961853 (a bisection of the closed form, 1e-5) and no 3D row at the bath (above the 3D
#   limit 0.001697);
# - --ramp 50 on prm/creasing_film.prm: the printed bath, evaluated by awk, is mu_0 = -0.14597453
#   at t = 0 (1e-8) and the bath 0 from t = T on (1e-12), and gelmpm --check takes it as the top
#   piece's 'Chemical potential value';
# - prm/bilayer_actuator.prm with --thicknesses 0.1,0.1: the bath -0.04 from the scene and
#   Timoshenko's curvature 0.19589 (doc/own_scenes.md section 6, 5e-6);
# - bad input exits with status 2 and a message naming the option or entry, nothing written:
#   one thickness, thicknesses for a scene of one gel, a bath above the largest swelling mu (3D,
#   plane strain, and 0.003 in the axisymmetric prm/swelling_sphere.prm, whose gel swells in 3D),
#   pieces that prescribe two baths, an option of gelmpm.
# Arguments: the build directory, the source directory.
set -u
tool="$1/gelmpm-reference"
prm="$2/prm"
failures=0
cd "$(mktemp -d)"

# value <csv> <region> <quantity> <mu or empty>: the value column of that row.
value() {
  awk -F, -v r="$2" -v q="$3" -v m="$4" '$1 == r && $2 == q && (m == "*" || $3 == m) { print $4; exit }' <<< "$1"
}
# near <name> <value> <expected> <tolerance>
near() {
  if [[ -n "$2" ]] && awk -v a="$2" -v b="$3" -v t="$4" 'BEGIN { d = a - b; exit !(d < t && -d < t) }'; then
    echo "ok   $1: $2 (expected $3 within $4)"
  else
    echo "FAIL $1: '$2' (expected $3 within $4)"
    failures=$((failures + 1))
  fi
}
# fails <name> <text the message must hold> <arguments...>: exit status 2 with that message.
fails() {
  local name="$1" text="$2"
  shift 2
  local out
  out=$("${tool}" "$@" 2>&1)
  local got=$?
  if [[ ${got} -ne 2 ]] || ! grep -qF -- "${text}" <<< "${out}"; then
    echo "FAIL ${name}: status ${got} (expected 2), output:"
    echo "${out}" | tail -n 3
    failures=$((failures + 1))
  else
    echo "ok   ${name}"
  fi
}

cube=$("${tool}" --csv "${prm}/free_swelling_cube.prm")
near "cube: mu_0 of lambda_0 = 1.2801" "$(value "${cube}" Material mu_0 '*')" -0.14597453 1e-6
near "cube: lambda_eq at mu_b = 0" "$(value "${cube}" Material lambda_free_3d 0)" 2.348902 1e-6
by_mu=$("${tool}" --csv "${prm}/free_swelling_cube.prm" \
  --set "Material/Initial state=chemical potential" \
  --set "Material/Initial chemical potential=-0.14597453")
near "cube: lambda_0 of mu_0 = -0.14597453" "$(value "${by_mu}" Material lambda_0 '*')" 1.2801 1e-6

film=$("${tool}" --csv "${prm}/creasing_film.prm")
near "film: J of plane-strain free swelling" "$(value "${film}" Material J_free_plane_strain 0)" 9.432 5e-4
near "film: s at mu_b = 0" "$(value "${film}" Material s_film 0)" 2.72722 1e-5
near "film: mu at s = 2.4" "$(value "${film}" Material mu_at_s_crease '*')" -0.0066 5e-5

warm=$("${tool}" --csv --bath 0.005 "${prm}/creasing_film.prm")
near "film: plane-strain J at mu_b = 0.005" "$(value "${warm}" Material J_free_plane_strain 0.005)" 29.961853 1e-5
near "film: no 3D state at mu_b = 0.005" "$(value "${warm}" Material J_free_3d 0.005 | wc -c)" 0 0.5

ramp=$("${tool}" --ramp 50 "${prm}/creasing_film.prm")
constants=$(sed -n 's/^ *set Function constants  = //p' <<< "${ramp}")
expression=$(sed -n 's/^ *set Function expression = //p' <<< "${ramp}")
# bath <t>: the printed expression at time t.
bath() {
  awk "function min(a, b) { return a < b ? a : b } function max(a, b) { return a > b ? a : b }
       BEGIN { ${constants//,/;}; t = $1; printf \"%.12g\", ${expression} }"
}
near "ramp: mu_0 at t = 0" "$(bath 0)" -0.14597453 1e-8
near "ramp: the bath at t = T" "$(bath 50)" 0 1e-12
near "ramp: the bath at t = 2 T" "$(bath 100)" 0 1e-12
piece="Boundary conditions/top/Chemical potential value/Function"
if "$1/gelmpm" --check "${prm}/creasing_film.prm" --set "${piece} constants=${constants}" \
  --set "${piece} expression=${expression}" > /dev/null 2>&1; then
  echo "ok   ramp: gelmpm --check takes the printed bath"
else
  echo "FAIL ramp: gelmpm --check refuses the printed bath"
  failures=$((failures + 1))
fi

bilayer=$("${tool}" --csv --thicknesses 0.1,0.1 "${prm}/bilayer_actuator.prm")
near "bilayer: the bath from the scene" \
  "$(awk -F, '$1 == "bilayer" && $2 == "bilayer_curvature" { print $3; exit }' <<< "${bilayer}")" -0.04 1e-12
near "bilayer: Timoshenko's curvature" "$(value "${bilayer}" bilayer bilayer_curvature '*')" 0.19589 5e-6

fails "one thickness" "--thicknesses" --thicknesses 0.1 "${prm}/bilayer_actuator.prm"
fails "thicknesses of one gel" "'--thicknesses' gives two layers, but the scene has 1 gel(s)" \
  --thicknesses 0.1,0.1 "${prm}/creasing_film.prm"
fails "bath above the largest mu" "'--bath' gives the bath mu_b = 0.5" --bath 0.5 \
  "${prm}/free_swelling_cube.prm"
fails "plane-strain bath above N nu/lambda_0" "'--bath' gives the bath mu_b = 0.006, above 0.005701898" \
  --bath 0.006 "${prm}/creasing_film.prm"
fails "axisymmetric bath above the 3D limit" "'--bath' gives the bath mu_b = 0.003, above 0.00169652" \
  --bath 0.003 "${prm}/swelling_sphere.prm"
fails "ramp with csv" "'--ramp' prints a bath expression" --ramp 50 --csv "${prm}/creasing_film.prm"
fails "two baths" "piece 'bottom' prescribes -0.05: the scene has no one bath" "${prm}/bilayer_actuator.prm" \
  --set "Boundary conditions/bottom/Chemical potential value/Function expression=-0.05"
fails "gelmpm option" "'--check' is an option of gelmpm" --check "${prm}/creasing_film.prm"
if [[ -n "$(ls -A)" ]]; then
  echo "FAIL: files were written: $(ls -A)"
  failures=$((failures + 1))
fi
echo "${failures} failure(s)"
exit $((failures > 0))
