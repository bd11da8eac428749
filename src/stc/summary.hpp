#pragma once
// Counts that describe an STC: what `loom stc` prints.
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "src/stc/stc.hpp"

namespace loom::stc {

struct SheetSummary {
  std::size_t index = 0;            ///< ordinal among sheets (the id shown in diagrams)
  std::size_t loops = 0;            ///< boundary loops (0: a pillow sheet; >1: merged sheets)
  std::size_t loop_length = 0;      ///< boundary edges over all its loops
  std::size_t self_crossing_quads = 0;  ///< boundary faces its loops cross twice
  std::size_t self_hexes = 0;       ///< hexes it passes twice (self-intersection inside)
  bool self_intersecting = false;
};

struct StcSummary {
  std::size_t hexes = 0, faces = 0, edges = 0, nodes = 0, sheets = 0, chords = 0;
  std::size_t boundary_faces = 0, whiskers = 0;
  std::size_t loops = 0;  ///< boundary loops over all sheets
  std::size_t self_intersecting_sheets = 0, self_intersecting_chords = 0;
  std::vector<SheetSummary> sheet_list;
};

StcSummary summarize(const Stc& stc);

/// Human-readable lines: counts, then one line per self-intersecting sheet.
std::string to_text(const StcSummary& s, bool surface);
nlohmann::json to_json(const StcSummary& s);

}  // namespace loom::stc
