// The corpus table (bench/corpus_table.cpp): which configuration it names
// as closing most, whose failures results.md then lists.
#include <doctest/doctest.h>

#include <filesystem>

#include "bench/corpus_table.hpp"
#include "tests/support.hpp"

using namespace loom;

namespace {
bench::Row randquad(const std::string& config, int seed, bool closed, bool comb_valid) {
  bench::Row r;
  r.input = "randquad 8 s" + std::to_string(seed);
  r.family = "randquad";
  r.faces = 8;
  r.quads = 8;
  r.config = config;
  r.closed = closed;
  r.comb_valid = comb_valid;
  r.note = closed ? (comb_valid ? "" : "criterion 3 (cells): two hexes share two faces") : "4 whiskers left";
  return r;
}
}  // namespace

TEST_CASE("of two configurations closing as many randquad, the one with more valid meshes closes most") {
  // "first" closes one of two, invalid; "second" one of two, valid.
  std::vector<bench::Row> rows = {randquad("first", 0, true, false), randquad("first", 1, false, false),
                                  randquad("second", 0, true, true), randquad("second", 1, false, false)};
  auto md = std::filesystem::temp_directory_path() / "loom-test-corpus-table.md";
  bench::write_outputs(rows, "", md.string(), false);
  std::string text = test::slurp(md);
  std::filesystem::remove(md);
  CHECK(text.find("Closes most: **second**") != std::string::npos);
  CHECK(text.find("### What stops second, input by input") != std::string::npos);
}

TEST_CASE("a row's fill columns survive the CSV, and the summary counts the fill beside the weave") {
  bench::Row filled = randquad("only", 0, false, false);
  filled.filled = true, filled.fill_hexes = 1280, filled.fill_seconds = 0.0125;
  filled.note += "; fill: made up";
  std::vector<bench::Row> rows = {filled, randquad("only", 1, true, true)};
  rows[1].row = 1;
  auto csv = std::filesystem::temp_directory_path() / "loom-test-corpus-table.csv";
  auto md = std::filesystem::temp_directory_path() / "loom-test-corpus-table-fill.md";
  bench::write_outputs(rows, csv.string(), md.string(), false);
  auto back = bench::read_csv(csv.string());
  std::string text = test::slurp(md);
  std::filesystem::remove(csv);
  std::filesystem::remove(md);
  REQUIRE(back.size() == 2);
  CHECK(back[0].filled);
  CHECK(back[0].fill_hexes == 1280);
  CHECK(back[0].fill_seconds == doctest::Approx(0.0125));
  CHECK(back[0].note == filled.note);
  CHECK_FALSE(back[1].filled);
  CHECK(text.find("2/2 (100.0%) of randquad (1 runs filled, 0 left without a mesh)") != std::string::npos);
}

TEST_CASE("with two rule sets, every row names its set and the report lists the runs whose outcome changed") {
  auto run = [](const std::string& set, int seed, bool closed, bool comb_valid, std::size_t hexes) {
    bench::Row r = randquad(set + ":priority", seed, closed, comb_valid);
    r.rules = set;
    r.hexes = hexes;
    return r;
  };
  // Seed 0: closed by both sets alike; seed 1: only "mine" closes; seed 2: both, in different hex counts.
  std::vector<bench::Row> rows = {run("shipped", 0, true, true, 40), run("mine", 0, true, true, 40),
                                  run("shipped", 1, false, false, 0), run("mine", 1, true, true, 52),
                                  run("shipped", 2, true, true, 60), run("mine", 2, true, true, 58)};
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i].row = i;
  auto csv = std::filesystem::temp_directory_path() / "loom-test-corpus-table-sets.csv";
  auto md = std::filesystem::temp_directory_path() / "loom-test-corpus-table-sets.md";
  bench::write_outputs(rows, csv.string(), md.string(), false);
  auto back = bench::read_csv(csv.string());
  std::string text = test::slurp(md);
  std::filesystem::remove(csv);
  std::filesystem::remove(md);
  REQUIRE(back.size() == 6);
  CHECK(back[1].rules == "mine");
  CHECK(back[1].config == "mine:priority");
  CHECK(text.find("2 of 3 runs compared changed") != std::string::npos);
  CHECK(text.find("| `randquad 8 s1` | priority | open | valid 1-6, 52 hexes |") != std::string::npos);
  CHECK(text.find("| `randquad 8 s2` | priority | valid 1-6, 60 hexes | valid 1-6, 58 hexes |") != std::string::npos);
  CHECK(text.find("`randquad 8 s0` | priority") == std::string::npos);
}
