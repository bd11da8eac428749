#pragma once
// The kinds `loom gen` knows: name, arguments, what each makes. The CLI and
// its help text are driven by this table (docs/generators.md describes it).
#include <functional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "src/mesh/hex_mesh.hpp"
#include "src/mesh/quad_surface.hpp"

namespace loom::gen {

using GeneratedMesh = std::variant<QuadSurface, HexMesh>;

struct GeneratorKind {
  std::string name;
  std::vector<std::string> params;  ///< integer arguments in order, e.g. {"A", "B", "C"}
  std::string summary;              ///< one line for --help
  bool hex_mesh = false;            ///< writes a hex mesh (else a surface)
  std::function<GeneratedMesh(const std::vector<int>& args)> make;  ///< args.size() == params.size()
};

/// Every kind, in the order --help lists them.
const std::vector<GeneratorKind>& generator_kinds();

/// The kind called `name`, or nullptr.
const GeneratorKind* find_generator_kind(std::string_view name);

/// "box A B C" style usage of a kind.
std::string usage(const GeneratorKind& kind);

}  // namespace loom::gen
