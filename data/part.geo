SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1, 1};
Cylinder(2) = {0.6, 0.5, -0.1, 0, 0, 1.2, 0.25};
Sphere(3) = {1.45, 0.5, 0.5, 0.25};
BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Volume{3}; Delete; }
Mesh.CharacteristicLengthMax = 0.12;
Physical Volume("solid", 1) = {1};
Physical Surface("wall", 2) = Surface{:};
