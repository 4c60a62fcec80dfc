// 2 x 1 x 1 box (volume 2, surface area 10) for tmop's io tests: tets, boundary triangles.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1, 1};
Physical Volume(7) = {1};
Physical Surface(3) = {1, 2, 3, 4, 5, 6};
Mesh.CharacteristicLengthMax = 0.5;
