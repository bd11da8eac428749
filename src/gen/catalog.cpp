#include "src/gen/catalog.hpp"

#include <fmt/format.h>

#include "src/gen/generator_args.hpp"
#include "src/gen/generators.hpp"

namespace loom::gen {

const std::vector<GeneratorKind>& generator_kinds() {
  static const std::vector<GeneratorKind> kinds{
      {"box",
       {"A", "B", "C"},
       "surface of [0,A]x[0,B]x[0,C], unit quads",
       false,
       [](const std::vector<int>& a) -> GeneratedMesh { return box(a[0], a[1], a[2]); }},
      {"lshape",
       {"N"},
       "L-shaped prism of three unit cubes, N cells per unit",
       false,
       [](const std::vector<int>& a) -> GeneratedMesh { return lshape(a[0]); }},
      {"cylinder",
       {"N", "H"},
       "radius 1, height 2, O-grid caps (N x N centre), H layers",
       false,
       [](const std::vector<int>& a) -> GeneratedMesh { return cylinder(a[0], a[1]); }},
      {"cubesphere",
       {"N"},
       "unit sphere projected from a cube, N x N quads per face",
       false,
       [](const std::vector<int>& a) -> GeneratedMesh { return cubesphere(a[0]); }},
      {"torus",
       {"N", "M"},
       "torus, N quads around the axis and M around the tube (N, M >= 3, N*M even)",
       false,
       [](const std::vector<int>& a) -> GeneratedMesh { return torus(a[0], a[1]); }},
      {"double-torus",
       {"N", "M1", "M2"},
       "two tori (N x M1 and N x M2 quads) joined by a tube, genus 2 (N >= 4 even, M1, M2 >= 3)",
       false,
       [](const std::vector<int>& a) -> GeneratedMesh { return torus_chain(a[0], {a[1], a[2]}); }},
      {"plate",
       {"N", "K"},
       "plate of (2N+1) x 3 x 1 unit cubes with N square holes, genus N, K quads per unit",
       false,
       [](const std::vector<int>& a) -> GeneratedMesh { return plate_with_holes(a[0], a[1]); }},
      {"ring",
       {"N", "K"},
       "ring of unit cubes round a square hole with N unit-cube bosses on top, genus 1, K quads per unit",
       false,
       [](const std::vector<int>& a) -> GeneratedMesh { return ring_of_bosses(a[0], a[1]); }},
      {"schneiders",
       {},
       "Schneiders' pyramid, 16 quads",
       false,
       [](const std::vector<int>&) -> GeneratedMesh { return schneiders(); }},
      {"tet4",
       {},
       "boundary of a tetrahedron split into 4 hexes, 12 quads",
       false,
       [](const std::vector<int>&) -> GeneratedMesh { return tet4(); }},
      {"spindle",
       {},
       "octagonal spindle (tetragonal trapezohedron), 8 quads",
       false,
       [](const std::vector<int>&) -> GeneratedMesh { return spindle(); }},
      {"odd7",
       {},
       "cube with one face split in two: 7 quads, no hex mesh exists",
       false,
       [](const std::vector<int>&) -> GeneratedMesh { return odd7(); }},
      {"randquad",
       {"F", "S"},
       "random quadrangulation of the unit sphere: F quads (even, >= 6), seed S",
       false,
       [](const std::vector<int>& a) -> GeneratedMesh {
         require_at_least("randquad", {{"S", a[1]}}, 0);
         return randquad(a[0], static_cast<std::uint64_t>(a[1]));
       }},
      {"quadrangulation",
       {"F", "I"},
       "3-connected quadrangulation number I (from 0) of those with F quads (6..20), on the unit sphere",
       false,
       [](const std::vector<int>& a) -> GeneratedMesh { return quadrangulation(a[0], a[1]); }},
      {"bosses",
       {"K"},
       "box with a cylindrical and a block boss, block-structured all-quad by Gmsh: 280 K^2 quads",
       false,
       [](const std::vector<int>& a) -> GeneratedMesh { return bosses(a[0]); }},
      {"bosses-free",
       {"K"},
       "the same part, free all-quad mesh by Gmsh (Frontal-Delaunay, subdivision); K: 1 coarse, 2 finer...",
       false,
       [](const std::vector<int>& a) -> GeneratedMesh { return bosses_free(a[0]); }},
      {"hexgrid",
       {"A", "B", "C"},
       "hex mesh of [0,A]x[0,B]x[0,C], unit cells",
       true,
       [](const std::vector<int>& a) -> GeneratedMesh { return hexgrid(a[0], a[1], a[2]); }},
      {"ogrid",
       {"N", "H"},
       "hex mesh whose boundary is 'cylinder N H' (swept O-grid)",
       true,
       [](const std::vector<int>& a) -> GeneratedMesh { return ogrid_cylinder(a[0], a[1]); }},
  };
  return kinds;
}

const GeneratorKind* find_generator_kind(std::string_view name) {
  for (const auto& kind : generator_kinds())
    if (kind.name == name) return &kind;
  return nullptr;
}

std::string usage(const GeneratorKind& kind) {
  return kind.params.empty() ? kind.name : fmt::format("{} {}", kind.name, fmt::join(kind.params, " "));
}

}  // namespace loom::gen
