// `loom rules explain FILE|DIR` and `loom rules list [DIR]`: what the engine
// makes of rule files, without weaving anything.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <fmt/format.h>

#include "engine/rule_compiler.hpp"
#include "engine/rule_parser.hpp"
#include "src/cli/command.hpp"
#include "src/stc/stc.hpp"
#include "src/util/error.hpp"
#include "src/weave/weave.hpp"

namespace {

std::vector<loom::engine::Rule> load(const std::string& path) {
  const auto& schema = *loom::stc::StcSchema::get().schema;
  try {
    std::vector<loom::engine::Rule> rules;
    if (path.empty() || std::filesystem::is_directory(path)) {
      rules = loom::engine::load_rule_dir(path.empty() ? loom::weave::default_rules_dir() : std::filesystem::path(path), schema);
    } else {
      std::ifstream in(path);
      if (!in) throw loom::InputError(path + ": cannot read the rule file; check the path");
      std::stringstream text;
      text << in.rdbuf();
      rules = loom::engine::compile_rules(text.str(), path, schema);
    }
    loom::stc::Stc scratch;
    auto actions = loom::weave::weave_actions(scratch);
    for (const auto& r : rules) loom::engine::check_actions(r, actions, schema);
    return rules;
  } catch (const loom::engine::RuleError& e) {
    throw loom::InputError(std::string(e.what()) + "; fix the rule file (grammar: docs/rules.md)");
  }
}

loom::cli::Register reg{{"rules", [](CLI::App& app) {
  app.description("Inspect rule files: their search plans and priorities");
  app.require_subcommand(1);
  auto path = std::make_shared<std::string>();
  auto* explain = app.add_subcommand("explain", "print the search plan of every rule in a file or directory");
  explain->add_option("FILE", *path, "a .rule file or a directory of them (default: the shipped rules)");
  auto* list = app.add_subcommand("list", "list the rules of a directory with their priorities");
  list->add_option("DIR", *path, "a directory of .rule files (default: the shipped rules)");
  return std::function<int()>([path, explain] {
    auto rules = load(*path);
    const auto& schema = *loom::stc::StcSchema::get().schema;
    std::size_t width = 16;
    for (const auto& r : rules) width = std::max(width, r.name.size());
    for (const auto& r : rules) {
      if (explain->parsed()) std::cout << loom::engine::explain(r, schema) << "\n";
      else std::cout << fmt::format("{:<{}} priority {:>4}  {}\n", r.name, width, r.priority, r.file);
    }
    return 0;
  });
}}};

}  // namespace
