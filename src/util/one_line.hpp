#pragma once
// The last guard of the error contract (docs/cli.md): whatever a message quotes
// (a path, an argument, bytes of a file), it is printed as one readable line.
#include <cstddef>
#include <string>
#include <string_view>

namespace loom {

/// Longest line one_line() returns, in bytes.
inline constexpr std::size_t max_message_bytes = 1000;

/// `message` made safe to print as one terminal line: control characters
/// (newlines, NUL, escape sequences, C1 controls) and bytes that are not valid
/// UTF-8 become \xNN; valid UTF-8 text is kept. A result longer than
/// max_message_bytes keeps its beginning and its end (the hint) around "...".
std::string one_line(std::string_view message);

}  // namespace loom
