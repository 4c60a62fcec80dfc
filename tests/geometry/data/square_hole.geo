// 2D unit square with a circular hole of radius 0.25: 4 corners, 4 straight curves, 1 closed
// curve (the hole).
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 1, 1};
Disk(2) = {0.5, 0.5, 0, 0.25};
BooleanDifference{ Surface{1}; Delete; }{ Surface{2}; Delete; }
Mesh.CharacteristicLengthMax = 0.1;
