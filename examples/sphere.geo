// A ball of radius 20 mm: one smooth face, no features.
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 20};
