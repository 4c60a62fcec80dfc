// 2 x 1 rectangle in the plane z = 0 (area 2, perimeter 6): a 2D mesh with boundary lines.
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 2, 1};
Physical Surface(5) = {1};
Physical Curve(6) = {1, 2, 3, 4};
Mesh.CharacteristicLengthMax = 0.4;
