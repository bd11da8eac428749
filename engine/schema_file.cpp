#include "engine/schema_file.hpp"

#include <algorithm>
#include <cctype>
#include <climits>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "engine/quoted.hpp"
#include "engine/rule_parser.hpp"

namespace loom::engine {

namespace {

struct Word {
  std::string text;
  int column = 0;
};

std::vector<Word> words_of(const std::string& line) {
  std::vector<Word> out;
  for (std::size_t i = 0; i < line.size();) {
    if (line[i] == '#') break;
    if (std::isspace(static_cast<unsigned char>(line[i]))) {
      ++i;
      continue;
    }
    std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i])) && line[i] != '#') ++i;
    out.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
  }
  return out;
}

class LineParser {
public:
  LineParser(Schema& schema, const std::string& file, int line, std::vector<Word> words)
      : schema_(schema), file_(file), line_(line), words_(std::move(words)) {}

  void run() {
    const std::string& key = next("'kind', 'port' or 'attribute'").text;
    if (key == "kind") {
      const Word& name = next("a kind name");
      declare([&] { schema_.add_kind(name.text); }, name);
    } else if (key == "port") {
      const Member m = member();
      const Word& arity_word = next("the port's number of slots");
      unsigned arity = number(arity_word);
      PortOrder order = PortOrder::ordered;
      PortPresence presence = PortPresence::optional;
      for (;;) {
        const Word& w = next("'cyclic', 'required' or '->'");
        if (w.text == "cyclic") order = PortOrder::cyclic;
        else if (w.text == "required") presence = PortPresence::required;
        else if (w.text == "->") break;
        else fail(w, fmt::format("expected 'cyclic', 'required' or '->', found {}", quoted(w.text)));
      }
      const Word& target = next("the kind the port points at");
      KindId to = kind(target);
      declare([&] { schema_.add_port(m.owner, m.name, arity, to, order, presence); }, m.at);
    } else if (key == "attribute") {
      const Member m = member();
      std::int32_t value = 0;
      if (pos_ < words_.size()) {
        const Word& w = words_[pos_++];
        try {
          std::size_t used = 0;
          long long v = std::stoll(w.text, &used);
          if (used != w.text.size() || v < INT32_MIN || v > INT32_MAX) throw std::out_of_range(w.text);
          value = static_cast<std::int32_t>(v);
        } catch (const std::logic_error&) {
          fail(w, fmt::format("expected a 32-bit integer default, found {}", quoted(w.text)));
        }
      }
      declare([&] { schema_.add_attribute(m.owner, m.name, value); }, m.at);
    } else {
      fail(words_.front(), fmt::format("expected 'kind', 'port' or 'attribute', found {}", quoted(key)));
    }
    if (pos_ < words_.size())
      fail(words_[pos_], fmt::format("unexpected {} at the end of the line", quoted(words_[pos_].text)));
  }

private:
  [[noreturn]] void fail(const Word& at, const std::string& what) const {
    throw RuleError(file_, {line_, at.column}, what);
  }
  const Word& next(const std::string& expected) {
    if (pos_ >= words_.size()) {
      Word end{"", words_.empty() ? 1 : words_.back().column + static_cast<int>(words_.back().text.size())};
      fail(end, fmt::format("expected {}, found the end of the line", expected));
    }
    return words_[pos_++];
  }
  KindId kind(const Word& w) const {
    auto k = schema_.find_kind(w.text);
    if (!k)
      fail(w, fmt::format("unknown kind {} (declare it first with 'kind {}')", quoted(w.text),
                          printable(w.text.substr(0, 40))));
    return *k;
  }
  unsigned number(const Word& w) const {
    const auto digit = [](char c) { return c >= '0' && c <= '9'; };  // ::isdigit(char) is UB past ASCII
    if (w.text.empty() || w.text.size() > 3 || !std::all_of(w.text.begin(), w.text.end(), digit))
      fail(w, fmt::format("expected a number of slots (1 to 255), found {}", quoted(w.text)));
    return static_cast<unsigned>(std::stoul(w.text));
  }
  /// OWNER.NAME: the owner kind, the member's name, and where it was written.
  // A struct, not a tuple: clang 14 (the fuzz build) cannot capture structured
  // bindings in a lambda.
  struct Member {
    KindId owner;
    std::string name;
    Word at;
  };
  Member member() {
    const Word& w = next("OWNER.NAME");
    auto dot = w.text.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == w.text.size())
      fail(w, fmt::format("expected OWNER.NAME, e.g. triangle.vertex, found {}", quoted(w.text)));
    Word owner{w.text.substr(0, dot), w.column};
    return {kind(owner), w.text.substr(dot + 1), w};
  }
  /// The schema's own checks (duplicates, arity) reported at this line.
  template <class Add>
  void declare(Add add, const Word& at) const {
    try {
      add();
    } catch (const std::invalid_argument& e) {
      std::string what = e.what();
      if (what.rfind("schema: ", 0) == 0) what = what.substr(8);
      fail(at, what);
    }
  }

  Schema& schema_;
  const std::string& file_;
  int line_;
  std::vector<Word> words_;
  std::size_t pos_ = 0;
};

}  // namespace

std::shared_ptr<Schema> parse_schema(const std::string& text, const std::string& file) {
  auto schema = std::make_shared<Schema>();
  std::istringstream in(text);
  int line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    auto words = words_of(line);
    if (!words.empty()) LineParser(*schema, file, line_no, std::move(words)).run();
  }
  if (schema->kind_count() == 0) throw RuleError(file, {}, "the schema declares no kind; write 'kind NAME' lines");
  return schema;
}

std::shared_ptr<Schema> load_schema(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw RuleError(path, {}, "cannot read the schema file");
  std::stringstream text;
  text << in.rdbuf();
  return parse_schema(text.str(), path);
}

}  // namespace loom::engine
