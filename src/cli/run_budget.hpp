#pragma once
// What a user may bound in one `loom weave` run, and what it shows of itself:
//   --max-seconds S  a watchdog thread stops the run at S seconds, with one
//                    line naming the stage it was in and status 1. Outputs are
//                    written only at the end, after commit(), so nothing is
//                    half-written; from commit() on, the run finishes.
//   --max-memory MB  the process's data segment is capped (RLIMIT_DATA): an
//                    allocation beyond it fails, and main() reports it, status 1.
//   --progress       a line on stderr as each stage starts and every 5 s,
//                    also when stderr is not a terminal (a log, a batch job).
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>

namespace loom::cli {

class RunBudget {
public:
  /// 0: no limit. Throws loom::InputError when the memory cap cannot be set.
  RunBudget(double max_seconds, std::uint64_t max_megabytes, bool progress_lines);
  ~RunBudget();
  RunBudget(const RunBudget&) = delete;
  RunBudget& operator=(const RunBudget&) = delete;

  /// What the run is doing, for the stop line and the progress lines.
  void stage(const char* name);
  void weaving(std::uint64_t steps, std::uint64_t hexes, std::uint64_t whiskers);
  /// The run is writing its outputs: it is no longer stopped.
  void commit();

private:
  void watch();
  std::string describe() const;
  void line() const;

  double max_seconds_;
  bool progress_lines_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::atomic<const char*> stage_{"reading"};
  std::atomic<std::uint64_t> steps_{0}, hexes_{0}, whiskers_{0};
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false, committed_ = false;
  std::thread watchdog_;
};

}  // namespace loom::cli
