// The acceptance mesh of recipe sliver (issue 5; tests/recipes/sliver_test.cc,
// docs/recipes/sliver.md): a viscous-CFD-like tet mesh of the box [0,1] x [0,0.8] x [0,0.48].
// - "boundary_layer" (physical volume 1): 10 prism layers on the wall z = 0, first height 0.0015,
//   growth 1.35 (total 0.082), each prism split into 3 tets. The layer's dihedral angles follow
//   the wall triangles (max <= 108 deg) and its thinnest cells are ~1 deg flat.
// - "far_field" (physical volume 2): the box above, plain Delaunay without optimisation, which
//   leaves slivers (max dihedral > 150, min < 10).
// gmsh 4.8.4: 11,100 tets (8,340 in the layer), layer dihedral 1.01 .. 107.08 deg, 38 slivers.
//   gmsh -3 boundary_layer_slivers.geo -format msh41 -o bl.msh
lc = 0.09;        // wall and far-field edge length
first = 0.0015;   // first-layer height: ~1 deg flat cells against lc
growth = 1.35;    // layer height ratio; the top layer (0.022) is still 4x flatter than lc
layers = 10;
Point(1) = {0, 0, 0, lc};
Point(2) = {1, 0, 0, lc};
Point(3) = {1, 0.8, 0, lc};
Point(4) = {0, 0.8, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
// Layer tops as fractions of the layer's thickness (what Layers{} takes).
thickness = first * (growth^layers - 1) / (growth - 1);
counts[] = {};
tops[] = {};
h = first;
z = 0;
For i In {1:layers}
  z += h;
  counts[] += 1;
  tops[] += z / thickness;
  h *= growth;
EndFor
layer[] = Extrude {0, 0, thickness} { Surface{1}; Layers{counts[], tops[]}; };
// Without Layers{} the extrusion is geometry only: its volume is meshed by Algorithm3D.
far[] = Extrude {0, 0, 0.4} { Surface{layer[0]}; };
Physical Volume("boundary_layer", 1) = {layer[1]};
Physical Volume("far_field", 2) = {far[1]};
Mesh.Algorithm = 6;    // Frontal-Delaunay wall triangles: well shaped, so the layer's are
Mesh.Algorithm3D = 1;  // Delaunay
Mesh.Optimize = 0;     // keep the slivers
