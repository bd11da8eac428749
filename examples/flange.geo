// A flange: a disc with a hub (a boss) on it, a bore through both and four
// bolt holes round it (genus 5). OpenCASCADE kernel; millimetres.
SetFactory("OpenCASCADE");
Cylinder(1) = {0, 0, 0, 0, 0, 8, 30};
Cylinder(2) = {0, 0, 8, 0, 0, 14, 13};
Cylinder(3) = {0, 0, -1, 0, 0, 24, 6};
For i In {0:3}
  Cylinder(4 + i) = {21 * Cos(i * Pi / 2 + Pi / 4), 21 * Sin(i * Pi / 2 + Pi / 4), -1, 0, 0, 10, 3};
EndFor
body() = BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; Delete; };
part() = BooleanDifference{ Volume{body()}; Delete; }{ Volume{3:7}; Delete; };
