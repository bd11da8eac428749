// Database::build: all meshes a shelling outwards from one hex reaches
// within the limits, breadth first (database.hpp).
#include <algorithm>
#include <array>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

#include "src/closure/cavity.hpp"
#include "src/closure/database.hpp"
#include "src/closure/hex_meeting.hpp"
#include "src/quadmap/hex_glue.hpp"

namespace loom::closure {

using quadmap::Code;
using quadmap::QuadMap;

namespace {

/// A mesh with its boundary's code, its vertices numbered as the code does.
struct MeshEntry {
  Code code;
  std::vector<Hex> hexes;
  std::uint32_t boundary_vertices = 0;
};

/// The entry for a mesh whose boundary, facing out of the mesh, is `outward`.
MeshEntry entry_of(const QuadMap& outward, const std::vector<Hex>& hexes) {
  const auto canon = quadmap::canonical_unoriented(outward);
  const QuadMap read = canon.mirrored ? quadmap::mirrored(outward) : outward;
  std::vector<quadmap::Vertex> label = quadmap::labels_from(read, quadmap::twins(read), canon.starts.front());
  MeshEntry e;
  e.code = canon.code;
  for (quadmap::Vertex l : label)
    if (l != quadmap::no_vertex) e.boundary_vertices = std::max(e.boundary_vertices, l + 1);
  std::uint32_t next = e.boundary_vertices;
  for (const Hex& h : hexes) {
    Hex mapped;
    for (int i = 0; i < 8; ++i) {
      const quadmap::Vertex v = h[i];
      if (v >= label.size()) label.resize(v + 1, quadmap::no_vertex);
      if (label[v] == quadmap::no_vertex) label[v] = next++;
      mapped[i] = label[v];
    }
    e.hexes.push_back(canon.mirrored ? mirror_hex(mapped) : mapped);
  }
  return e;
}

/// One boundary the outward shelling reached: how (from which boundary, by
/// which gluing on that boundary's canonical inner map) and at what cost.
struct Reached {
  std::uint32_t parent;
  std::uint16_t bottom;
  std::uint8_t sides;
  std::uint8_t hexes;
  std::uint16_t quads;
  bool first = true;  ///< the first mesh found for its boundary (the one stored)
};

/// How a mesh's hexes touch its boundary: for each hex with a corner on it,
/// the boundary corners (as the code numbers them), as a hash. Meshes alike
/// in this allow the same gluings outside.
std::uint64_t contact_hash(const MeshEntry& e) {
  std::vector<std::array<std::uint32_t, 9>> contacts;
  for (const Hex& h : e.hexes) {
    std::array<std::uint32_t, 9> c;
    c.fill(UINT32_MAX);
    std::uint32_t n = 0;
    for (std::uint32_t v : h)
      if (v < e.boundary_vertices) c[n++] = v;
    if (n == 0) continue;
    std::sort(c.begin(), c.begin() + n);
    contacts.push_back(c);
  }
  std::sort(contacts.begin(), contacts.end());
  std::uint64_t hash = 1469598103934665603ull;
  for (const auto& c : contacts)
    for (std::uint32_t x : c) hash = (hash ^ x) * 1099511628211ull;
  return hash;
}

/// A boundary still to grow from: its code and the hexes with a corner on it
/// (the only ones a hex glued outside can touch), numbered as the code is.
struct Frontier {
  std::uint32_t node;
  Code code;
  std::vector<Hex> touching;
};

std::uint64_t code_hash(const Code& c) { return quadmap::CodeHash{}(c); }

/// The inner map of a stored boundary: its quads facing away from the mesh's
/// outside (where the next hex goes), vertex ids as the code numbers them.
QuadMap inner_map(const Code& code, const std::vector<Hex>& hexes) {
  QuadMap inner = quadmap::mirrored(quadmap::map_of_code(code));
  for (const Hex& h : hexes)
    for (std::uint32_t v : h) inner.vertex_bound = std::max(inner.vertex_bound, v + 1);
  return inner;
}

/// Whether the hex `glued` places meets each of `hexes` as a valid mesh allows.
bool fits_outside(const quadmap::GluedHex& glued, const QuadMap& inner, const std::vector<Hex>& hexes) {
  std::vector<const Quad*> onto;
  for (int c = 0; c < glued.k; ++c) onto.push_back(&inner.quads[glued.covered[static_cast<std::size_t>(c)]]);
  for (const Hex& h : hexes)
    if (!meets_as_glued(glued.hex, h, onto)) return false;
  return true;
}

std::vector<Hex> touching(const std::vector<Hex>& hexes, std::uint32_t boundary_vertices) {
  std::vector<Hex> out;
  for (const Hex& h : hexes)
    if (std::any_of(h.begin(), h.end(), [&](std::uint32_t v) { return v < boundary_vertices; })) out.push_back(h);
  return out;
}

/// The entry of node `n`, its whole mesh rebuilt by gluing again along the way from the cube.
MeshEntry replay(const std::vector<Reached>& nodes, std::uint32_t n, const MeshEntry& cube) {
  std::vector<std::uint32_t> way;
  for (std::uint32_t at = n; at != 0; at = nodes[at].parent) way.push_back(at);
  MeshEntry e = cube;
  for (auto it = way.rbegin(); it != way.rend(); ++it) {
    const QuadMap inner = inner_map(e.code, e.hexes);
    quadmap::GluedHex glued;
    if (!quadmap::glue_hex(inner, quadmap::twins(inner), quadmap::degrees(inner), {nodes[*it].bottom, nodes[*it].sides},
                           glued))
      throw std::logic_error("database: a stored gluing no longer applies");
    e.hexes.push_back(glued.hex);
    e = entry_of(quadmap::mirrored(glued.after), e.hexes);
  }
  return e;
}

}  // namespace

Database Database::build(const DatabaseLimits& limits, const std::function<void(int, std::size_t)>& progress) {
  const Hex cube{0, 1, 2, 3, 4, 5, 6, 7};
  QuadMap cube_boundary;
  for (const Quad& f : quadmap::outward_faces(cube)) cube_boundary.quads.push_back(f);
  cube_boundary.vertex_bound = 8;
  const MeshEntry cube_entry = entry_of(cube_boundary, {cube});

  std::vector<Reached> nodes{{0, 0, 0, 1, 6}};
  // Per boundary reached, how many of its meshes were grown; when more than
  // one may be, also which contacts those had (boundary and contact hashes mixed).
  const int most = std::clamp(limits.grown_per_boundary, 1, 255);
  auto pair_key = [](std::uint64_t code, std::uint64_t contact) { return code ^ (contact * 0x9E3779B97F4A7C15ull); };
  std::unordered_map<std::uint64_t, std::uint8_t> grown_of{{code_hash(cube_entry.code), 1}};
  std::unordered_set<std::uint64_t> contacts_grown;
  if (most > 1) contacts_grown.insert(pair_key(code_hash(cube_entry.code), contact_hash(cube_entry)));
  std::vector<Frontier> level{{0, cube_entry.code, cube_entry.hexes}};
  if (progress) progress(1, nodes.size());
  for (int hexes = 1; hexes < limits.max_hexes && !level.empty(); ++hexes) {
    std::vector<Frontier> next_level;
    for (const Frontier& f : level) {
      const QuadMap inner = inner_map(f.code, f.touching);
      const auto twin = quadmap::twins(inner);
      const auto degree = quadmap::degrees(inner);
      const QuadsAtVertex at(inner);
      quadmap::GluedHex glued;
      for (std::uint32_t q = 0; q < inner.size(); ++q)
        for (std::uint8_t sides = 0; sides < 16; ++sides) {
          if (!quadmap::glue_hex(inner, twin, degree, {q, sides}, glued)) continue;
          if (glued.after.size() > static_cast<std::size_t>(limits.max_quads)) continue;
          if (!glued_front_is_proper(inner, at, glued)) continue;
          if (!fits_outside(glued, inner, f.touching)) continue;
          std::vector<Hex> grown = f.touching;
          grown.push_back(glued.hex);
          MeshEntry e = entry_of(quadmap::mirrored(glued.after), grown);
          const std::uint64_t code = code_hash(e.code);
          std::uint8_t& meshes_grown = grown_of[code];
          if (meshes_grown >= most) continue;
          if (most > 1 && !contacts_grown.insert(pair_key(code, contact_hash(e))).second) continue;
          const bool first = meshes_grown++ == 0;
          nodes.push_back({f.node, static_cast<std::uint16_t>(q), sides, static_cast<std::uint8_t>(hexes + 1),
                           static_cast<std::uint16_t>(glued.after.size()), first});
          next_level.push_back({static_cast<std::uint32_t>(nodes.size() - 1), std::move(e.code),
                                touching(e.hexes, e.boundary_vertices)});
        }
    }
    level = std::move(next_level);
    if (progress) progress(hexes + 1, nodes.size());
  }

  Database db;
  for (std::uint32_t n = 0; n < nodes.size(); ++n)
    if (nodes[n].first && nodes[n].quads <= limits.store_quads) {
      const MeshEntry m = n == 0 ? cube_entry : replay(nodes, n, cube_entry);
      db.add(entry_of_mesh(m.code, m.hexes));
    }
  return db;
}

}  // namespace loom::closure
