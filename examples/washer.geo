// A washer: a thick ring, its bore a third of its diameter (genus 1).
// OpenCASCADE kernel; millimetres.
SetFactory("OpenCASCADE");
Cylinder(1) = {0, 0, 0, 0, 0, 8, 24};
Cylinder(2) = {0, 0, -1, 0, 0, 10, 8};
part() = BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; };
