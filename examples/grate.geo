// A grate: a plate with three by two square holes (genus 6). OpenCASCADE
// kernel; millimetres.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 64, 44, 5};
For i In {0:2}
  For j In {0:1}
    Box(2 + 2 * i + j) = {6 + 20 * i, 6 + 20 * j, -1, 12, 12, 7};
  EndFor
EndFor
part() = BooleanDifference{ Volume{1}; Delete; }{ Volume{2:7}; Delete; };
