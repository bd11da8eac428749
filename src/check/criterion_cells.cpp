// Criteria 1-3: cells, faces, doublets.
#include <algorithm>
#include <bit>

#include "src/check/criteria.hpp"
#include "src/check/key_numbering.hpp"

namespace loom::criteria {

CriterionResult passed(int number) { return {number, criterion_name(number), true, {}}; }

CriterionResult failed(int number, std::string detail) {
  return {number, criterion_name(number), false, std::move(detail)};
}

CriterionResult distinct_nodes(const HexMesh& mesh) {
  if (mesh.hexes.empty()) return failed(1, "the mesh has no hexes");
  std::size_t bad = 0;
  std::string first;
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
    const Hex& hex = mesh.hexes[h];
    std::string problem;
    for (int i = 0; i < 8 && problem.empty(); ++i) {
      if (hex[i] >= mesh.points.size())
        problem = fmt::format("hex {} refers to node {}, but the mesh has {} nodes", h, hex[i], mesh.points.size());
      for (int j = 0; j < i && problem.empty(); ++j)
        if (hex[i] == hex[j]) problem = fmt::format("hex {} uses node {} twice (corners {} and {})", h, hex[i], j, i);
    }
    if (problem.empty()) continue;
    if (bad++ == 0) first = problem;
  }
  if (bad == 0) return passed(1);
  return failed(1, bad == 1 ? first : fmt::format("{} ({} hexes fail)", first, bad));
}

CriterionResult faces_in_one_or_two_hexes(const HexMesh& mesh, const HexTopology& topo) {
  const std::size_t hexes = mesh.hexes.size();
  auto hex_key = [&](std::size_t h) {
    Hex key = mesh.hexes[h];
    std::sort(key.begin(), key.end());
    return key;
  };
  const KeyNumbering cells = number_by_key<8>(hexes, mesh.points.size(), hex_key);
  if (cells.distinct != hexes) {
    std::vector<std::uint32_t> first_with(cells.distinct, kNoSide);
    std::size_t duplicates = 0;
    std::string first;
    for (std::uint32_t h = 0; h < hexes; ++h) {
      std::uint32_t& original = first_with[cells.number[h]];
      if (original == kNoSide) {
        original = h;
      } else if (duplicates++ == 0) {
        first = fmt::format("hexes {} and {} are the same hex (same 8 nodes)", original, h);
      }
    }
    return failed(2, duplicates == 1 ? first : fmt::format("{} ({} duplicated hexes)", first, duplicates));
  }

  std::size_t overfull = 0;
  std::uint32_t worst_face = kNoSide;
  for (std::uint32_t item = 0; item < topo.hex_faces.size(); ++item) {
    const std::uint32_t f = topo.hex_faces[item];
    if (topo.face_hex_count[f] <= 2 || topo.face_sides[f][0] != item) continue;
    if (overfull++ == 0) worst_face = f;
  }
  if (overfull == 0) return passed(2);
  std::vector<std::uint32_t> holders;
  for (std::uint32_t item = 0; item < topo.hex_faces.size(); ++item)
    if (topo.hex_faces[item] == worst_face) holders.push_back(item / 6);
  const std::uint32_t side = topo.face_sides[worst_face][0];
  const auto nodes = face_nodes(mesh.hexes[side / 6], static_cast<int>(side % 6));
  std::string detail =
      fmt::format("face {} is in {} hexes: {}", fmt::join(nodes, "-"), holders.size(), fmt::join(holders, ", "));
  if (overfull > 1) detail += fmt::format(" ({} such faces)", overfull);
  return failed(2, detail);
}

CriterionResult no_doublets(const HexMesh& mesh, const HexTopology& topo) {
  std::size_t pairs = 0;
  std::string first;
  for (std::uint32_t h = 0; h < mesh.hexes.size(); ++h) {
    std::array<std::uint32_t, 6> across{};
    int count = 0;
    for (int lf = 0; lf < 6; ++lf) {
      const std::uint32_t f = topo.hex_faces[6 * h + lf];
      if (topo.face_hex_count[f] < 2) continue;
      const auto& sides = topo.face_sides[f];
      const std::uint32_t other = (sides[0] / 6 == h ? sides[1] : sides[0]) / 6;
      if (other != h) across[count++] = other;
    }
    for (int i = 1; i < count; ++i)  // insertion sort: at most 6 (std::sort here trips GCC 12's -Warray-bounds)
      for (int j = i; j > 0 && across[j] < across[j - 1]; --j) std::swap(across[j], across[j - 1]);
    for (int i = 0; i + 1 < count; ++i) {
      if (across[i] != across[i + 1] || (i > 0 && across[i] == across[i - 1])) continue;
      if (across[i] < h) continue;  // counted from the smaller hex
      int shared = 2;
      while (i + shared < count && across[i + shared] == across[i]) ++shared;
      if (pairs++ == 0) first = fmt::format("hexes {} and {} share {} faces", h, across[i], shared);
    }
  }
  if (pairs > 0)
    return failed(3, pairs == 1 ? first : fmt::format("{} ({} pairs of hexes share more than one face)", first, pairs));
  return hexes_meet_properly(mesh);
}

CriterionResult hexes_meet_properly(const HexMesh& mesh) {
  // Hexes at each node (CSR), then every pair meeting at some node.
  const std::size_t nodes = mesh.points.size();
  std::vector<std::uint32_t> start(nodes + 1, 0), at;
  for (const Hex& hex : mesh.hexes)
    for (auto n : hex) ++start[n + 1];
  for (std::size_t n = 0; n < nodes; ++n) start[n + 1] += start[n];
  at.resize(start[nodes]);
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::uint32_t h = 0; h < mesh.hexes.size(); ++h)
    for (auto n : mesh.hexes[h]) at[fill[n]++] = h;
  std::size_t bad = 0;
  std::string first;
  std::vector<std::pair<std::uint32_t, unsigned>> met;  // (other hex, corners of h it has)
  for (std::uint32_t h = 0; h < mesh.hexes.size(); ++h) {
    met.clear();
    for (int k = 0; k < 8; ++k) {
      auto n = mesh.hexes[h][k];
      for (auto i = start[n]; i < start[n + 1]; ++i)
        if (at[i] > h) met.emplace_back(at[i], 1u << k);
    }
    std::sort(met.begin(), met.end());
    for (std::size_t i = 0; i < met.size();) {
      std::uint32_t g = met[i].first;
      unsigned mine = 0;
      for (; i < met.size() && met[i].first == g; ++i) mine |= met[i].second;
      if (std::popcount(mine) == 1) continue;
      unsigned theirs = 0;
      for (int k = 0; k < 8; ++k)
        for (int j = 0; j < 8; ++j)
          if ((mine >> j & 1u) && mesh.hexes[g][k] == mesh.hexes[h][j]) theirs |= 1u << k;
      if (is_hex_edge_or_face(mine) && is_hex_edge_or_face(theirs)) continue;
      if (bad++ == 0)
        first = fmt::format("hexes {} and {} meet in {} nodes that are not one face, one edge or one node of both", h,
                            g, std::popcount(mine));
    }
  }
  if (bad == 0) return passed(3);
  return failed(3, bad == 1 ? first : fmt::format("{} ({} such pairs)", first, bad));
}

}  // namespace loom::criteria
