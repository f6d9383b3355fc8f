#!/usr/bin/env bash
# Writes the meshes of the scenes in prm/ from their Gmsh geometry files here (Debian: apt-get
# install gmsh). The .msh files are kept in the repository, so that the scenes run without Gmsh.
#
#   bash contrib/meshes/make_meshes.sh
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
top="$(cd "${here}/../.." && pwd)"
gmsh -2 -format msh41 "${here}/gripper_finger.geo" -o "${top}/prm/gripper_finger.msh" >/dev/null
gmsh -2 -format msh41 -setnumber triangles 1 "${here}/gripper_finger.geo" \
  -o "${top}/tests/particles/gripper_finger_triangles.msh" >/dev/null
echo "wrote prm/gripper_finger.msh and tests/particles/gripper_finger_triangles.msh"
