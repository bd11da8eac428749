// A tee: two solid round bars joined at right angles, the junction filleted.
SetFactory("OpenCASCADE");
Cylinder(1) = {-30, 0, 0, 60, 0, 0, 8};
Cylinder(2) = {0, 0, 0, 0, 0, 28, 6};
body() = BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; Delete; };
// the curve where the upright meets the bar
e() = Curve In BoundingBox{-7, -7, 4, 7, 7, 9};
part() = Fillet{body(0)}{e()}{3};
