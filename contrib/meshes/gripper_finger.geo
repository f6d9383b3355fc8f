// A hydrogel gripper finger (prm/gripper_finger.prm): a tapered beam with a rounded tip, standing
// on its base. Written to prm/gripper_finger.msh by contrib/meshes/make_meshes.sh.
//
// Lengths in units of the finger's length L = 1: base width 0.3 at y = 0.2, tip width 0.16 at
// y = 1.2 with a semicircular cap, so the tip reaches y = 1.28. The sides are slanted and the tip
// is round: no union of boxes minus disks makes this shape. The same finger in triangles is
// tests/particles/gripper_finger_triangles.msh.
//
// Physical groups of the boundary (GelMPM selects boundary pieces by their numbers or names):
//   1 base   (bonded to a rigid support)
//   2 inner  (the gripping side, x > 0, in contact with the solvent)
//   3 outer  (the back, x < 0)
//   4 tip    (the cap)
size = 0.08; // the subdivision into quadrilaterals halves it

Point(1) = {-0.15, 0.2, 0, size};
Point(2) = { 0.15, 0.2, 0, size};
Point(3) = { 0.08, 1.2, 0, size};
Point(4) = { 0.00, 1.2, 0, size}; // centre of the cap
Point(5) = {-0.08, 1.2, 0, size};

Line(1)   = {1, 2};
Line(2)   = {2, 3};
Circle(3) = {3, 4, 5};
Line(4)   = {5, 1};

Curve Loop(1)    = {1, 2, 3, 4};
Plane Surface(1) = {1};

Physical Curve("base", 1)  = {1};
Physical Curve("inner", 2) = {2};
Physical Curve("outer", 3) = {4};
Physical Curve("tip", 4)   = {3};
Physical Surface("gel", 5) = {1};

// Quadrilaterals only (with -setnumber triangles 1: triangles only, for the tests).
If (!Exists(triangles))
  triangles = 0;
EndIf
Mesh.RecombineAll         = !triangles;
Mesh.Algorithm            = 6;
Mesh.SubdivisionAlgorithm = !triangles;
Mesh.MshFileVersion       = 4.1;
