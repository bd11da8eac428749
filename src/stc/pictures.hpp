#pragma once
// SVG pictures beside DOT files. A picture is never worth a run: when
// Graphviz cannot draw one, its SVG is left out, its DOT stays, and the run
// warns once at the end; so does a sheet diagram that cannot be traced (a
// weave state whose boundary is pinched).
#include <cstddef>
#include <filesystem>
#include <string>

namespace loom::stc {

struct PictureFailures {
  std::size_t count = 0;
  std::string first;  ///< "FILE: why" of the first failure

  void add(const std::filesystem::path& file, const std::string& why);
  /// The warning line for the user ("loom: warning: ..."); empty when none failed.
  std::string warning() const;
};

/// Writes `dot` rendered as SVG to `svg` (atomically), or counts in
/// `failures` why it could not be drawn.
void write_svg(const std::filesystem::path& svg, const std::string& dot, PictureFailures& failures);

}  // namespace loom::stc
