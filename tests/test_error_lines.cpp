// Every error line is one printable, bounded line, whatever it quotes: control
// bytes and broken UTF-8 are escaped, a huge quote is cut (issue 15).
#include <doctest/doctest.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "src/util/one_line.hpp"
#include "tests/support.hpp"

using namespace loom;

namespace {

bool printable_line(const std::string& line) {
  return std::none_of(line.begin(), line.end(), [](char c) {
    auto byte = static_cast<unsigned char>(c);
    return byte < 0x20 || byte == 0x7f;
  });
}

// stderr of a CLI run: exactly one line, printable, at most `bytes` long.
void check_one_bounded_line(const test::CliResult& r, std::size_t bytes) {
  CHECK(r.status == 2);
  REQUIRE(!r.err.empty());
  CHECK(test::count_lines(r.err) == 1);
  CHECK(r.err.back() == '\n');
  CHECK(printable_line(r.err.substr(0, r.err.size() - 1)));
  CHECK(r.err.size() <= bytes);
}

}  // namespace

TEST_CASE("one_line escapes control bytes and broken UTF-8, and keeps valid UTF-8") {
  using namespace std::string_literals;
  CHECK(one_line("a\0b\nc\x1b[31md\x7f"s) == "a\\x00b\\x0ac\\x1b[31md\\x7f");
  CHECK(one_line("maillage-\xc3\xa9t\xc3\xa9 \xe2\x82\xac") == "maillage-\xc3\xa9t\xc3\xa9 \xe2\x82\xac");
  CHECK(one_line("\xc2\x85 C1") == "\\xc2\\x85 C1");                          // C1 control (NEL)
  CHECK(one_line("\xff \xe2\x82 \xed\xa0\x80") == "\\xff \\xe2\\x82 \\xed\\xa0\\x80");  // invalid, cut, surrogate
  CHECK(one_line("\xc3") == "\\xc3");                                          // ends inside a sequence
}

TEST_CASE("one_line cuts a huge message in the middle, keeping its start and its hint") {
  std::string huge = "file.obj: line 1: " + std::string(1'000'000, 'a') + "; fix the syntax";
  std::string line = one_line(huge);
  CHECK(line.size() <= max_message_bytes);
  CHECK(line.starts_with("file.obj: line 1: aaa"));
  CHECK(line.ends_with("aaa; fix the syntax"));
  CHECK(line.find(" ... ") != std::string::npos);

  // Cuts fall between escapes and between UTF-8 sequences, never inside one.
  line = one_line(std::string(5000, '\0'));
  CHECK(line.size() <= max_message_bytes);
  std::string rest = line;
  rest.erase(rest.find(" ... "), 5);
  for (std::size_t i = 0; i < rest.size(); i += 4) CHECK(rest.compare(i, 4, "\\x00") == 0);
  line = one_line(std::string(1000, 'a') + std::string(3000, '\xe2') + "\xe2\x82\xac" + "; hint");
  CHECK(line.ends_with("\\xe2\xe2\x82\xac; hint"));
}

TEST_CASE("loom prints one bounded, printable line for raw bytes in rule files, paths and arguments") {
  test::ScratchDir dir("error-lines");
  std::ofstream(dir / "nul.rule", std::ios::binary) << std::string("rule r { match { v: node \0 } }", 30);
  auto r = test::run_cli("rules list " + (dir / "nul.rule").string());
  check_one_bounded_line(r, 1200);
  CHECK(r.err.find("nul.rule:1:26: unexpected character '\\x00'") != std::string::npos);

  const std::string long_name(1'000'000, 'x');
  std::ofstream(dir / "long.rule") << "rule r { match { v: node } " << long_name << " }";
  r = test::run_cli("rules list " + (dir / "long.rule").string());
  check_one_bounded_line(r, 1200);
  CHECK(r.err.find("long.rule:1:28: expected 'priority', 'order', 'anchor', 'match', 'rewrite' or '}', found "
                   "'xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx...'") != std::string::npos);
  std::ofstream(dir / "long.rule") << "rule r { match { v: node\n f: face\n f.node[0] == " << long_name << " } }";
  r = test::run_cli("rules list " + (dir / "long.rule").string());
  check_one_bounded_line(r, 1200);
  CHECK(r.err.find("long.rule:3:2: unknown variable 'xxxxxxxx") != std::string::npos);
  CHECK(r.err.ends_with("xxxx'; fix the rule file (grammar: docs/rules.md)\n"));

  // A newline in a file name.
  const std::string strange = (dir / "bad\nname.obj").string();
  std::ofstream(strange) << "garbage\n";
  r = test::run_cli("stc '" + strange + "'");
  check_one_bounded_line(r, 1200);
  CHECK(r.err.find("bad\\x0aname.obj") != std::string::npos);

  r = test::run_cli("gen box " + std::string(100'000, '7') + "z 1 1 -o " + (dir / "b.obj").string());
  check_one_bounded_line(r, 1200);
  CHECK(r.err.find("must be a whole number, got '7777") != std::string::npos);
  CHECK(r.err.ends_with("usage: loom gen box A B C -o FILE\n"));
}
