#pragma once
// Command-line parsing shared by the benchmark programs (CLI11): --help prints
// the options and exits 0; a bad option prints one line and exits 2.
#include <cstdlib>
#include <iostream>

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

}  // namespace loom::bench
