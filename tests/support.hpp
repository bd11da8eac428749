#pragma once
// Shared helpers for the doctest suites: run the CLI, make scratch directories,
// check closed meshes.
#include <filesystem>
#include <string>

#include <vector>

#include "src/check/validity.hpp"
#include "src/closure/database.hpp"
#include "src/mesh/hex_mesh.hpp"
#include "src/mesh/quad_surface.hpp"
#include "src/quadmap/quad_map.hpp"

namespace loom::test {

struct CliResult {
  int status = -1;     ///< exit status (128+N if killed by signal N)
  std::string out;     ///< stdout
  std::string err;     ///< stderr
};

/// Runs `build/loom ARGS` through the shell (args are passed verbatim).
CliResult run_cli(const std::string& args);
/// Runs a shell command line, stdin from /dev/null, stdout and stderr captured
/// (the redirections bind to its last simple command).
CliResult run_shell(const std::string& command);
/// run_cli() with the STC invariant checks off, as in a user's run (ctest
/// turns them on for every rule), so that only what such a run checks is checked.
CliResult run_cli_unchecked(const std::string& args);

/// A fresh, empty directory under the system temp dir, removed at destruction.
class ScratchDir {
public:
  explicit ScratchDir(const std::string& tag);
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

private:
  std::filesystem::path path_;
};

/// Path of a file under tests/data.
inline std::filesystem::path data(const std::string& name) { return std::filesystem::path(LOOM_TEST_DATA) / name; }

/// Number of lines in s (a final line without '\n' counts).
int count_lines(const std::string& s);

/// The application lines of the last attempt in a `loom weave --trace`
/// file's text; with `kept`, only those no later `undo STEP` line took back.
std::vector<std::string> trace_applications(const std::string& trace, bool kept);

/// The whole content of a file (empty if unreadable).
std::string slurp(const std::filesystem::path& p);
/// Writes `text` to a file, replacing it.
void spit(const std::filesystem::path& p, const std::string& text);

/// The unit cube as 6 outward quads.
QuadSurface unit_cube();

/// Criteria 1-6 of `hexes` against `surface` (its points first, the rest at random).
ValidityReport check_against(const QuadSurface& surface, const std::vector<Hex>& hexes);
/// A surface for a quad map: its vertices at random.
QuadSurface surface_of(const quadmap::QuadMap& m);
/// The database shipped in rules/, read once.
const closure::Database& shipped_database();

}  // namespace loom::test
