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
