// Unit box, for boundary classification tests: 8 corners, 12 feature curves, 6 planar patches.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Mesh.CharacteristicLengthMax = 0.25;
