#pragma once
#include <chrono>

namespace loom {

/// Wall-clock laps, for profiles that say where a run's time went.
class Stopwatch {
public:
  /// Seconds since the last lap (or since made).
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return s;
  }

private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace loom
