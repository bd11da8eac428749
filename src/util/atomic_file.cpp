#include "src/util/atomic_file.hpp"

#include <fstream>
#include <system_error>
#include <unistd.h>

#include "src/util/error.hpp"

namespace loom {

void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path&)>& write) {
  namespace fs = std::filesystem;
  fs::path dir = target.parent_path();
  if (dir.empty()) dir = ".";
  if (!fs::is_directory(dir))
    fail_input(target.string(), "output directory does not exist", "create it or choose another path");
  fs::path tmp = dir / fmt::format(".{}.loom-tmp-{}{}", target.stem().string(), ::getpid(),
                                   target.extension().string());
  try {
    write(tmp);
  } catch (...) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw;
  }
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    fail_input(target.string(), "cannot write output file (" + ec.message() + ")",
               "check the path and permissions");
  }
}

void write_text_atomically(const std::filesystem::path& target, const std::string& content) {
  write_atomically(target, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << content;
    out.close();
    if (!out) fail_input(target.string(), "cannot write output file", "check the path, permissions and free space");
  });
}

}  // namespace loom
