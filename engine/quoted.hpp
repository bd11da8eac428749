#pragma once
// Names and words from a file, made safe to quote in a one-line message: the
// bytes that are not printable ASCII shown as \xNN, and a long one cut to 40
// of them (found by fuzzing: a schema file's raw bytes, or a 1,000-byte name,
// made its error line unreadable). The engine's copy of src/io's quote_token.
#include <string>
#include <string_view>

#include <fmt/format.h>

namespace loom::engine {

inline std::string printable(std::string_view text) {
  std::string out;
  for (char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f) out += c;
    else out += fmt::format("\\x{:02x}", byte);
  }
  return out;
}

/// 'text', escaped as printable() does and cut to 40 bytes with "...".
inline std::string quoted(std::string_view text) {
  constexpr std::size_t limit = 40;
  return "'" + printable(text.substr(0, limit)) + (text.size() > limit ? "...'" : "'");
}

}  // namespace loom::engine
