#pragma once
// Errors that reach the user. An InputError is bad input or bad usage: the CLI
// prints its one line and exits with status 2. Its message says what is wrong,
// where, and what to do.
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace loom {

class InputError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Builds the one-line message "WHERE: WHAT; HINT" (hint optional).
[[noreturn]] inline void fail_input(const std::string& where, const std::string& what,
                                    const std::string& hint = {}) {
  throw InputError(hint.empty() ? fmt::format("{}: {}", where, what)
                                : fmt::format("{}: {}; {}", where, what, hint));
}

}  // namespace loom
