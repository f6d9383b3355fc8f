#!/usr/bin/env bash
# The peer tools read the scene file of the MPM scene they are compared with (PeerInput): the gel,
# 'Time stepping', 'Newton' and 'Stability' from the scene, the mesh from 'FE peer'. Checked:
# - the gel is the scene's: 'Material/Initial stretch = 1.3' given to gelmpm-fem-column is the
#   lambda_0 it reports (the Table 1 default is 1.2801);
# - bad input exits with status 2 and one message naming the entry: a 3D scene ('Dimension'), the
#   scene of another benchmark ('Time stepping/Characteristic length', 'Material/Regions'), a
#   non-physical gel ('Material/Shear modulus'), a malformed peer entry ('FE peer/Cells'), an
#   unknown entry, a gelmpm-only option; and nothing is written.
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
check "unknown entry" 2 "FE peer/Cels" "${build}/gelmpm-fem-flat-punch" "${prm}/flat_punch.prm" \
  --set "FE peer/Cels=4"
check "gelmpm option" 2 "'--resume' is an option of gelmpm" "${build}/gelmpm-fem-swelling" \
  "${prm}/constrained_swelling.prm" --resume
if [[ -n "$(ls -A)" ]]; then
  echo "FAIL: files were written: $(ls -A)"
  failures=$((failures + 1))
fi
exit ${failures}
