#pragma once
// Compiling parsed rules against a schema: names resolved, the pattern turned
// into a search plan from its anchor, the rewrite into graph operations.
// Errors are RuleErrors at the offending file:line:column.
#include <filesystem>
#include <string>
#include <vector>

#include "engine/rule.hpp"
#include "engine/rule_ast.hpp"
#include "engine/schema.hpp"

namespace loom::engine {

Rule compile_rule(const ast::Rule& rule, const Schema& schema);

/// Parses and compiles every rule in `text`.
std::vector<Rule> compile_rules(const std::string& text, const std::string& file, const Schema& schema);

/// Loads every `*.rule` file of `dir`, in file-name order. Throws RuleError
/// for a broken file, and for two rules with one name.
std::vector<Rule> load_rule_dir(const std::filesystem::path& dir, const Schema& schema);

/// The search plan as text, one operation a line (`loom rules explain`).
std::string explain(const Rule& rule, const Schema& schema);

}  // namespace loom::engine
