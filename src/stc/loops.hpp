#pragma once
// Loops: where sheets meet the boundary. A loop is a closed sequence
// edge0 face0 edge1 face1 ... of boundary edges and boundary faces, each face
// entered through one edge and left through the opposite one.
#include <vector>

#include "src/stc/stc.hpp"

namespace loom::stc {

struct Loop {
  Id sheet = no_element;
  std::vector<Id> edges;  ///< boundary edges of the sheet, in order
  std::vector<Id> faces;  ///< faces[i] lies between edges[i] and edges[i+1] (cyclically)
  /// Number of faces the loop passes twice (it crosses itself there).
  std::size_t self_crossings() const;
};

/// Every loop of every sheet, sheets in id order, each loop starting at its
/// smallest boundary edge and leaving through its smaller-id boundary face.
/// A sheet with no boundary edge (a pillow sheet) has no loop.
std::vector<Loop> trace_loops(const Stc& stc);

/// The boundary faces around a boundary edge (two on a closed surface).
std::vector<Id> boundary_faces_of_edge(const Stc& stc, Id edge);

}  // namespace loom::stc
