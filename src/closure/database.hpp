#pragma once
// The database of small hexahedrizations: for each quadrangulation it holds,
// a hex mesh with that boundary, found by Loom itself (docs/closure.md).
//
// Built by shelling outwards from one hex (database_build.cpp): every mesh of
// n + 1 hexes is a mesh of n with one hex glued onto its boundary
// (hex_glue.hpp), kept when its boundary stays proper and the new hex meets
// the others properly. Breadth first, so the first mesh found for a boundary
// has the fewest hexes such a shelling gives it; up to grown_per_boundary
// meshes of each boundary are grown on. Boundaries are keyed by
// their canonical code up to reflection (canonical.hpp).
//
// An entry stores its mesh as a shelling from the boundary inwards: start
// from the code's map (its quads facing away from the mesh, as a cavity's
// front does), glue a hex as each gluing says, and fill the cube left at the
// end. mesh() replays it; vertices 0..n-1 are the boundary's as the code
// numbers them, new ones follow.
//
// On disk (rules/closure/database.txt, scripts/make-database.sh) one line
// per entry: `entry Q H | code | b.s b.s ...`, Q boundary quads, H hexes, the
// code's numbers, then per gluing its bottom quad and sides (0..15).
#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <mutex>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "src/mesh/hex_mesh.hpp"
#include "src/quadmap/canonical.hpp"
#include "src/quadmap/hex_glue.hpp"

namespace loom::closure {

struct DatabaseLimits {
  int max_hexes = 6;     ///< meshes of up to this many hexes (at most 255)
  int max_quads = 24;    ///< boundaries of up to this many quads are grown
  int store_quads = 24;  ///< of those, boundaries of up to this many quads are kept
  /// Meshes grown further per boundary: the first one found, and then others
  /// whose hexes touch the boundary in other corners (another mesh inside the
  /// same boundary allows other gluings outside it). Only the first is kept.
  int grown_per_boundary = 1;
};

class Database {
public:
  struct Entry {
    quadmap::Code code;
    std::vector<quadmap::Gluing> shelling;  ///< all hexes but the last cube
    std::size_t hexes() const { return shelling.size() + 1; }
  };

  Database() = default;
  /// Shells outwards from one hex as DatabaseLimits allows. `progress` (if
  /// set) gets the number of hexes done and the meshes grown so far (one per
  /// boundary reached when grown_per_boundary is 1).
  static Database build(const DatabaseLimits& limits,
                        const std::function<void(int hexes, std::size_t meshes)>& progress = {});
  /// Throws InputError naming the file and line for anything it cannot read.
  static Database load(const std::filesystem::path& file);
  /// The same from the file's text; `where` names it in errors.
  static Database parse(std::string_view text, const std::string& where);
  /// Writes every entry, in order, atomically.
  void save(const std::filesystem::path& file) const;

  const Entry* find(const quadmap::Code& code) const;
  /// mesh_of one of this database's entries, replayed the first time it is
  /// asked for (by any thread) and kept: a search asks for the same entries at
  /// many fronts, and replaying all of them at load would take a second.
  const std::vector<Hex>& mesh(const Entry& e) const;
  /// mesh(e) on a front of e's boundary: `read` is the front as its canonical
  /// code reads it (mirrored when the code is its mirror image's), `start`
  /// one of the code's start darts. Boundary vertices are named as the front
  /// names them, inner ones numbered from read.vertex_bound on.
  std::vector<Hex> mesh_on(const Entry& e, const quadmap::QuadMap& read, const std::vector<quadmap::Dart>& twin,
                           quadmap::Dart start, bool mirrored) const;
  const std::vector<Entry>& entries() const { return entries_; }
  std::size_t size() const { return entries_.size(); }
  void add(Entry e);
  /// Gives the entry with e's code e's mesh instead; std::logic_error if
  /// there is no such entry.
  void replace(Entry e);

private:
  std::vector<Entry> entries_;
  mutable std::deque<std::once_flag> replayed_;  ///< per entry: its mesh is in meshes_
  mutable std::vector<std::vector<Hex>> meshes_;
  std::unordered_map<quadmap::Code, std::uint32_t, quadmap::CodeHash> index_;
};

/// The hexes of an entry, by replaying its shelling. Throws std::logic_error
/// when a gluing does not apply (a corrupt entry).
std::vector<Hex> mesh_of(const Database::Entry& e);

/// The entry of a mesh given with its boundary's code (vertex ids as the code
/// numbers them, inner ones after): the shelling that takes its hexes off in
/// the reverse of `hexes`' order. Throws std::logic_error if that is not a
/// shelling of the mesh.
Database::Entry entry_of_mesh(const quadmap::Code& code, const std::vector<Hex>& hexes);

/// rules/closure/database.txt in the rules directory given.
std::filesystem::path database_file(const std::filesystem::path& rules_dir);

}  // namespace loom::closure
