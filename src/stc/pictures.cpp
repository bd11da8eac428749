#include "src/stc/pictures.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "engine/dot.hpp"
#include "src/util/atomic_file.hpp"

namespace loom::stc {

void PictureFailures::add(const std::filesystem::path& file, const std::string& why) {
  if (count++ == 0) first = fmt::format("{}: {}", file.string(), why);
}

std::string PictureFailures::warning() const {
  if (count == 0) return {};
  return fmt::format("loom: warning: {} picture{} could not be drawn and {} left out (first: {}); every other DOT "
                     "and SVG file is written",
                     count, count == 1 ? "" : "s", count == 1 ? "is" : "are", first);
}

void write_svg(const std::filesystem::path& svg, const std::string& dot, PictureFailures& failures) {
  std::string picture;
  try {
    picture = engine::render_svg(dot);
  } catch (const std::runtime_error& e) {
    failures.add(svg, e.what());
    return;
  }
  write_text_atomically(svg, picture);
}

}  // namespace loom::stc
