#include "tests/support.hpp"

#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>

#include "src/weave/weave.hpp"

namespace loom::test {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void spit(const std::filesystem::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
}

QuadSurface unit_cube() {
  QuadSurface s;
  s.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  s.quads = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  return s;
}

CliResult run_cli(const std::string& args) { return run_shell(std::string(LOOM_CLI) + " " + args); }

CliResult run_shell(const std::string& command) {
  ScratchDir io("cli");
  auto out = io / "out.txt", err = io / "err.txt";
  std::string cmd = command + " >" + out.string() + " 2>" + err.string() + " </dev/null";
  int raw = std::system(cmd.c_str());
  CliResult r;
  if (WIFEXITED(raw)) r.status = WEXITSTATUS(raw);
  else if (WIFSIGNALED(raw)) r.status = 128 + WTERMSIG(raw);
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

CliResult run_cli_unchecked(const std::string& args) {
  const char* was = std::getenv("LOOM_CHECK_INVARIANTS");
  const std::string saved = was ? was : "";
  ::setenv("LOOM_CHECK_INVARIANTS", "0", 1);
  CliResult r = run_cli(args);
  if (was) ::setenv("LOOM_CHECK_INVARIANTS", saved.c_str(), 1);
  else ::unsetenv("LOOM_CHECK_INVARIANTS");
  return r;
}

ScratchDir::ScratchDir(const std::string& tag) {
  static std::mt19937_64 rng(std::random_device{}());
  path_ = std::filesystem::temp_directory_path() /
          ("loom-test-" + tag + "-" + std::to_string(rng()));
  std::filesystem::create_directories(path_);
}

ScratchDir::~ScratchDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  if (!s.empty() && s.back() != '\n') ++n;
  return n;
}

std::vector<std::string> trace_applications(const std::string& trace, bool kept) {
  std::vector<std::string> lines;
  std::istringstream in(trace);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("# attempt ", 0) == 0) {
      lines.clear();
    } else if (line.rfind("undo ", 0) == 0) {
      if (!kept) continue;
      const std::string step = line.substr(5) + " ";
      // Undone newest first: the last line kept is the one named.
      if (lines.empty() || lines.back().rfind(step, 0) != 0)
        throw std::runtime_error("trace: '" + line + "' does not undo the latest application kept");
      lines.pop_back();
    } else {
      lines.push_back(line);
    }
  }
  return lines;
}

ValidityReport check_against(const QuadSurface& surface, const std::vector<Hex>& hexes) {
  HexMesh mesh{surface.points, hexes};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  for (const Hex& h : hexes)
    for (std::uint32_t v : h)
      while (mesh.points.size() <= v) mesh.points.push_back({u(rng), u(rng), u(rng)});
  return check_hex_mesh(mesh, &surface);
}

QuadSurface surface_of(const quadmap::QuadMap& m) {
  QuadSurface s{{}, m.quads};
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (std::uint32_t v = 0; v < m.vertex_bound; ++v) s.points.push_back({u(rng), u(rng), u(rng)});
  return s;
}

const closure::Database& shipped_database() {
  static const closure::Database db = closure::Database::load(closure::database_file(weave::default_rules_dir()));
  return db;
}

}  // namespace loom::test
