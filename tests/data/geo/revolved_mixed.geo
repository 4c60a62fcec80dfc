// Revolving a triangulated square about an axis through one of its sides with layers:
// triangles away from the axis sweep into prisms, those with a corner on the axis into
// pyramids, those with a side on it into tetrahedra (a tet + prism + pyramid mesh).
lc = 0.4;
Point(1) = {0, 0, 0, lc};
Point(2) = {1, 0, 0, lc};
Point(3) = {1, 1, 0, 0.6 * lc};
Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Extrude {{0, 1, 0}, {0, 0, 0}, -Pi / 4} { Surface{1}; Layers{2}; Recombine; }
Physical Volume("solid") = {1};
