#include "src/io/vtk_cell_types.hpp"

#include <fmt/format.h>

namespace loom {

namespace {
struct VtkType {
  CellKind kind;
  const char* name;
};

VtkType lookup(int vtk_type) {
  switch (vtk_type) {
    case 1:
      return {CellKind::vertex, "vertex"};
    case 2:
      return {CellKind::vertex, "poly-vertex"};
    case 3:
      return {CellKind::line, "line"};
    case 4:
      return {CellKind::line, "poly-line"};
    case 5:
      return {CellKind::triangle, "triangle"};
    case 6:
      return {CellKind::unsupported, "triangle strip (6)"};
    case 7:
      return {CellKind::polygon, "polygon"};
    case 8:
      return {CellKind::unsupported, "pixel (8; save quads as VTK_QUAD 9)"};
    case 9:
      return {CellKind::quad, "quad"};
    case 10:
      return {CellKind::other_volume, "tetrahedron"};
    case 11:
      return {CellKind::unsupported, "voxel (11; save hexahedra as VTK_HEXAHEDRON 12)"};
    case 12:
      return {CellKind::hexahedron, "hexahedron"};
    case 13:
      return {CellKind::other_volume, "wedge"};
    case 14:
      return {CellKind::other_volume, "pyramid"};
    case 21:
      return {CellKind::line, "quadratic edge"};
    case 22:
      return {CellKind::triangle, "quadratic triangle"};
    case 23:
      return {CellKind::quad, "quadratic quad"};
    case 28:
      return {CellKind::quad, "biquadratic quad"};
    case 24:
      return {CellKind::other_volume, "quadratic tetrahedron"};
    case 25:
      return {CellKind::other_volume, "quadratic hexahedron"};
    case 29:
      return {CellKind::other_volume, "triquadratic hexahedron"};
    default:
      return {CellKind::unsupported, nullptr};
  }
}
}  // namespace

RawCell vtk_cell(int vtk_type, std::vector<std::int64_t> nodes, CellOrigin origin) {
  VtkType type = lookup(vtk_type);
  std::string name = type.name ? type.name : fmt::format("{}", vtk_type);
  return RawCell{type.kind, std::move(nodes), origin, std::move(name)};
}

}  // namespace loom
