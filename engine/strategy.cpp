#include "engine/strategy.hpp"

#include <cctype>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "engine/quoted.hpp"
#include "engine/rule_parser.hpp"

namespace loom::engine {

namespace {

constexpr int kMaxDepth = 100;
constexpr std::size_t kMaxSearchDepth = 1000;

struct Word {
  std::string text;
  ast::Pos pos;
};

std::vector<Word> split_words(const std::string& text, const std::string& file) {
  std::vector<Word> words;
  int line = 1, column = 1;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '\n') {
      ++line, column = 1, ++i;
    } else if (c == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      ++column, ++i;
    } else if (c == '{' || c == '}') {
      words.push_back({std::string(1, c), {line, column}});
      ++column, ++i;
    } else if (std::isalnum(static_cast<unsigned char>(c)) || c == '_') {
      Word w{"", {line, column}};
      while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_'))
        w.text += text[i++], ++column;
      words.push_back(std::move(w));
    } else {
      throw RuleError(file, {line, column},
                      fmt::format("unexpected character '{}'; a strategy holds words, numbers and braces",
                                  std::isprint(static_cast<unsigned char>(c)) ? std::string(1, c) : fmt::format("\\x{:02x}", static_cast<unsigned char>(c))));
    }
  }
  return words;
}

class Parser {
public:
  Parser(std::vector<Word> words, std::string file) : words_(std::move(words)), file_(std::move(file)) {
    if (!words_.empty()) end_.pos = words_.back().pos;
  }

  Strategy file() {
    Strategy s;
    s.source = file_;
    while (!at_end()) {
      if (accept("seed")) {
        s.seed = number("a seed");
      } else if (accept("phase")) {
        StrategyPhase p;
        p.name = name("a phase name");
        p.body = block(0);
        s.phases.push_back(std::move(p));
      } else {
        fail(peek(), "expected 'phase' or 'seed'");
      }
    }
    if (s.phases.empty()) fail(end_word(), "a strategy needs at least one 'phase NAME { ... }'");
    return s;
  }

private:
  bool at_end() const { return pos_ >= words_.size(); }
  const Word& end_word() const { return end_; }
  const Word& peek() const { return at_end() ? end_word() : words_[pos_]; }
  bool accept(const char* w) {
    if (at_end() || words_[pos_].text != w) return false;
    ++pos_;
    return true;
  }
  void expect(const char* w) {
    if (!accept(w)) fail(peek(), fmt::format("expected '{}'", w));
  }
  [[noreturn]] void fail(const Word& at, const std::string& what) const {
    throw RuleError(file_, at.pos, fmt::format("{}, found {}", what, quoted(at.text)));
  }
  static bool is_keyword(const std::string& w) {
    for (const char* k : {"apply", "repeat", "try", "else", "backtrack", "phase", "seed", "all", "except", "goal",
                          "window", "branching", "max", "priority", "sequence", "random", "when", "search", "depth", "beam", "cost", "width"})
      if (w == k) return true;
    return false;
  }
  bool at_name() const {
    return !at_end() && words_[pos_].text != "{" && words_[pos_].text != "}" && !is_keyword(words_[pos_].text) &&
           !std::isdigit(static_cast<unsigned char>(words_[pos_].text[0]));
  }
  std::string name(const char* what) {
    if (!at_name()) fail(peek(), fmt::format("expected {}", what));
    return words_[pos_++].text;
  }
  std::uint64_t number(const char* what) {
    const Word& w = peek();
    if (at_end() || !std::isdigit(static_cast<unsigned char>(w.text[0])) || w.text.size() > 18)
      fail(w, fmt::format("expected {} (a non-negative integer)", what));
    for (char c : w.text)
      if (!std::isdigit(static_cast<unsigned char>(c))) fail(w, fmt::format("expected {} (a non-negative integer)", what));
    ++pos_;
    return std::stoull(w.text);
  }

  std::uint64_t positive(const char* what) {
    const Word& w = peek();
    const std::uint64_t v = number(what);
    if (v == 0) fail(w, fmt::format("expected {} of at least 1 (with 0 a search tries nothing)", what));
    return v;
  }

  std::vector<StrategyNode> block(int depth) {
    if (depth > kMaxDepth) fail(peek(), fmt::format("blocks nested more than {} deep", kMaxDepth));
    expect("{");
    std::vector<StrategyNode> nodes;
    while (!accept("}")) {
      if (at_end()) fail(peek(), "expected '}'");
      nodes.push_back(node(depth));
    }
    if (nodes.empty()) fail(words_[pos_ - 1], "an empty block does nothing; write a node in it");
    return nodes;
  }

  struct Setting {
    const char* keyword;
    std::size_t* value;
    const char* what;
    bool positive;  ///< 0 refused
  };

  /// `{ goal MEASURE  SETTING N ...  apply ... }`, the body of a backtrack or a search.
  void goal_block(StrategyNode& n, int depth, const char* node, const char* branches, std::initializer_list<Setting> settings) {
    expect("{");
    const bool has_cost = n.op == StrategyNode::Op::beam;
    for (bool more = true; more;) {
      more = false;
      if (accept("goal")) n.goal = name("a measure"), more = true;
      else if (has_cost && accept("cost")) n.cost = name("a measure"), more = true;
      for (const Setting& s : settings)
        if (!more && accept(s.keyword)) *s.value = s.positive ? positive(s.what) : number(s.what), more = true;
    }
    if (n.goal.empty())
      fail(peek(), fmt::format("{} needs 'goal MEASURE' first (the goal is that the measure reaches 0)", node));
    if (has_cost && n.cost.empty())
      fail(peek(), fmt::format("{} needs 'cost MEASURE' (the states it keeps are those of least cost)", node));
    if (peek().text != "apply")
      fail(peek(), fmt::format("{} takes one 'apply' ({} are that apply's matches)", node, branches));
    n.body.push_back(this->node(depth + 1));
    expect("}");
  }

  StrategyNode node(int depth) {
    StrategyNode n;
    n.pos = peek().pos;
    if (accept("apply")) {
      n.op = StrategyNode::Op::apply;
      if (accept("sequence")) n.pick = StrategyNode::Pick::sequence;
      else if (accept("random")) n.pick = StrategyNode::Pick::random;
      else accept("priority");
      if (accept("all")) {
        n.all = true;
        if (accept("except")) do n.rules.push_back(name("a rule name")); while (at_name());
      } else {
        do n.rules.push_back(name("a rule name or 'all'")); while (at_name());
      }
    } else if (accept("repeat")) {
      n.op = StrategyNode::Op::repeat;
      n.body = block(depth + 1);
    } else if (accept("try")) {
      n.op = StrategyNode::Op::try_else;
      n.body = block(depth + 1);
      if (accept("else")) n.otherwise = block(depth + 1);
    } else if (accept("backtrack")) {
      n.op = StrategyNode::Op::backtrack;
      goal_block(n, depth, "backtrack", "its alternatives",
                 {{"window", &n.window, "a window", false},
                  {"branching", &n.branching, "a branching", false},
                  {"max", &n.max_backtracks, "a number of backtracks", false}});
    } else if (accept("search")) {
      n.op = StrategyNode::Op::search;
      goal_block(n, depth, "search", "its branches",
                 {{"depth", &n.depth, "a depth", true},
                  {"branching", &n.branching, "a branching", true},
                  {"max", &n.max_tried, "a number of applications", true}});
      // A level is a frame of the search's recursion.
      if (n.depth > kMaxSearchDepth)
        throw RuleError(file_, n.pos, fmt::format("a search deeper than {} levels; lower its depth", kMaxSearchDepth));
    } else if (accept("beam")) {
      n.op = StrategyNode::Op::beam;
      goal_block(n, depth, "beam", "its branches",
                 {{"width", &n.width, "a width", true},
                  {"depth", &n.depth, "a depth", true},
                  {"branching", &n.branching, "a branching", true},
                  {"max", &n.max_tried, "a number of applications", true}});
    } else if (accept("when")) {
      n.op = StrategyNode::Op::when;
      n.goal = name("a measure");
    } else {
      fail(peek(), "expected 'apply', 'repeat', 'try', 'backtrack', 'search', 'beam', 'when' or '}'");
    }
    return n;
  }

  std::vector<Word> words_;
  std::string file_;
  Word end_{"end of file", {}};
  std::size_t pos_ = 0;
};

StrategyNode apply_node(StrategyNode::Pick pick, bool all, std::vector<std::string> rules) {
  StrategyNode n;
  n.pick = pick;
  n.all = all;
  n.rules = std::move(rules);
  return n;
}

Strategy builtin(const std::string& source, StrategyNode apply) {
  Strategy s;
  s.source = source;
  StrategyNode repeat;
  repeat.op = StrategyNode::Op::repeat;
  repeat.body.push_back(std::move(apply));
  s.phases.push_back({"main", {std::move(repeat)}});
  return s;
}

}  // namespace

Strategy Strategy::parse_text(const std::string& text, const std::string& file) {
  return Parser(split_words(text, file), file).file();
}

Strategy Strategy::parse(const std::string& spec) {
  if (spec == "priority") return builtin(spec, apply_node(StrategyNode::Pick::priority, true, {}));
  if (spec == "random") return builtin(spec, apply_node(StrategyNode::Pick::random, true, {}));
  if (spec.rfind("sequence:", 0) == 0) {
    std::vector<std::string> names;
    std::stringstream list(spec.substr(9));
    for (std::string n; std::getline(list, n, ',');)
      if (!n.empty()) names.push_back(n);
    if (names.empty()) throw std::invalid_argument("strategy 'sequence:' names no rule; write sequence:seam,cross");
    return builtin(spec, apply_node(StrategyNode::Pick::sequence, false, std::move(names)));
  }
  if (spec == "sequence") throw std::invalid_argument("strategy 'sequence' needs rule names: sequence:seam,cross");
  std::ifstream in(spec, std::ios::binary);
  if (!in)
    throw std::invalid_argument(
        fmt::format("--strategy {}: neither priority, random, sequence:RULE,... nor a readable strategy file", spec));
  std::stringstream text;
  text << in.rdbuf();
  return parse_text(text.str(), spec);
}

bool Strategy::random() const {
  bool any = false;
  for (const auto& p : phases)
    each_node(p.body, [&](const StrategyNode& n) {
      any |= n.op == StrategyNode::Op::apply && n.pick == StrategyNode::Pick::random;
    });
  return any;
}

Strategy Strategy::with_random_picks() const {
  Strategy s = *this;
  for (auto& p : s.phases)
    each_node(p.body, [](StrategyNode& n) {
      if (n.op == StrategyNode::Op::apply && n.pick == StrategyNode::Pick::priority) n.pick = StrategyNode::Pick::random;
    });
  if (s.source.find("random picks") == std::string::npos) s.source += " (random picks)";
  return s;
}

Strategy Strategy::without_backtracking() const {
  Strategy s = *this;
  for (auto& p : s.phases)
    each_node(p.body, [](StrategyNode& n) {
      if (n.op != StrategyNode::Op::backtrack) return;
      StrategyNode plain;
      plain.op = StrategyNode::Op::repeat;
      plain.pos = n.pos;
      plain.body = std::move(n.body);
      n = std::move(plain);
    });
  if (s.source.find("no backtracking") == std::string::npos) s.source += " (no backtracking)";
  return s;
}

}  // namespace loom::engine
