#pragma once
// Closing a small closed piece of the weave's front from the closure database
// in one rewrite: the template rule rules/closure/database.rule.
//
// The front component of a whisker is every whisker joined to it across
// edges, when each of its edges lies on exactly two of them (a closed
// surface). When it has at most kMostTemplateQuads faces and the database
// holds its boundary (by canonical code, closure/database.hpp), the entry's
// mesh is placed by an automorphism that meets the hexes round the component
// properly (closure/shelling_search.hpp), and its hexes go into the STC: a
// whisker gets the hex on its open side, every other face, edge and node is
// new, and sheets and chords follow the hexes (parallel edges share a sheet,
// opposite faces a chord; where two meet they are merged into one).
#include <cstddef>

#include "src/closure/database.hpp"
#include "src/stc/stc.hpp"

namespace loom::weave {

/// The database's largest boundaries (database.hpp: stored up to 18 quads).
inline constexpr std::size_t kMostTemplateQuads = 18;

/// Whether the front component of whisker `face` is closed, has at most
/// kMostTemplateQuads faces and the database's mesh for it fits.
bool closes_from_database(const stc::Stc& stc, stc::Id face, const closure::Database& db);

/// Puts the database's mesh into the front component of `face`; returns the
/// hexes added. Throws std::runtime_error where closes_from_database is false.
std::size_t close_from_database(stc::Stc& stc, stc::Id face, const closure::Database& db);

}  // namespace loom::weave
