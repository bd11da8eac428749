// The examples in README.md and docs/*.md are run as written, so a figure or
// a message that moves fails the suite instead of drifting from the tool.
//
// An example is a fenced block holding lines that start with "$ ": each such
// line is a command, and the lines after it, up to the next "$ " line or the
// block's end, are what it prints. A trailing comment "# loom ..." says how
// the command's input was made; it is run first, in the same directory. The
// blocks of one document share one scratch directory (with `rules` and
// `examples` linked into it), in order, so a later example may use an earlier
// one's files. `loom` and `build/loom` are the CLI under test; `echo $?`
// prints the previous command's status. stdout and stderr are compared
// separately, each in order: lines starting "loom: " (errors, warnings and
// notes, cli.md) are stderr's, the others stdout's. A line "..." stands for
// any number of lines, where a document shows only part of an output.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "tests/support.hpp"

namespace fs = std::filesystem;
using loom::test::CliResult;
using loom::test::ScratchDir;

namespace {

struct Command {
  int line = 0;         ///< in the document, from 1
  std::string text;     ///< after "$ "
  std::vector<std::string> expected;
};

/// Every "$ " line of the document's fenced blocks, with the lines after it
/// up to the next one or the block's closing fence.
std::vector<Command> commands_of(const fs::path& doc) {
  std::ifstream in(doc);
  std::vector<Command> commands;
  std::string line;
  bool in_block = false, open = false;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.starts_with("```")) {
      in_block = !in_block;
      open = false;
      continue;
    }
    if (!in_block) continue;
    if (line.starts_with("$ ")) {
      commands.push_back({number, line.substr(2), {}});
      open = true;
    } else if (open) {
      commands.back().expected.push_back(line);
    }
  }
  return commands;
}

/// Blank lines at the end of an output or of a block are not compared.
std::vector<std::string> without_trailing_blanks(std::vector<std::string> lines) {
  while (!lines.empty() && lines.back().empty()) lines.pop_back();
  return lines;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return without_trailing_blanks(std::move(lines));
}

std::string joined(const std::vector<std::string>& lines) { return fmt::format("{}", fmt::join(lines, "\n")); }

/// Whether the lines read `actual`, "..." in `expected` matching any run of lines.
bool matches(const std::vector<std::string>& actual, std::size_t a, const std::vector<std::string>& expected,
             std::size_t e) {
  if (e == expected.size()) return a == actual.size();
  if (expected[e] == "...") {
    for (std::size_t skip = a; skip <= actual.size(); ++skip)
      if (matches(actual, skip, expected, e + 1)) return true;
    return false;
  }
  return a < actual.size() && actual[a] == expected[e] && matches(actual, a + 1, expected, e + 1);
}

bool is_diagnostic(const std::string& line) { return line.starts_with("loom: "); }

/// The command as run: `loom` is the CLI under test, found on the scratch
/// directory's PATH so that its usage lines name it `loom`, as the documents
/// do; "" when the command runs something else.
std::string with_cli(const std::string& text) {
  if (text.starts_with("build/loom ")) return text.substr(6);
  return text.starts_with("loom ") ? text : "";
}

/// The input-making command of a trailing "# loom ..." comment, or "".
std::string setup_of(std::string& text) {
  const std::size_t hash = text.find(" # ");
  if (hash == std::string::npos) return "";
  std::string comment = text.substr(hash + 3);
  text = text.substr(0, hash);
  while (!comment.empty() && comment.front() == ' ') comment.erase(0, 1);
  return comment.starts_with("loom ") ? comment : "";
}

CliResult run_in(const fs::path& dir, const std::string& command) {
  // The user's run: the invariant checks ctest turns on are not part of it.
  return loom::test::run_shell(
      fmt::format("cd '{0}' && PATH='{0}/bin':\"$PATH\" LOOM_CHECK_INVARIANTS=0 {1}", dir.string(), command));
}

/// Runs a document's examples; returns how many commands it has.
std::size_t check_document(const std::string& name) {
  const std::vector<Command> commands = commands_of(fs::path(LOOM_SOURCE_DIR) / name);
  if (commands.empty()) return 0;
  ScratchDir dir("doc");
  fs::create_directory_symlink(fs::path(LOOM_SOURCE_DIR) / "rules", dir / "rules");
  fs::create_directory_symlink(fs::path(LOOM_SOURCE_DIR) / "examples", dir / "examples");
  fs::create_directory(dir / "bin");
  fs::create_symlink(fs::path(LOOM_CLI), dir / "bin" / "loom");
  int status = 0;
  for (Command c : commands) {
    const std::string where = fmt::format("{}:{}: $ {}", name, c.line, c.text);
    CAPTURE(where);
    std::vector<std::string> out, err;
    if (c.text == "echo $?") {
      out = {std::to_string(status)};
    } else {
      const std::string setup = setup_of(c.text);
      if (!setup.empty()) {
        const CliResult made = run_in(dir.path(), with_cli(setup));
        REQUIRE_MESSAGE(made.status == 0, "its input command failed: " << made.err);
      }
      const std::string command = with_cli(c.text);
      REQUIRE_MESSAGE(!command.empty(), "an example runs loom, build/loom or echo $? only");
      const CliResult r = run_in(dir.path(), command);
      status = r.status;
      out = lines_of(r.out);
      err = lines_of(r.err);
    }
    std::vector<std::string> expected_out, expected_err;
    for (const std::string& line : without_trailing_blanks(c.expected))
      (is_diagnostic(line) ? expected_err : expected_out).push_back(line);
    CHECK_MESSAGE(matches(out, 0, expected_out, 0), "stdout:\n" << joined(out) << "\nbut the document shows:\n"
                                                              << joined(expected_out));
    CHECK_MESSAGE(matches(err, 0, expected_err, 0), "stderr:\n" << joined(err) << "\nbut the document shows:\n"
                                                              << joined(expected_err));
  }
  return commands.size();
}

}  // namespace

TEST_CASE("every example in README.md and docs/*.md prints what the document shows") {
  std::vector<std::string> documents = {"README.md"};
  for (const auto& entry : fs::directory_iterator(fs::path(LOOM_SOURCE_DIR) / "docs"))
    if (entry.path().extension() == ".md") documents.push_back("docs/" + entry.path().filename().string());
  std::sort(documents.begin(), documents.end());
  std::size_t commands = 0;
  for (const std::string& name : documents) commands += check_document(name);
  // The README, cli.md, rules.md and weaving.md hold 35 today:
  // finding far fewer means the examples are no longer being read.
  CHECK(commands >= 33);
}
