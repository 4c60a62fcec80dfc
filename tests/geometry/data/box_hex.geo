// Unit box as 4 x 4 x 4 hexahedra (transfinite + recombined), for quad boundary facets:
//   gmsh -3 box_hex.geo -o box_hex.msh; gmsh -3 box_hex.geo -order 2 -o box_hex27.msh
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Transfinite Curve{:} = 5;
Transfinite Surface{:};
Recombine Surface{:};
Transfinite Volume{1};
