#include "src/io/msh_element_types.hpp"

namespace loom {

std::optional<MshElementType> msh_element_type(int type) {
  switch (type) {
    case 1:
      return MshElementType{1, 2, "2-node line"};
    case 2:
      return MshElementType{2, 3, "3-node triangle"};
    case 3:
      return MshElementType{2, 4, "4-node quadrangle"};
    case 4:
      return MshElementType{3, 4, "4-node tetrahedron"};
    case 5:
      return MshElementType{3, 8, "8-node hexahedron"};
    case 6:
      return MshElementType{3, 6, "6-node prism"};
    case 7:
      return MshElementType{3, 5, "5-node pyramid"};
    case 8:
      return MshElementType{1, 3, "3-node line"};
    case 9:
      return MshElementType{2, 6, "6-node triangle"};
    case 10:
      return MshElementType{2, 9, "9-node quadrangle"};
    case 11:
      return MshElementType{3, 10, "10-node tetrahedron"};
    case 12:
      return MshElementType{3, 27, "27-node hexahedron"};
    case 13:
      return MshElementType{3, 18, "18-node prism"};
    case 14:
      return MshElementType{3, 14, "14-node pyramid"};
    case 15:
      return MshElementType{0, 1, "point"};
    case 16:
      return MshElementType{2, 8, "8-node quadrangle"};
    case 17:
      return MshElementType{3, 20, "20-node hexahedron"};
    case 18:
      return MshElementType{3, 15, "15-node prism"};
    case 19:
      return MshElementType{3, 13, "13-node pyramid"};
    default:
      return std::nullopt;
  }
}

CellKind msh_cell_kind(int type, int dimension) {
  switch (dimension) {
    case 0:
      return CellKind::vertex;
    case 1:
      return CellKind::line;
    case 2:
      return type == 3 ? CellKind::quad : type == 2 ? CellKind::triangle : CellKind::polygon;
    case 3:
      return type == 5 ? CellKind::hexahedron : CellKind::other_volume;
    default:
      return CellKind::unsupported;
  }
}

}  // namespace loom
