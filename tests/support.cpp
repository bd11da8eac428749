#include "tests/support.hpp"

#include <fstream>
#include <random>
#include <sstream>
#include <sys/wait.h>

namespace loom::test {

namespace {
std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
}  // namespace

CliResult run_cli(const std::string& args) {
  ScratchDir io("cli");
  auto out = io / "out.txt", err = io / "err.txt";
  std::string cmd = std::string(LOOM_CLI) + " " + args + " >" + out.string() + " 2>" + err.string() + " </dev/null";
  int raw = std::system(cmd.c_str());
  CliResult r;
  if (WIFEXITED(raw)) r.status = WEXITSTATUS(raw);
  else if (WIFSIGNALED(raw)) r.status = 128 + WTERMSIG(raw);
  r.out = slurp(out);
  r.err = slurp(err);
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

}  // namespace loom::test
