// `loom gen KIND ARGS... -o FILE`: writes a test input (docs/generators.md).
#include <fmt/format.h>

#include <charconv>
#include <iostream>
#include <variant>

#include "src/cli/command.hpp"
#include "src/gen/catalog.hpp"
#include "src/io/hex_io.hpp"
#include "src/io/mesh_format.hpp"
#include "src/io/surface_io.hpp"
#include "src/io/text_scanner.hpp"
#include "src/util/error.hpp"

namespace {

struct Options {
  std::string kind;
  std::vector<std::string> args;
  std::string output;
  std::string seed, size;  ///< named forms of the sizes S and K
};

/// `randquad F --seed S` and `KIND ... --size K` (K defaults to 1) name their
/// last size; the positional form works too.
void fill_named_sizes(const loom::gen::GeneratorKind& kind, Options& o) {
  while (o.args.size() < kind.params.size()) {
    const std::string& param = kind.params[o.args.size()];
    if (param == "S" && !o.seed.empty()) o.args.push_back(o.seed);
    else if (param == "K") o.args.push_back(o.size.empty() ? "1" : o.size);
    else break;
  }
}

std::string kinds_list() {
  std::vector<std::string> names;
  for (const auto& k : loom::gen::generator_kinds()) names.push_back(k.name);
  return fmt::format("{}", fmt::join(names, ", "));
}

int parse_size(const loom::gen::GeneratorKind& kind, const std::string& param, const std::string& text) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size())
    loom::fail_input("gen " + kind.name, fmt::format("{} must be a whole number, got {}", param, loom::quote_token(text)),
                     fmt::format("usage: loom gen {} -o FILE", loom::gen::usage(kind)));
  return value;
}

int run(Options o) {
  const auto* kind = loom::gen::find_generator_kind(o.kind);
  if (!kind) loom::fail_input("gen", fmt::format("unknown kind {}", loom::quote_token(o.kind)), "choose one of " + kinds_list());
  fill_named_sizes(*kind, o);
  if (o.args.size() != kind->params.size())
    loom::fail_input("gen " + kind->name,
                     fmt::format("expects {} argument{}, got {}", kind->params.size(),
                                 kind->params.size() == 1 ? "" : "s", o.args.size()),
                     fmt::format("usage: loom gen {} -o FILE", loom::gen::usage(*kind)));
  std::vector<int> sizes;
  for (std::size_t i = 0; i < o.args.size(); ++i) sizes.push_back(parse_size(*kind, kind->params[i], o.args[i]));
  // Reject an unusable output name before generating anything.
  if (kind->hex_mesh)
    loom::hex_format_of(o.output);
  else
    loom::surface_format_of(o.output);

  const loom::gen::GeneratedMesh mesh = kind->make(sizes);
  const std::string made = fmt::format("{}", fmt::join(o.args, " "));
  const std::string what = made.empty() ? kind->name : kind->name + " " + made;
  if (const auto* surface = std::get_if<loom::QuadSurface>(&mesh)) {
    loom::write_surface(o.output, *surface);
    std::cout << fmt::format("wrote {}: surface {}, {} quads, {} nodes\n", o.output, what, surface->quads.size(),
                             surface->points.size());
  } else {
    const auto& hexes = std::get<loom::HexMesh>(mesh);
    loom::write_hex_mesh(o.output, hexes);
    std::cout << fmt::format("wrote {}: hex mesh {}, {} hexes, {} nodes\n", o.output, what, hexes.hexes.size(),
                             hexes.points.size());
  }
  return 0;
}

std::string kinds_help() {
  std::string text = "Kinds:\n";
  for (const auto& k : loom::gen::generator_kinds())
    text += fmt::format("  {:<16} {}{}\n", loom::gen::usage(k), k.summary, k.hex_mesh ? " [hex mesh]" : "");
  return text + "Surfaces: .obj .off .vtk .vtu .msh; hex meshes: .vtk .vtu .msh .exo .e";
}

loom::cli::Register reg{
    {"gen", [](CLI::App& app) {
       auto o = std::make_shared<Options>();
       app.description("Write a test input: a closed quad surface or a structured hex mesh");
       app.add_option("KIND", o->kind, "what to make (listed below)")->required();
       app.add_option("ARGS", o->args, "the kind's whole-number sizes");
       app.add_option("-o,--output", o->output, "file to write; the format follows the extension")->required();
       app.add_option("--seed", o->seed, "the seed S of randquad");
       app.add_option("--size", o->size, "the size K of bosses, bosses-free, plate and ring (default 1)");
       app.footer(kinds_help());
       return std::function<int()>([o] { return run(*o); });
     }}};

}  // namespace
