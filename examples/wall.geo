// An angle bracket: two thin walls (3 mm) at right angles, the inner corner
// filleted, with a hole through each wall.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 50, 40, 3};
Box(2) = {0, 0, 0, 3, 40, 36};
body() = BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; Delete; };
e() = Curve In BoundingBox{2.9, -1, 2.9, 3.1, 41, 3.1};
f() = Fillet{body(0)}{e()}{4};
Cylinder(10) = {30, 20, -1, 0, 0, 5, 6};
Cylinder(11) = {-1, 20, 22, 5, 0, 0, 6};
part() = BooleanDifference{ Volume{f()}; Delete; }{ Volume{10:11}; Delete; };
