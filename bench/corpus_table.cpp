#include "bench/corpus_table.hpp"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

namespace loom::bench {

namespace {

// ---------------------------------------------------------------- CSV

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::vector<std::string> csv_split(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') out.back() += '"', ++i;
      else if (c == '"') quoted = false;
      else out.back() += c;
    } else if (c == '"') quoted = true;
    else if (c == ',') out.emplace_back();
    else out.back() += c;
  }
  return out;
}

}  // namespace

void write_csv(const std::string& file, const std::vector<Row>& rows) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error("bench_corpus: cannot write " + file);
  for (std::size_t i = 0; i < kColumns.size(); ++i) out << (i ? "," : "") << kColumns[i];
  out << '\n';
  for (const auto& r : rows) {
    auto f = r.fields();
    for (std::size_t i = 0; i < f.size(); ++i) out << (i ? "," : "") << csv_field(f[i]);
    out << '\n';
  }
}

std::vector<Row> read_csv(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("bench_corpus: cannot read " + file);
  std::string line;
  if (!std::getline(in, line) || csv_split(line) != kColumns)
    throw std::runtime_error("bench_corpus: " + file + " is not a bench_corpus CSV (header differs)");
  std::vector<Row> rows;
  while (std::getline(in, line))
    if (!line.empty()) rows.push_back(Row::from(csv_split(line)));
  return rows;
}

namespace {

// ---------------------------------------------------------------- reports

struct Band {
  int lo, hi;
  std::string name() const { return fmt::format("{}-{}", lo, hi); }
};
const std::vector<Band> kBands = {{6, 20}, {22, 50}, {52, 100}, {102, 200}};

std::string rate(std::size_t k, std::size_t n) {
  if (n == 0) return "-";
  return fmt::format("{}/{} ({:.1f}%)", k, n, 100.0 * double(k) / double(n));
}

// Configurations in order of first appearance: rows are numbered input by
// input, configuration by configuration, so this is the corpus's order.
std::vector<std::string> config_order(const std::vector<Row>& rows) {
  std::vector<std::string> names;
  for (const auto& r : rows)
    if (std::find(names.begin(), names.end(), r.config) == names.end()) names.push_back(r.config);
  return names;
}

std::string md_row(const std::vector<std::string>& cells) {
  std::string s = "|";
  for (const auto& c : cells) {
    std::string e;
    for (char ch : c) e += ch == '|' ? std::string("\\|") : std::string(1, ch);
    s += " " + e + " |";
  }
  return s + "\n";
}
std::string md_header(const std::vector<std::string>& cells) {
  std::string s = md_row(cells) + "|";
  for (std::size_t i = 0; i < cells.size(); ++i) s += "---|";
  return s + "\n";
}

/// `best`, when given, receives the configuration that closes most.
std::string summary_md(const std::vector<Row>& rows, std::string* best_out = nullptr) {
  std::string out;
  auto cfgs = config_order(rows);
  out += "### Per configuration\n\n";
  std::vector<std::string> head = {"config", "runs", "closed", "valid 1-6", "valid 1-7", "randquad closed"};
  for (const auto& b : kBands) head.push_back("F " + b.name());
  head.insert(head.end(), {"valid 1-6 with fill", "randquad valid 1-6 with fill", "backtracks", "recheck mismatches",
                           "errors/timeouts", "seconds"});
  out += md_header(head);
  std::string best;
  double best_rate = -1;
  std::size_t best_closed = 0, best_comb = 0;
  for (const auto& c : cfgs) {
    std::size_t runs = 0, closed = 0, comb = 0, valid = 0, rq = 0, rq_closed = 0, bt = 0, mism = 0, errors = 0;
    std::size_t with_fill = 0, rq_with_fill = 0;
    double secs = 0;
    std::vector<std::size_t> bn(kBands.size()), bc(kBands.size());
    for (const auto& r : rows) {
      if (r.config != c) continue;
      ++runs;
      closed += r.closed, comb += r.comb_valid, valid += r.valid, bt += r.backtracks, secs += r.seconds;
      mism += r.recheck.starts_with("MISMATCH");
      with_fill += r.comb_valid || r.filled;
      errors += r.note.starts_with("error:") || r.note.starts_with("timeout:");
      if (r.family == "randquad") {
        ++rq, rq_closed += r.closed, rq_with_fill += r.comb_valid || r.filled;
        for (std::size_t b = 0; b < kBands.size(); ++b)
          if (r.faces >= kBands[b].lo && r.faces <= kBands[b].hi) ++bn[b], bc[b] += r.closed;
      }
    }
    std::vector<std::string> cells = {c, std::to_string(runs), rate(closed, runs), rate(comb, runs),
                                      rate(valid, runs), rate(rq_closed, rq)};
    for (std::size_t b = 0; b < kBands.size(); ++b) cells.push_back(rate(bc[b], bn[b]));
    cells.insert(cells.end(), {rate(with_fill, runs), rate(rq_with_fill, rq), std::to_string(bt), std::to_string(mism),
                               std::to_string(errors), fmt::format("{:.1f}", secs)});
    out += md_row(cells);
    double key = rq ? double(rq_closed) / double(rq) : double(closed) / double(runs);
    // Ties go to the configuration whose closures pass criteria 1-6 most often.
    if (key > best_rate || (key == best_rate && (comb > best_comb || (comb == best_comb && closed > best_closed))))
      best = c, best_rate = key, best_closed = closed, best_comb = comb;
  }
  out += "\n";
  if (best_out) *best_out = best;
  if (!best.empty()) {
    out += fmt::format("Closes most: **{}** ({:.1f}% of randquad; {} runs closed in all).\n\n", best,
                       100.0 * best_rate, best_closed);
    std::vector<const Row*> fails;
    std::size_t filled = 0, unfilled = 0, rq_runs = 0, rq_meshed = 0;
    for (const auto& r : rows)
      if (r.config == best) {
        if (!r.comb_valid) fails.push_back(&r), ++(r.filled ? filled : unfilled);
        if (r.family == "randquad") ++rq_runs, rq_meshed += r.comb_valid || r.filled;
      }
    out += fmt::format("With the constructive fill where its weave gives no mesh passing criteria 1-6: {} of randquad "
                       "({} runs filled, {} left without a mesh).\n\n", rate(rq_meshed, rq_runs), filled, unfilled);
    if (!fails.empty()) {
      out += fmt::format("What stops {} ({} runs without a mesh passing criteria 1-6; up to 12 shown, smallest first):\n\n",
                         best, fails.size());
      std::stable_sort(fails.begin(), fails.end(), [](const Row* a, const Row* b) { return a->quads < b->quads; });
      for (std::size_t i = 0; i < fails.size() && i < 12; ++i)
        out += fmt::format("- `{}` ({} quads): {}\n", fails[i]->input, fails[i]->quads, fails[i]->note);
      out += "\n";
    }
  }
  return out;
}

/// What stops a run, in a few words (from its note).
std::string stop_cause(const Row& r) {
  if (r.note.starts_with("timeout:")) return "stopped by the timeout";
  if (r.note.starts_with("error:")) return "error";
  if (r.note.starts_with("primal:")) return "closed; primal construction failed";
  if (r.note.starts_with("criterion ")) return "closed; fails " + r.note.substr(0, r.note.find(':'));
  if (!r.closed && r.note.find("the front stopped shrinking") != std::string::npos) return "open; the front stopped shrinking";
  if (!r.closed && r.note.find("stopped after") != std::string::npos) return "open; step limit";
  if (!r.closed) return "open; no rule applies";
  return "closed; " + r.note;
}

/// Every run of `config` without a mesh passing criteria 1-6: counts by
/// cause, then each run (smallest first) with what stops it.
std::string stops_md(const std::vector<Row>& rows, const std::string& config) {
  std::vector<const Row*> fails;
  for (const auto& r : rows)
    if (r.config == config && !r.comb_valid) fails.push_back(&r);
  if (fails.empty()) return "";
  std::stable_sort(fails.begin(), fails.end(), [](const Row* a, const Row* b) { return a->quads < b->quads; });
  std::map<std::string, std::size_t> causes;
  for (const Row* r : fails) ++causes[stop_cause(*r)];
  std::string out = fmt::format("### What stops {}, input by input\n\n{} runs give no mesh passing criteria 1-6:\n\n",
                                config, fails.size());
  out += md_header({"cause", "runs"});
  for (const auto& [cause, n] : causes) out += md_row({cause, std::to_string(n)});
  out += "\n<details><summary>Every one, smallest first</summary>\n\n";
  out += md_header({"input", "quads", "cause", "what is left"});
  for (const Row* r : fails) out += md_row({"`" + r->input + "`", std::to_string(r->quads), stop_cause(*r), r->note});
  out += "\n</details>\n\n";
  return out;
}

std::string rows_md(const std::vector<Row>& rows, bool randquad_too) {
  std::string out = md_header({"input", "quads", "config", "closed", "valid", "comb. valid", "hexes", "steps", "cross",
                               "seam", "other", "backtracks", "whiskers left", "degeneracies", "pillows", "min SJ",
                               "mean SJ", "< 0.2", "seconds", "recheck"});
  for (const auto& r : rows) {
    if (!randquad_too && r.family == "randquad") continue;
    auto f = r.fields();
    out += md_row({r.input, std::to_string(r.quads), r.config, f[7], f[8], f[9], f[10], f[11], f[12], f[13],
                   r.other_rules.empty() ? "-" : r.other_rules, f[15], f[16], r.degeneracies, r.pillows,
                   f[19].empty() ? "-" : f[19], f[20].empty() ? "-" : f[20], f[21], fmt::format("{:.3f}", r.seconds),
                   r.recheck.empty() ? "-" : r.recheck});
  }
  return out;
}

std::string randquad_md(const std::vector<Row>& rows) {
  // Closed runs per F (10 seeds each), one column per configuration.
  auto cfgs = config_order(rows);
  std::map<int, std::map<std::string, std::pair<int, int>>> by_f;  // F -> config -> (closed, runs)
  for (const auto& r : rows)
    if (r.family == "randquad") {
      auto& c = by_f[r.faces][r.config];
      c.first += r.closed, c.second += 1;
    }
  if (by_f.empty()) return {};
  std::vector<std::string> head = {"F"};
  head.insert(head.end(), cfgs.begin(), cfgs.end());
  std::string out = md_header(head);
  for (const auto& [f, m] : by_f) {
    std::vector<std::string> cells = {std::to_string(f)};
    for (const auto& c : cfgs) {
      auto it = m.find(c);
      cells.push_back(it == m.end() ? "-" : fmt::format("{}/{}", it->second.first, it->second.second));
    }
    out += md_row(cells);
  }
  return out;
}

/// How a run ended, for comparing rule sets: the verdict and the hexes.
std::string outcome(const Row& r) {
  if (r.note.starts_with("timeout:") || r.note.starts_with("error:")) return stop_cause(r);
  std::string verdict = r.valid ? "valid 1-7" : r.comb_valid ? "valid 1-6" : r.closed ? "closed, not valid" : "open";
  return r.comb_valid ? fmt::format("{}, {} hexes", verdict, r.hexes) : verdict;
}

/// With several rule sets in the table: the (input, configuration) pairs whose
/// outcome is not the same under every set.
std::string changes_md(const std::vector<Row>& rows) {
  std::vector<std::string> sets;
  for (const auto& r : rows)
    if (std::find(sets.begin(), sets.end(), r.rules) == sets.end()) sets.push_back(r.rules);
  if (sets.size() < 2) return {};
  using Key = std::pair<std::string, std::string>;  // input, configuration without its rule set
  std::vector<Key> order;
  std::map<Key, std::map<std::string, const Row*>> runs;
  for (const auto& r : rows) {
    const std::string prefix = r.rules + ":";
    Key key{r.input, r.config.starts_with(prefix) ? r.config.substr(prefix.size()) : r.config};
    if (!runs.count(key)) order.push_back(key);
    runs[key][r.rules] = &r;
  }
  std::vector<std::string> head = {"input", "config"};
  head.insert(head.end(), sets.begin(), sets.end());
  std::string table;
  std::size_t changed = 0, compared = 0;
  for (const Key& key : order) {
    const auto& by_set = runs[key];
    if (by_set.size() < 2) continue;
    ++compared;
    std::vector<std::string> cells = {"`" + key.first + "`", key.second};
    std::set<std::string> seen;
    for (const auto& set : sets) {
      auto it = by_set.find(set);
      cells.push_back(it == by_set.end() ? "-" : outcome(*it->second));
      if (it != by_set.end()) seen.insert(cells.back());
    }
    if (seen.size() > 1) ++changed, table += md_row(cells);
  }
  std::string out = fmt::format("### Outcomes that changed between rule sets\n\n{} of {} runs compared changed",
                                changed, compared);
  return out + (changed ? ":\n\n" + md_header(head) + table + "\n" : ".\n\n");
}

}  // namespace

void write_outputs(std::vector<Row> rows, const std::string& csv, const std::string& md, bool md_full) {
  std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.row < b.row; });
  // As the CSV stores them, so that a merge of shard CSVs writes this same report.
  for (Row& r : rows) r.seconds = std::stod(fmt::format("{:.4f}", r.seconds));
  if (!csv.empty()) write_csv(csv, rows);
  std::string best;
  std::string text = "## Summary\n\n" + summary_md(rows, &best);
  std::string rq = randquad_md(rows);
  if (!rq.empty()) text += "### Random quadrangulations: closed runs per F (of 10 seeds)\n\n" + rq + "\n";
  if (!best.empty()) text += stops_md(rows, best);
  const std::string changes = changes_md(rows);
  text += changes;
  text += md_full ? "### Every run\n\n" : "### Per input (randquad rows in the CSV)\n\n";
  text += rows_md(rows, md_full);
  if (!md.empty()) {
    std::ofstream out(md);
    if (!out) throw std::runtime_error("bench_corpus: cannot write " + md);
    out << text;
  }
  std::cout << summary_md(rows) << changes;
}

}  // namespace loom::bench
