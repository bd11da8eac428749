#pragma once
// Each subcommand lives in its own cmd_*.cpp and registers itself here.
// A command's callback returns the process exit status (see docs/cli.md):
// 0 success, 1 not achieved / not valid, 2 bad input or usage, 3 weave written
// with bad geometry. Bad input is reported by throwing loom::InputError.
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace loom::cli {

struct Command {
  std::string name;
  /// Adds the subcommand to `app`; the returned function runs it after parsing.
  std::function<std::function<int()>(CLI::App& app)> setup;
};

std::vector<Command>& registry();

struct Register {
  explicit Register(Command c) { registry().push_back(std::move(c)); }
};

}  // namespace loom::cli
