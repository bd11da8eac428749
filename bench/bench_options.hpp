#pragma once
// Command-line parsing shared by the benchmark programs (CLI11): --help prints
// the options and exits 0; a bad option prints one line and exits 2. And the
// lists of sizes they take: "6,8,10", "6-16" (even ones) or "6-200:4".
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace loom::bench {

inline void parse_or_exit(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    std::exit(app.exit(e));
  } catch (const CLI::ParseError& e) {
    std::cerr << app.get_name() << ": " << e.what() << " (try --help)\n";
    std::exit(2);
  }
}

inline std::vector<int> parse_counts(const std::string& s) {
  std::vector<int> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) {
    if (item.empty()) continue;
    const auto dash = item.find('-');
    if (dash == std::string::npos) {
      out.push_back(std::stoi(item));
      continue;
    }
    const auto colon = item.find(':');
    const int from = std::stoi(item.substr(0, dash)), to = std::stoi(item.substr(dash + 1, colon - dash - 1));
    const int step = colon == std::string::npos ? 2 : std::stoi(item.substr(colon + 1));
    for (int f = from; f <= to; f += step) out.push_back(f);
  }
  return out;
}

}  // namespace loom::bench
