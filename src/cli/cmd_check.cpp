// `loom check HEXMESH [--boundary SURFACE] [--json] [--plot FILE.svg]`: is this an accepted hex
// mesh (docs/validity.md)? Exit 0 valid, 1 not valid, 2 bad input.
#include <iostream>
#include <optional>

#include "src/check/quality_histogram.hpp"
#include "src/check/validity.hpp"
#include "src/check/verdict.hpp"
#include "src/cli/command.hpp"
#include "src/io/hex_io.hpp"
#include "src/io/surface_io.hpp"
#include "src/util/atomic_file.hpp"
#include "src/util/error.hpp"

namespace {

struct Options {
  std::string mesh;
  std::string boundary;
  std::string plot;
  bool json = false;
};

int run(const Options& o) {
  const loom::HexMesh mesh = loom::read_hex_mesh(o.mesh);
  if (mesh.hexes.empty())
    loom::fail_input(o.mesh, "contains no hexahedra, so there is nothing to check", "give a hex mesh file");
  std::optional<loom::QuadSurface> boundary;
  if (!o.boundary.empty()) {
    boundary = loom::read_surface(o.boundary);
    if (boundary->quads.empty())
      loom::fail_input(o.boundary, "contains no quads", "give the quad surface the mesh should be bounded by");
  }
  const loom::ValidityReport report = loom::check_hex_mesh(mesh, boundary ? &*boundary : nullptr);
  const loom::QualityHistogram histogram = loom::quality_histogram(mesh);
  if (!o.plot.empty()) loom::write_text_atomically(o.plot, loom::histogram_svg(histogram, "loom check " + o.mesh));
  if (o.json) {
    nlohmann::json j = loom::validity_json(report);
    j["scaled_jacobian_histogram"] = loom::histogram_json(histogram);
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << loom::verdict_line(report) << "\n";
  }
  return report.valid() ? 0 : 1;
}

loom::cli::Register reg{
    {"check", [](CLI::App& app) {
       auto o = std::make_shared<Options>();
       app.description(
           "Check a hex mesh against the validity criteria (docs/validity.md) and print one verdict line; "
           "exit 0 valid, 1 invalid, 2 bad input");
       app.add_option("HEXMESH", o->mesh, "hex mesh (.vtk .vtu .msh)")->required()->check(CLI::ExistingFile);
       app.add_option("--boundary", o->boundary,
                      "quad surface (.obj .off .vtk .vtu .msh) whose quads must be exactly the mesh's boundary faces")
           ->check(CLI::ExistingFile);
       app.add_flag("--json", o->json, "print a JSON object instead of the verdict line");
       app.add_option("--plot", o->plot, "also write a bar chart (SVG) of the scaled Jacobians to this file");
       return std::function<int()>([o] { return run(*o); });
     }}};

}  // namespace
