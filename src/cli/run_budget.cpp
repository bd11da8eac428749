#include "src/cli/run_budget.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <sys/resource.h>

#include <fmt/format.h>

#include "src/util/error.hpp"

namespace loom::cli {

namespace {
constexpr auto kProgressEvery = std::chrono::seconds(5);
constexpr double kLongestSeconds = 1e9;  // 30 years
}  // namespace

RunBudget::RunBudget(double max_seconds, std::uint64_t max_megabytes, bool progress_lines)
    : max_seconds_(max_seconds), progress_lines_(progress_lines) {
  // Past these a limit is no limit (and the arithmetic below would overflow).
  if (max_seconds_ > kLongestSeconds) max_seconds_ = 0;
  if (max_megabytes > (RLIM_INFINITY >> 20)) max_megabytes = 0;
  if (max_megabytes > 0) {
    rlimit cap{};
    cap.rlim_cur = cap.rlim_max = static_cast<rlim_t>(max_megabytes) << 20;
    if (::setrlimit(RLIMIT_DATA, &cap) != 0)
      throw InputError(fmt::format("--max-memory {}: the system refused the limit ({}); give a smaller one",
                                   max_megabytes, std::strerror(errno)));
  }
  if (max_seconds_ > 0 || progress_lines_) watchdog_ = std::thread([this] { watch(); });
}

RunBudget::~RunBudget() {
  {
    std::lock_guard lock(mutex_);
    done_ = true;
  }
  wake_.notify_all();
  if (watchdog_.joinable()) watchdog_.join();
}

void RunBudget::stage(const char* name) {
  stage_ = name;
  if (progress_lines_) line();
}

void RunBudget::line() const {
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::fprintf(stderr, "loom: %.1f s: %s\n", seconds, describe().c_str());
  std::fflush(stderr);
}

void RunBudget::weaving(std::uint64_t steps, std::uint64_t hexes, std::uint64_t whiskers) {
  steps_ = steps, hexes_ = hexes, whiskers_ = whiskers;
}

void RunBudget::commit() {
  std::lock_guard lock(mutex_);
  committed_ = true;
}

std::string RunBudget::describe() const {
  std::string what = stage_.load();
  if (what == "weaving")
    what += fmt::format(" ({} steps, {} hexes, {} whiskers left)", steps_.load(), hexes_.load(), whiskers_.load());
  return what;
}

void RunBudget::watch() {
  using clock = std::chrono::steady_clock;
  const auto deadline = max_seconds_ > 0 ? start_ + std::chrono::duration_cast<clock::duration>(
                                                        std::chrono::duration<double>(max_seconds_))
                                         : clock::time_point::max();
  auto next_line = start_ + kProgressEvery;
  std::unique_lock lock(mutex_);
  while (!done_ && !committed_) {
    const auto until = progress_lines_ ? std::min(deadline, next_line) : deadline;
    wake_.wait_until(lock, until, [&] { return done_ || committed_; });
    if (done_ || committed_) break;
    if (clock::now() >= deadline) {
      // The main thread writes nothing before commit(), which takes this lock:
      // ending the process here leaves no file half-written.
      std::fprintf(stderr,
                   "loom: stopped at the --max-seconds budget (%g s) while %s; nothing written; raise "
                   "--max-seconds or mesh a smaller part\n",
                   max_seconds_, describe().c_str());
      std::fflush(stderr);
      std::_Exit(1);
    }
    if (progress_lines_ && clock::now() >= next_line) {
      line();
      next_line = clock::now() + kProgressEvery;
    }
  }
}

}  // namespace loom::cli
