#pragma once
// Sheet diagrams, as in the 1996 report's figures: one sheet drawn flat, its
// loop(s) as the outer boundary, each chord on it as a line that enters at a
// boundary face (labelled outside with the face's boundary id) and carries the
// id of the other sheet it lies on; STC vertices (hexes) where chords cross;
// open whisker ends as small dots.
#include <filesystem>
#include <string>

#include "src/stc/pictures.hpp"
#include "src/stc/stc.hpp"

namespace loom::stc {

/// DOT text of the diagram of `sheet` (neato layout, loop points pinned on a
/// circle in loop order). Sheets and hexes are labelled with their ordinals
/// (the ids `loom stc` prints), boundary faces with their boundary index.
std::string sheet_diagram_dot(const Stc& stc, Id sheet);

/// Writes stc.dot and sheet-K.dot for every sheet K into `dir` (created if
/// needed), each also as .svg (pictures.hpp) when its graph has at most
/// `svg_limit` elements. Returns the number of files written.
std::size_t write_stc_dot(const Stc& stc, const std::filesystem::path& dir, PictureFailures& failures,
                          std::size_t svg_limit = 4000);

}  // namespace loom::stc
