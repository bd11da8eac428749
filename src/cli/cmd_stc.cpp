// `loom stc MESH [--dot DIR] [--json] [--weld]`: the STC of a hex mesh (its
// dual) or of a surface (the initial weave state), its counts and diagrams.
#include <iostream>
#include <variant>

#include <fmt/format.h>

#include "src/check/validity.hpp"
#include "src/cli/command.hpp"
#include "src/io/any_mesh.hpp"
#include "src/mesh/surface_validation.hpp"
#include "src/stc/build.hpp"
#include "src/stc/sheet_diagram.hpp"
#include "src/stc/summary.hpp"
#include "src/util/error.hpp"

namespace {

struct Options {
  std::string mesh;
  std::string dot_dir;
  bool json = false;
  bool weld = false;
  bool no_svg = false;
};

// The dual is only defined for a cell complex: a corrupt mesh (a face in three
// hexes, a degenerate hex, hexes meeting along an edge only) would break the
// construction or the loop tracing. Geometry (criterion 7) does not matter here.
void require_combinatorially_valid(const loom::HexMesh& mesh, const std::string& file) {
  const loom::ValidityReport report = loom::check_hex_mesh(mesh);
  if (report.combinatorial_valid()) return;
  const loom::CriterionResult& failed = *report.first_failure();
  loom::fail_input(file,
                   fmt::format("not a valid hex mesh, so it has no STC: criterion {} ({}) fails: {}", failed.number,
                               failed.name, failed.detail),
                   fmt::format("run 'loom check {}' to see every criterion, and fix the mesh", file));
}

// One line per meridian: a basis of the cycles that bound inside the solid.
std::string meridian_lines(const loom::SurfaceSummary& checked) {
  if (checked.genus == 0) return "";
  if (!checked.meridians_known)
    return "meridians: not determined (the linking numbers of the surface's cycles could not be trusted; does the "
           "surface meet itself?)\n";
  std::string lines;
  for (const auto& cycle : checked.meridians) lines += fmt::format("meridian {}\n", loom::describe_cycle(cycle));
  return lines;
}

int run(const Options& o) {
  auto mesh = loom::read_surface_or_hex_mesh(o.mesh);
  bool surface = std::holds_alternative<loom::QuadSurface>(mesh);
  loom::stc::Stc stc;
  loom::SurfaceSummary checked;
  if (surface) {
    auto& s = std::get<loom::QuadSurface>(mesh);
    checked = loom::validate_surface(s, o.mesh, {.weld = o.weld});
    stc = loom::stc::build_from_surface(s);
  } else {
    require_combinatorially_valid(std::get<loom::HexMesh>(mesh), o.mesh);
    stc = loom::stc::build_from_hex_mesh(std::get<loom::HexMesh>(mesh));
  }
  auto summary = loom::stc::summarize(stc);
  loom::stc::PictureFailures failures;
  std::size_t files = o.dot_dir.empty() ? 0 : loom::stc::write_stc_dot(stc, o.dot_dir, failures, o.no_svg ? 0 : 4000);
  if (failures.count) std::cerr << failures.warning() << "\n";
  if (o.json) {
    auto j = loom::stc::to_json(summary);
    j["input"] = surface ? "surface" : "hex mesh";
    if (surface) {
      j["genus"] = checked.genus;
      if (checked.meridians_known) {
        j["meridians"] = nlohmann::json::array();
        for (const auto& cycle : checked.meridians) j["meridians"].push_back({{"length", cycle.size()}, {"nodes", cycle}});
      } else {
        j["meridians"] = nullptr;
      }
    }
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << loom::stc::to_text(summary, surface);
    if (surface) std::cout << fmt::format("genus {}\n", checked.genus) << meridian_lines(checked);
    if (files) std::cout << fmt::format("wrote {} DOT/SVG files to {}\n", files, o.dot_dir);
  }
  return 0;
}

loom::cli::Register reg{{"stc", [](CLI::App& app) {
  auto o = std::make_shared<Options>();
  app.description("Build the STC of a hex mesh (its dual) or of a quad surface (the initial weave) and report it");
  app.add_option("MESH", o->mesh, "hex mesh or quad surface (.obj .off .vtk .vtu .msh)")->required()->check(CLI::ExistingFile);
  app.add_option("--dot", o->dot_dir, "write stc.dot and sheet-K.dot (with .svg) into this directory");
  app.add_flag("--no-svg", o->no_svg, "write DOT files only, no SVG");
  app.add_flag("--json", o->json, "print the counts as JSON");
  app.add_flag("--weld", o->weld, "merge coincident surface nodes instead of rejecting them");
  return std::function<int()>([o] { return run(*o); });
}}};

}  // namespace
