// Replays every seed of tests/fuzz/corpus/NAME/ and every crash libFuzzer
// found, kept in tests/fuzz/crashes/NAME/, through the fuzz target NAME
// (tests/fuzz/fuzz_targets.hpp, docs/fuzzing.md): each input must be accepted
// or refused with the reader's documented error and a one-line printable
// message, so that a fixed crash stays fixed. An unexpected exception fails
// the case; a crash or sanitizer report stops the suite.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "tests/fuzz/fuzz_targets.hpp"

namespace fs = std::filesystem;
using loom::fuzz::find_target;
using loom::fuzz::is_one_printable_line;
using loom::fuzz::Outcome;
using loom::fuzz::Target;

namespace {

const fs::path fuzz_dir = LOOM_FUZZ_DIR;

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<fs::path> files_in(const fs::path& dir) {
  std::vector<fs::path> files;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_regular_file() && e.path().filename().string().front() != '.') files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

struct Replayed {
  int accepted = 0, refused = 0;
};

// Runs every file of `dir` through `target`. Seeds named ok-* must be
// accepted and bad-* refused, so a reader that starts refusing good input, or
// accepting what it must not, fails here too.
Replayed replay(const Target& target, const fs::path& dir) {
  Replayed counts;
  for (const fs::path& file : files_in(dir)) {
    INFO(file.string());
    Outcome outcome;
    try {
      outcome = target.run(bytes_of(file));
    } catch (const std::exception& e) {
      FAIL_CHECK("not the reader's documented error: " << e.what());
      continue;
    }
    const std::string name = file.filename().string();
    if (outcome) {
      ++counts.refused;
      if (target.checks_message) CHECK_MESSAGE(is_one_printable_line(*outcome), *outcome);
      CHECK_FALSE(name.starts_with("ok-"));
    } else {
      ++counts.accepted;
      CHECK_FALSE(name.starts_with("bad-"));
    }
  }
  return counts;
}

}  // namespace

TEST_CASE("every fuzz target's seed corpus replays: good seeds accepted, bad ones refused in one line") {
  for (const Target& target : loom::fuzz::targets()) {
    CAPTURE(target.name);
    const fs::path dir = fuzz_dir / "corpus" / std::string(target.name);
    REQUIRE(fs::is_directory(dir));
    Replayed counts = replay(target, dir);
    CHECK(counts.accepted >= 1);
    CHECK(counts.refused >= 1);
    for (const fs::path& seed : files_in(dir)) CHECK(fs::file_size(seed) <= target.max_len);
  }
}

TEST_CASE("every crash the fuzzers found is accepted or refused in one line, not a crash") {
  // The folder is in the repository: without it this case would check nothing.
  REQUIRE(fs::is_directory(fuzz_dir / "crashes"));
  int replayed = 0;
  for (const auto& e : fs::directory_iterator(fuzz_dir / "crashes")) {
    if (!e.is_directory()) continue;
    ++replayed;
    const std::string name = e.path().filename().string();
    CAPTURE(name);
    const Target* target = find_target(name);
    REQUIRE_MESSAGE(target, "tests/fuzz/crashes/" << name << " names no fuzz target");
    replay(*target, e.path());
  }
  CHECK(replayed >= 4);
}

TEST_CASE("the replay tells a refusal from a finding") {
  const Target* obj = find_target("obj");
  REQUIRE(obj);
  const char* cube =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
      "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
  CHECK(obj->run(cube) == std::nullopt);
  Outcome open = obj->run(std::string(cube, std::string_view(cube).rfind("f ")));
  REQUIRE(open);
  CHECK(open->find("open") != std::string::npos);
  Outcome garbage = obj->run("\x7f" "ELF\x01\n\x1b[2J");
  REQUIRE(garbage);
  CHECK(garbage->starts_with("fuzz.obj"));
  CHECK(is_one_printable_line(*garbage));
  CHECK_FALSE(is_one_printable_line(""));
  CHECK_FALSE(is_one_printable_line("line 1\nline 2"));
  CHECK_FALSE(is_one_printable_line("a \x1b[2J escape"));
  CHECK_FALSE(is_one_printable_line("\xff\xfe binary"));
  CHECK_FALSE(is_one_printable_line(std::string(2000, 'x')));
  CHECK(is_one_printable_line("caf\xc3\xa9: line 3: unexpected 'x'; fix it"));
  CHECK(find_target("no such reader") == nullptr);
}
