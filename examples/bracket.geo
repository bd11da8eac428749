// A genus-0 bracket for `loom mesh`: a base plate with a notch cut from one
// end, a cylindrical boss, and a rounded block standing on it. OpenCASCADE
// kernel; lengths in millimetres.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 60, 40, 12};
Cylinder(2) = {18, 20, 6, 0, 0, 22, 9};
Box(3) = {38, 8, 6, 14, 24, 16};
Box(4) = {-1, 14, 4, 11, 12, 10};
base() = BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; Volume{3}; Delete; };
part() = BooleanDifference{ Volume{base()}; Delete; }{ Volume{4}; Delete; };
