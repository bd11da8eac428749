// `loom weave SURFACE -o HEXMESH [...]`: the whole pipeline, quad surface in,
// hex mesh out (weave_command.hpp; docs/cli.md).
#include <memory>

#include "src/cli/command.hpp"
#include "src/cli/weave_command.hpp"
#include "src/io/surface_io.hpp"
#include "src/mesh/surface_validation.hpp"

namespace {

loom::cli::Register reg{{"weave", [](CLI::App& app) {
  auto o = std::make_shared<loom::cli::WeaveCommandOptions>();
  auto weld = std::make_shared<bool>(false);
  app.description("Weave a hex mesh whose boundary is exactly the given closed quad surface");
  app.add_option("SURFACE", o->input, "closed all-quad surface (.obj .off .vtk .vtu .msh)")->required()->check(CLI::ExistingFile);
  loom::cli::add_weave_options(app, *o);
  app.add_flag("--weld", *weld, "merge coincident surface nodes instead of rejecting them");
  return std::function<int()>([o, weld] {
    return loom::cli::run_weave(*o, [&](loom::cli::RunBudget&) {
      loom::QuadSurface surface = loom::read_surface(o->input);
      loom::validate_surface(surface, o->input, {.weld = *weld});
      return surface;
    });
  });
}}};

}  // namespace
