// Loading rule files: a file's text, or every *.rule file of a directory.
#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include "engine/rule_compiler.hpp"
#include "engine/rule_parser.hpp"

namespace loom::engine {

std::vector<Rule> compile_rules(const std::string& text, const std::string& file, const Schema& schema) {
  std::vector<Rule> out;
  for (const auto& r : parse_rules(text, file)) out.push_back(compile_rule(r, schema));
  return out;
}

std::vector<Rule> load_rule_dir(const std::filesystem::path& dir, const Schema& schema) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw RuleError(dir.string(), {}, "no such rule directory; pass --rules DIR with the rule files (*.rule)");
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path().extension() == ".rule") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  std::vector<Rule> rules;
  std::map<std::string, std::string> seen;
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    if (!in) throw RuleError(f.string(), {}, "cannot read the rule file");
    for (auto& r : compile_rules(text.str(), f.string(), schema)) {
      if (auto [it, fresh] = seen.emplace(r.name, f.string()); !fresh)
        throw RuleError(f.string(), {}, fmt::format("rule '{}' is also defined in {}", r.name, it->second));
      rules.push_back(std::move(r));
    }
  }
  if (rules.empty()) throw RuleError(dir.string(), {}, "no *.rule file in the rule directory");
  return rules;
}

}  // namespace loom::engine
