#include "engine/strategy.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

namespace loom::engine {

namespace {
Strategy::Kind kind_named(const std::string& name, const std::string& where) {
  if (name == "priority") return Strategy::Kind::priority;
  if (name == "sequence") return Strategy::Kind::sequence;
  if (name == "random") return Strategy::Kind::random;
  throw std::invalid_argument(fmt::format("{}: unknown strategy '{}'; use priority, sequence or random", where, name));
}
}  // namespace

Strategy Strategy::parse(const std::string& spec) {
  Strategy s;
  if (spec.rfind("sequence:", 0) == 0) {
    s.kind = Kind::sequence;
    std::stringstream names(spec.substr(9));
    for (std::string n; std::getline(names, n, ',');)
      if (!n.empty()) s.order.push_back(n);
    if (s.order.empty()) throw std::invalid_argument("strategy 'sequence:' names no rule; write sequence:seam,cross");
    return s;
  }
  if (spec == "priority" || spec == "sequence" || spec == "random") {
    s.kind = kind_named(spec, "--strategy");
    if (s.kind == Kind::sequence) throw std::invalid_argument("strategy 'sequence' needs rule names: sequence:seam,cross");
    return s;
  }
  std::ifstream in(spec);
  if (!in) throw std::invalid_argument(fmt::format("--strategy {}: neither priority, sequence:..., random nor a readable strategy file", spec));
  int line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    line = line.substr(0, line.find('#'));
    std::stringstream words(line);
    std::string key;
    if (!(words >> key)) continue;
    std::string where = fmt::format("{}:{}", spec, line_no);
    if (key == "strategy") {
      std::string k;
      words >> k;
      s.kind = kind_named(k, where);
    } else if (key == "order") {
      for (std::string n; words >> n;) s.order.push_back(n);
    } else if (key == "seed") {
      if (!(words >> s.seed)) throw std::invalid_argument(where + ": 'seed' needs a non-negative integer");
    } else {
      throw std::invalid_argument(fmt::format("{}: expected 'strategy', 'order' or 'seed', found '{}'", where, key));
    }
  }
  if (s.kind == Kind::sequence && s.order.empty())
    throw std::invalid_argument(spec + ": a sequence strategy needs an 'order' line naming rules");
  return s;
}

std::string Strategy::name() const {
  switch (kind) {
    case Kind::priority: return "priority";
    case Kind::random: return "random";
    case Kind::sequence: {
      std::string n = "sequence:";
      for (std::size_t i = 0; i < order.size(); ++i) n += (i ? "," : "") + order[i];
      return n;
    }
  }
  return "";
}

}  // namespace loom::engine
