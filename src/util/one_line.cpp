#include "src/util/one_line.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace loom {

namespace {

// Length of the valid, printable UTF-8 sequence starting at text[i], or 0.
std::size_t printable_sequence(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  if (lead >= 0x20 && lead < 0x7f) return 1;
  std::size_t length = 0;
  if (lead >= 0xc2 && lead <= 0xdf) length = 2;
  else if (lead >= 0xe0 && lead <= 0xef) length = 3;
  else if (lead >= 0xf0 && lead <= 0xf4) length = 4;
  if (length == 0 || i + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k)
    if ((byte(i + k) & 0xc0) != 0x80) return 0;
  // Overlong forms, surrogates, code points past U+10FFFF, and C1 controls.
  const unsigned char second = byte(i + 1);
  if ((lead == 0xe0 && second < 0xa0) || (lead == 0xed && second >= 0xa0) || (lead == 0xf0 && second < 0x90) ||
      (lead == 0xf4 && second >= 0x90) || (lead == 0xc2 && second < 0xa0))
    return 0;
  return length;
}

// The largest position <= at that is not inside a UTF-8 sequence or a \xNN
// escape, so that cutting there leaves both sides readable.
std::size_t boundary_before(std::string_view text, std::size_t at) {
  while (at > 0 && at < text.size() && (static_cast<unsigned char>(text[at]) & 0xc0) == 0x80) --at;
  for (std::size_t back = 1; back <= 3 && back <= at; ++back)
    if (text.substr(at - back, 2) == "\\x") return at - back;
  return at;
}

}  // namespace

std::string one_line(std::string_view message) {
  std::string out;
  out.reserve(std::min(message.size(), 4 * max_message_bytes));
  for (std::size_t i = 0; i < message.size();) {
    if (std::size_t n = printable_sequence(message, i)) {
      out.append(message.substr(i, n));
      i += n;
    } else {
      out += fmt::format("\\x{:02x}", static_cast<unsigned char>(message[i]));
      ++i;
    }
  }
  if (out.size() <= max_message_bytes) return out;
  constexpr std::string_view gap = " ... ";
  constexpr std::size_t tail_bytes = 300;  // room for the hint at the end
  const std::size_t head = boundary_before(out, max_message_bytes - tail_bytes - gap.size());
  // + 3: boundary_before() moves back at most 3 bytes.
  const std::size_t tail = boundary_before(out, out.size() - tail_bytes + 3);
  return out.substr(0, head) + std::string(gap) + out.substr(tail);
}

}  // namespace loom
