#include "src/closure/database_improve.hpp"

#include <algorithm>

namespace loom::closure {

DatabaseImprovement improve_by_search(Database& db, const ClosureOptions& options,
                                      const std::function<void(const DatabaseImprovement&)>& progress) {
  DatabaseImprovement result;
  for (std::size_t i = 0; i < db.size(); ++i) {
    const Database::Entry& e = db.entries()[i];
    // The code's map faces away from the mesh, as a cavity's front does.
    const ClosureResult r = close_cavity(surface_cavity(quadmap::map_of_code(e.code)), &db, options);
    ++result.searched;
    if (r.closed && r.hexes.size() < e.hexes()) {
      result.hexes_saved += e.hexes() - r.hexes.size();
      ++result.improved;
      // The search places hexes from the boundary inwards; an entry lists
      // them outwards, the last one taken off first.
      std::vector<Hex> outwards(r.hexes.rbegin(), r.hexes.rend());
      db.replace(entry_of_mesh(e.code, outwards));
    }
    if (progress) progress(result);
  }
  return result;
}

}  // namespace loom::closure
