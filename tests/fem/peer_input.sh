#!/usr/bin/env bash
# The peer tools read the scene file of the MPM scene they are compared with (PeerInput): the gel,
# 'Time stepping', 'Newton' and 'Stability' from the scene, the mesh from 'FE peer'. Checked:
# - the gel is the scene's: 'Material/Initial stretch = 1.3' given to gelmpm-fem-column is the
#   lambda_0 it reports (the Table 1 default is 1.2801);
# - bad input exits with status 2 and one message naming the entry: a 3D scene ('Dimension'), the
#   scene of another benchmark ('Time stepping/Characteristic length', 'Material/Regions'), a
#   non-physical gel ('Material/Shear modulus'), a malformed peer entry ('FE peer/Cells'), peer
#   entries that the peer's mesh cannot take ('FE peer/Width' 0, 'FE peer/Cells' that put the
#   punch's edge inside a cell, 'FE peer/Ramp time' 0: they ended with exit 1 and a message
#   naming no entry), a degree above 10, an unknown entry, a gelmpm-only option; and nothing is
#   written.
# Arguments: the build directory, the source directory.
set -u
build="$1"
prm="$2/prm"
failures=0
check() { # name, expected status, text the message must hold, command...
  local name="$1" status="$2" text="$3"
  shift 3
  local out
  out=$("$@" 2>&1)
  local got=$?
  if [[ ${got} -ne ${status} ]] || ! grep -qF -- "${text}" <<< "${out}"; then
    echo "FAIL ${name}: status ${got} (expected ${status}), output:"
    echo "${out}" | tail -n 5
    failures=$((failures + 1))
  else
    echo "ok   ${name}"
  fi
}
cd "$(mktemp -d)"
check "scene gel" 0 "lambda_0 1.3," "${build}/gelmpm-fem-column" "${prm}/column_buckling.prm" \
  --set "Material/Initial stretch=1.3" --set "Time stepping/End time=1e-3" \
  --set "Time stepping/Initial step=1e-3" --set "FE peer/Cells=1" --quiet
check "3D scene" 2 "Dimension" "${build}/gelmpm-fem-column" "${prm}/free_swelling_cube.prm"
check "other benchmark" 2 "Time stepping/Characteristic length" \
  "${build}/gelmpm-fem-column" "${prm}/flat_punch.prm"
check "no regions" 2 "Material/Regions" "${build}/gelmpm-fem-bilayer" "${prm}/column_buckling.prm"
check "negative modulus" 2 "Material/Shear modulus" "${build}/gelmpm-fem-swelling" \
  "${prm}/constrained_swelling.prm" --set "Material/Shear modulus=-1"
check "malformed cells" 2 "FE peer/Cells" "${build}/gelmpm-fem-flat-punch" "${prm}/flat_punch.prm" \
  --set "FE peer/Cells=abc"
check "zero width" 2 "'FE peer/Width' is 0" "${build}/gelmpm-fem-swelling" \
  "${prm}/constrained_swelling.prm" --set "FE peer/Width=0"
check "punch edge in a cell" 2 "'FE peer/Cells' is 21" "${build}/gelmpm-fem-flat-punch" \
  "${prm}/flat_punch.prm" --set "FE peer/Cells=21"
check "zero ramp time" 2 "'FE peer/Ramp time' is 0" "${build}/gelmpm-fem-column" \
  "${prm}/column_buckling.prm" --set "FE peer/Ramp time=0"
# A degree without bound ran out of memory (std::bad_alloc after 21 s at 40).
check "degree 40" 2 "'FE peer/Degree' is 40, above 10" "${build}/gelmpm-fem-swelling" \
  "${prm}/constrained_swelling.prm" --set "FE peer/Degree=40"
check "unknown entry" 2 "FE peer/Cels" "${build}/gelmpm-fem-flat-punch" "${prm}/flat_punch.prm" \
  --set "FE peer/Cels=4"
check "gelmpm option" 2 "'--resume' is an option of gelmpm" "${build}/gelmpm-fem-swelling" \
  "${prm}/constrained_swelling.prm" --resume
# A peer whose body is one gel refuses a scene with material regions (it dropped them silently).
check "two gels" 2 "'Material/Regions' names the region(s) passive, but gelmpm-fem-swelling" \
  "${build}/gelmpm-fem-swelling" "${prm}/bilayer_actuator.prm"
check "column with a region" 2 "'Material/Regions' names the region(s) soft, but gelmpm-fem-column" \
  "${build}/gelmpm-fem-column" "${prm}/column_buckling.prm" --set "Material/Regions=soft" \
  --set "Material/soft/Selector=y < 1" --set "Material/soft/Flory-Huggins chi=0.3"
if [[ -n "$(ls -A)" ]]; then
  echo "FAIL: files were written: $(ls -A)"
  failures=$((failures + 1))
fi
# The output directory is claimed as gelmpm claims its own (PeerInput::claim_output_directory):
# a peer runs into a new directory and again into its own, but a directory that holds a gelmpm
# run's results is refused and its statistics.csv left as it was (the peer overwrote it), gelmpm
# refuses the peer's directory (it deleted the peer's statistics.csv), and so is a directory whose
# lock (gelmpm.lock) another run holds, here this script.
short=(--set "Time stepping/End time=1e-3" --quiet)
check "new directory" 0 "results: fem/statistics.csv" "${build}/gelmpm-fem-swelling" \
  "${prm}/constrained_swelling.prm" --set "FE peer/Output directory=fem" "${short[@]}"
check "own directory again" 0 "results: fem/statistics.csv" "${build}/gelmpm-fem-swelling" \
  "${prm}/constrained_swelling.prm" --set "FE peer/Output directory=fem" "${short[@]}"
"${build}/gelmpm" "${prm}/constrained_swelling.prm" --set "Output/Directory=mpm" \
  --set "Time stepping/End time=1e-3" >/dev/null 2>&1
before=$(md5sum <mpm/statistics.csv)
check "gelmpm's directory" 2 "'FE peer/Output directory' is 'mpm', which holds the results of a gelmpm run" \
  "${build}/gelmpm-fem-swelling" "${prm}/constrained_swelling.prm" \
  --set "FE peer/Output directory=mpm" "${short[@]}"
if [[ $(md5sum <mpm/statistics.csv) != "${before}" ]]; then
  echo "FAIL: the gelmpm run's statistics.csv was changed"
  failures=$((failures + 1))
fi
# And the other way round: gelmpm refuses the peer's directory, whose statistics.csv it would
# have deleted with an earlier run's output.
before=$(md5sum <fem/statistics.csv)
check "peer's directory for gelmpm" 2 "'Output/Directory' is 'fem', which holds a statistics.csv that no gelmpm run wrote" \
  "${build}/gelmpm" "${prm}/constrained_swelling.prm" --set "Output/Directory=fem" \
  --set "Time stepping/End time=1e-3"
if [[ $(md5sum <fem/statistics.csv) != "${before}" ]]; then
  echo "FAIL: the peer's statistics.csv was changed by gelmpm"
  failures=$((failures + 1))
fi
mkdir busy
exec 9>busy/gelmpm.lock
flock -n 9
check "locked directory" 2 "'FE peer/Output directory' is 'busy', the output directory of another GelMPM run" \
  "${build}/gelmpm-fem-swelling" "${prm}/constrained_swelling.prm" \
  --set "FE peer/Output directory=busy" "${short[@]}"
exec 9>&-
exit ${failures}
