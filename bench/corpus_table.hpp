#pragma once
// bench_corpus's table: one Row per (input, configuration), its CSV form (read
// back by --merge) and the Markdown report (summary, closure per F, rows).
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

namespace loom::bench {

// ---------------------------------------------------------------- rows

inline const std::vector<std::string> kColumns = {
    "row", "input", "family", "faces", "quads", "config", "rules", "closed", "valid", "comb_valid", "hexes", "steps",
    "cross", "seam", "other_rules", "backtracks", "whiskers_left", "degeneracies", "pillows", "min_sj", "mean_sj",
    "below_0_2", "seconds", "recheck", "filled", "fill_hexes", "fill_seconds", "note"};

struct Row {
  std::size_t row = 0;
  std::string input, family;
  int faces = 0;
  std::size_t quads = 0;
  std::string config;  ///< the configuration, prefixed by "RULES:" when a run compares rule sets
  std::string rules;   ///< the rule set's name (its directory's)
  bool closed = false, valid = false, comb_valid = false;
  std::size_t hexes = 0, steps = 0, cross = 0, seam = 0;
  std::string other_rules;
  std::size_t backtracks = 0, whiskers_left = 0;
  std::string degeneracies = "n/a", pillows = "n/a";
  std::optional<double> min_sj, mean_sj;
  std::size_t below_0_2 = 0;
  double seconds = 0;
  std::string recheck;  ///< "ok", "MISMATCH: ...", or "" (no mesh)
  /// The weave gave no mesh passing criteria 1-6 and the constructive fill
  /// did (src/fill): its hexes and seconds (not counted in `seconds`).
  bool filled = false;
  std::size_t fill_hexes = 0;
  double fill_seconds = 0;
  std::string note;     ///< why it failed (the weave's `left`, a failure, an exception)

  std::vector<std::string> fields() const {
    auto opt = [](const std::optional<double>& v) { return v ? fmt::format("{:.4f}", *v) : std::string(); };
    return {std::to_string(row), input, family, std::to_string(faces), std::to_string(quads), config,
            rules, closed ? "yes" : "no", valid ? "yes" : "no", comb_valid ? "yes" : "no", std::to_string(hexes),
            std::to_string(steps), std::to_string(cross), std::to_string(seam), other_rules,
            std::to_string(backtracks), std::to_string(whiskers_left), degeneracies, pillows, opt(min_sj),
            opt(mean_sj), std::to_string(below_0_2), fmt::format("{:.4f}", seconds), recheck,
            filled ? "yes" : "no", std::to_string(fill_hexes), fmt::format("{:.4f}", fill_seconds), note};
  }
  static Row from(const std::vector<std::string>& f) {
    if (f.size() != kColumns.size())
      throw std::runtime_error(fmt::format("bench_corpus: a CSV row has {} fields, not {}", f.size(), kColumns.size()));
    Row r;
    std::size_t i = 0;
    auto num = [&] { return std::size_t(std::stoull(f[i++])); };
    auto str = [&] { return f[i++]; };
    auto yes = [&] { return f[i++] == "yes"; };
    auto opt = [&]() -> std::optional<double> {
      const std::string& s = f[i++];
      if (s.empty()) return std::nullopt;
      return std::stod(s);
    };
    r.row = num();
    r.input = str();
    r.family = str();
    r.faces = int(num());
    r.quads = num();
    r.config = str();
    r.rules = str();
    r.closed = yes();
    r.valid = yes();
    r.comb_valid = yes();
    r.hexes = num();
    r.steps = num();
    r.cross = num();
    r.seam = num();
    r.other_rules = str();
    r.backtracks = num();
    r.whiskers_left = num();
    r.degeneracies = str();
    r.pillows = str();
    r.min_sj = opt();
    r.mean_sj = opt();
    r.below_0_2 = num();
    r.seconds = std::stod(str());
    r.recheck = str();
    r.filled = yes();
    r.fill_hexes = num();
    r.fill_seconds = std::stod(str());
    r.note = str();
    return r;
  }
};


void write_csv(const std::string& file, const std::vector<Row>& rows);
/// Throws std::runtime_error when the file cannot be read or is not a bench_corpus CSV.
std::vector<Row> read_csv(const std::string& file);
/// Sorts the rows by number, writes the CSV and the Markdown report (when the
/// file names are not empty; `md_full`: every row, not only the named shapes)
/// and prints the summary on stdout.
void write_outputs(std::vector<Row> rows, const std::string& csv, const std::string& md, bool md_full);

}  // namespace loom::bench
