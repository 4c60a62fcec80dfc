// Reference surface for the part's spherical cavity (data/part.geo): the sphere of radius 0.25
// at (1.45, 0.5, 0.5), finer than the part's mesh. Saved as binary STL:
//   gmsh -2 cavity_sphere.geo -format stl -bin -o cavity_sphere.stl
SetFactory("OpenCASCADE");
Sphere(1) = {1.45, 0.5, 0.5, 0.25};
Mesh.CharacteristicLengthMax = 0.06;
