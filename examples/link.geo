// A connecting link: a bar with rounded ends, a hole through each end and a
// slot in the middle (genus 3). OpenCASCADE kernel; millimetres.
SetFactory("OpenCASCADE");
Box(1) = {0, -10, 0, 60, 20, 6};
Cylinder(2) = {0, 0, 0, 0, 0, 6, 10};
Cylinder(3) = {60, 0, 0, 0, 0, 6, 10};
body() = BooleanUnion{ Volume{1}; Delete; }{ Volume{2:3}; Delete; };
Cylinder(4) = {0, 0, -1, 0, 0, 8, 4};
Cylinder(5) = {60, 0, -1, 0, 0, 8, 4};
Box(6) = {22, -4, -1, 16, 8, 8};
part() = BooleanDifference{ Volume{body()}; Delete; }{ Volume{4:6}; Delete; };
