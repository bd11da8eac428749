#pragma once
// Improving the database with its own search (docs/closure.md).
//
// The outward shelling (database_build.cpp) gives each boundary the fewest
// hexes that a shelling through boundaries of at most 24 quads needs, and it
// grows only the first mesh found for each boundary. The search from a
// boundary inwards (shelling_search.hpp) is not bound by either: its fronts
// may grow past 24 quads, and it ends in whatever entry the database holds.
// So each entry's boundary is searched in turn, with the database as it then
// stands, and where the search closes it in fewer hexes the entry takes that
// mesh. Entries are taken in the database's order (fewest hexes first), so
// a later one can end in an earlier one's new mesh. Deterministic: the
// search's budget is in expansions.
#include <cstddef>
#include <functional>

#include "src/closure/database.hpp"
#include "src/closure/shelling_search.hpp"

namespace loom::closure {

struct DatabaseImprovement {
  std::size_t searched = 0;  ///< entries searched
  std::size_t improved = 0;  ///< entries given a smaller mesh
  std::size_t hexes_saved = 0;
};

/// Searches every entry's boundary with `options` (its budget per entry) and
/// keeps the smaller meshes found. `progress` (if set) gets the entries done
/// and the result so far after each entry.
DatabaseImprovement improve_by_search(Database& db, const ClosureOptions& options,
                                      const std::function<void(const DatabaseImprovement&)>& progress = {});

}  // namespace loom::closure
