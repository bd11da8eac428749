// `loom mesh PART -o HEXMESH [--size H]`: a CAD part (STEP, IGES, BREP, .geo)
// to a hex mesh. Gmsh meshes the part's boundary free and all-quad with an even
// count (cad/cad_part.hpp), then the run is `loom weave`'s (weave_command.hpp).
#include <iostream>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "src/cad/cad_part.hpp"
#include "src/check/surface_angle_bound.hpp"
#include "src/cli/command.hpp"
#include "src/cli/weave_command.hpp"
#include "src/io/mesh_format.hpp"
#include "src/io/surface_io.hpp"
#include "src/mesh/surface_validation.hpp"

namespace {

struct MeshOptions {
  std::optional<double> size;
  std::string surface;
};

loom::QuadSurface part_surface(const loom::cli::WeaveCommandOptions& o, const MeshOptions& m,
                               loom::cli::RunBudget& budget) {
  if (!m.surface.empty()) loom::surface_format_of(m.surface);  // refused before Gmsh's work
  budget.stage("meshing the part's boundary with Gmsh");
  loom::cad::PartSurface part = loom::cad::quad_surface_of_part(o.input, m.size);
  const loom::SurfaceSummary summary = loom::validate_surface(part.surface, o.input);
  if (!o.quiet) {
    const loom::SurfaceAngleBound bound = loom::surface_angle_bound(part.surface);
    const std::string refined =
        part.refinement_balls > 0 ? fmt::format(", made finer in {} balls round slivers", part.refinement_balls)
        : part.meshings > 1       ? std::string(", made no better by finer meshes round its slivers")
                                  : std::string();
    std::cerr << fmt::format("{}: {} faces meshed by Gmsh into {} quads (size {:.4g}, the diagonal {:.4g} / {:.3g}{}; "
                             "least corner sine {:.3g}); genus {}\n",
                             o.input, part.faces, part.surface.quads.size(), part.size, part.diagonal,
                             part.diagonal / part.size, refined, bound.least_sine, summary.genus);
  }
  if (!m.surface.empty()) loom::write_surface(m.surface, part.surface);
  return std::move(part.surface);
}

loom::cli::Register reg{{"mesh", [](CLI::App& app) {
  auto o = std::make_shared<loom::cli::WeaveCommandOptions>();
  auto m = std::make_shared<MeshOptions>();
  app.description("Mesh a CAD part's boundary all-quad with Gmsh, then weave a hex mesh bounded by it");
  app.add_option("PART", o->input, fmt::format("one closed solid ({})", fmt::join(loom::cad::kCadExtensions, " ")))
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--size", m->size,
                 fmt::format("the quads' edge length (default: the part's bounding-box diagonal / {})",
                             loom::cad::kDefaultDivisions))
      ->check(CLI::PositiveNumber);
  app.add_option("--surface", m->surface,
                 "also write the quad surface Gmsh made to this file (.obj .off .vtk .vtu .msh), as soon as it is "
                 "made: 'loom weave' takes it");
  loom::cli::add_weave_options(app, *o);
  return std::function<int()>([o, m] {
    return loom::cli::run_weave(*o, [&](loom::cli::RunBudget& budget) { return part_surface(*o, *m, budget); });
  });
}}};

}  // namespace
