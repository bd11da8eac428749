#pragma once
// What `loom weave` and `loom mesh` say of a run beside the mesh: the JSON
// report (--report, keys in docs/cli.md) and the cell fields every written mesh
// carries.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "src/check/depth.hpp"
#include "src/check/surface_angle_bound.hpp"
#include "src/io/cell_table.hpp"
#include "src/pipeline/mesh_surface.hpp"

namespace loom::cli {

/// What the report says of the surface itself, before any hex.
struct SurfaceFigures {
  SurfaceAngleBound bound;
  SurfaceThickness half_thickness;
};

/// The report of a run on `input` (the path the user gave), whose surface has `surface`.
nlohmann::json report_json(const std::string& input, const SurfaceFigures& surface, const pipeline::MeshingResult& r);

/// Where each hex came from (0 woven, 1 searched, 2 database, 3 filled,
/// 4 pillow), its scaled Jacobian (the minimum over its corners, as criterion 7
/// measures it), and the three sheets it lies on (those its edges 0-1, 0-3 and
/// 0-4 cross; check/hex_sheets.hpp), and why it is inverted (`inversions`, of
/// this mesh).
std::vector<CellField> cell_fields(const HexMesh& mesh, const std::vector<closure::HexSource>& sources,
                                   const geometry::InversionDiagnosis& inversions);

}  // namespace loom::cli
