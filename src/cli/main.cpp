// The `loom` command line: parses, dispatches to a subcommand, and turns every
// failure into one clear line on stderr and the documented exit status. Messages
// quote paths, arguments and file contents, so each goes through one_line().
#include <cstdio>
#include <exception>
#include <iostream>
#include <map>
#include <new>

#include "engine/rule_parser.hpp"
#include "src/cli/command.hpp"
#include "src/util/error.hpp"
#include "src/util/one_line.hpp"

namespace loom::cli {
std::vector<Command>& registry() {
  static std::vector<Command> commands;
  return commands;
}
}  // namespace loom::cli

int main(int argc, char** argv) {
  using namespace loom::cli;
  CLI::App app{"Loom: all-hexahedral meshing by whisker weaving"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "loom 0.1.0");
  std::map<CLI::App*, std::function<int()>> runners;
  for (auto& c : registry()) {
    auto* sub = app.add_subcommand(c.name);
    runners[sub] = c.setup(*sub);
  }
  try {
    app.parse(argc, argv);
    for (auto& [sub, run] : runners)
      if (sub->parsed()) return run();
    return 2;
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "loom: error: " << loom::one_line(e.what()) << "; see 'loom --help'\n";
    return 2;
  } catch (const loom::InputError& e) {
    std::cerr << "loom: error: " << loom::one_line(e.what()) << "\n";
    return 2;
  } catch (const loom::engine::RuleError& e) {
    // A rule or strategy file read before a command could say which (the
    // rule directory's default strategy, read with the options) is bad input too.
    std::cerr << "loom: error: " << loom::one_line(e.what())
              << "; fix the file (grammar: docs/rules.md, docs/strategies.md)\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "loom: out of memory: the run needs more than it may use (--max-memory, or the machine's); nothing "
                 "written; raise --max-memory or mesh a smaller part\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "loom: internal error: " << loom::one_line(e.what()) << "; please report it with the input\n";
    return 1;
  }
}
