#include "tests/fuzz/fuzz_targets.hpp"


#include <array>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "engine/rewriter.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_parser.hpp"
#include "engine/schema_file.hpp"
#include "engine/strategy.hpp"
#include "src/closure/database.hpp"
#include "src/fill/cap.hpp"
#include "src/io/formats.hpp"
#include "src/mesh/surface_validation.hpp"
#include "src/stc/stc.hpp"
#include "src/util/error.hpp"
#include "src/util/one_line.hpp"
#include "src/weave/weave.hpp"

namespace loom::fuzz {

namespace {

using Parser = RawMesh (*)(std::string_view text, const std::string& where);

// A mesh file goes where read_surface() and read_hex_mesh() take it: the
// format's parser, then the checks common to all formats, then (for a
// surface) validate_surface(), as `loom weave` and `loom stc` do. Welding is
// on for inputs of odd length, so that both of its paths are fed.
Outcome read_mesh(Parser parse, std::string_view bytes, const std::string& where) {
  try {
    RawMesh raw = parse(bytes, where);
    RawMesh copy = raw;
    try {
      to_hex_mesh(std::move(copy), where);
    } catch (const InputError&) {
    }
    QuadSurface surface = to_quad_surface(std::move(raw), where);
    validate_surface(surface, where, {.weld = bytes.size() % 2 == 1});
    return std::nullopt;
  } catch (const InputError& e) {
    return e.what();
  }
}

Outcome obj(std::string_view bytes) { return read_mesh(parse_obj, bytes, "fuzz.obj"); }
Outcome off(std::string_view bytes) { return read_mesh(parse_off, bytes, "fuzz.off"); }
Outcome vtk(std::string_view bytes) { return read_mesh(parse_legacy_vtk, bytes, "fuzz.vtk"); }
Outcome vtu(std::string_view bytes) { return read_mesh(parse_vtu, bytes, "fuzz.vtu"); }
// Only our ASCII parser: a binary file (file type 1) goes to Gmsh in a forked
// child, which is not fuzzed in process (docs/fuzzing.md). The parser itself
// ignores the file type, so every header reaches it.
Outcome msh(std::string_view bytes) { return read_mesh(parse_msh_ascii, bytes, "fuzz.msh"); }

// As `loom rules list FILE` loads a rule file: parse, compile against the STC
// schema, and check every action call against the weave's actions.
Outcome rules(std::string_view bytes) {
  static stc::Stc scratch;
  static const engine::Actions actions = weave::weave_actions(scratch);
  const auto& schema = *stc::StcSchema::get().schema;
  try {
    for (const auto& rule : engine::compile_rules(std::string(bytes), "fuzz.rule", schema))
      engine::check_actions(rule, actions, schema);
    return std::nullopt;
  } catch (const engine::RuleError& e) {
    return e.what();
  }
}

Outcome schema(std::string_view bytes) {
  try {
    engine::parse_schema(std::string(bytes), "fuzz-schema.txt");
    return std::nullopt;
  } catch (const engine::RuleError& e) {
    return e.what();
  }
}

Outcome cap(std::string_view bytes) {
  try {
    fill::parse_cap(bytes, "fuzz.cap");
    return std::nullopt;
  } catch (const InputError& e) {
    return e.what();
  }
}

Outcome database(std::string_view bytes) {
  try {
    closure::Database::parse(bytes, "fuzz-database.txt");
    return std::nullopt;
  } catch (const InputError& e) {
    return e.what();
  }
}

Outcome strategy(std::string_view bytes) {
  try {
    engine::Strategy::parse_text(std::string(bytes), "fuzz.strategy");
    return std::nullopt;
  } catch (const engine::RuleError& e) {
    return e.what();
  }
}

constexpr std::array<Target, 10> all_targets{{
    {"obj", obj, 4096},
    {"off", off, 4096},
    {"vtk", vtk, 4096},
    {"vtu", vtu, 4096},
    {"msh", msh, 4096},
    {"rules", rules, 4096},
    {"schema", schema, 1024},
    {"cap", cap, 4096},
    {"database", database, 4096},
    {"strategy", strategy, 4096},
}};

}  // namespace

std::span<const Target> targets() { return all_targets; }

const Target* find_target(std::string_view name) {
  for (const Target& t : all_targets)
    if (t.name == name) return &t;
  return nullptr;
}

bool is_one_printable_line(std::string_view message) { return !message.empty() && one_line(message) == message; }

int run_for_fuzzer(const Target& target, const std::uint8_t* data, std::size_t size) {
  Outcome outcome = target.run({reinterpret_cast<const char*>(data), size});
  if (outcome && target.checks_message && !is_one_printable_line(*outcome)) {
    std::fprintf(stderr, "fuzz_%.*s: the error message is not one printable line: %s\n",
                 static_cast<int>(target.name.size()), target.name.data(), one_line(*outcome).c_str());
    std::abort();
  }
  return 0;
}

#define LOOM_FUZZ_ENTRY(name)                                   \
  int fuzz_##name(const std::uint8_t* data, std::size_t size) { \
    return run_for_fuzzer(*find_target(#name), data, size);     \
  }
LOOM_FUZZ_ENTRY(obj)
LOOM_FUZZ_ENTRY(off)
LOOM_FUZZ_ENTRY(vtk)
LOOM_FUZZ_ENTRY(vtu)
LOOM_FUZZ_ENTRY(msh)
LOOM_FUZZ_ENTRY(rules)
LOOM_FUZZ_ENTRY(schema)
LOOM_FUZZ_ENTRY(cap)
LOOM_FUZZ_ENTRY(database)
LOOM_FUZZ_ENTRY(strategy)
#undef LOOM_FUZZ_ENTRY

}  // namespace loom::fuzz
