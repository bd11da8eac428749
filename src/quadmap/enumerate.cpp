#include "src/quadmap/enumerate.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

#include "src/quadmap/hex_glue.hpp"

namespace loom::quadmap {

std::vector<QuadMap> vertex_splits(const QuadMap& m) {
  const auto twin = twins(m);
  std::vector<Dart> first(m.vertex_bound, no_dart);
  for (Dart d = 0; d < twin.size(); ++d)
    if (first[m.tail(d)] == no_dart) first[m.tail(d)] = d;
  std::vector<QuadMap> out;
  std::vector<Dart> ring;
  for (Vertex v = 0; v < m.vertex_bound; ++v) {
    if (first[v] == no_dart) continue;
    ring.clear();
    Dart d = first[v];
    do {
      ring.push_back(d);
      d = twin[prev_in_quad(d)];
    } while (d != first[v]);
    const auto k = static_cast<int>(ring.size());
    // The quad of ring[i] lies between neighbours head(ring[i]) and
    // head(ring[i+1]). v keeps the quads of ring[i..j-1]; a new vertex c
    // takes the others; the quad (c, n_i, v, n_j) opens between them.
    for (int i = 0; i < k; ++i)
      for (int j = i + 2; j <= i + k - 2 && j < k; ++j) {
        QuadMap split = m;
        const Vertex c = split.vertex_bound++;
        for (int r = j; r != i + k; ++r) {
          Quad& q = split.quads[ring[r % k] / 4];
          for (Vertex& w : q)
            if (w == v) w = c;
        }
        split.quads.push_back({c, m.head(ring[i]), v, m.head(ring[j])});
        out.push_back(std::move(split));
      }
  }
  return out;
}

namespace {

/// Expansions by a hex glued onto one quad (+4) or onto the two quads of one edge (+2).
void hex_expansions(const QuadMap& m, bool single_edge, std::vector<QuadMap>& out) {
  const auto twin = twins(m);
  const auto deg = degrees(m);
  GluedHex glued;
  for (std::uint32_t q = 0; q < m.size(); ++q) {
    if (!single_edge) {
      if (glue_hex(m, twin, deg, {q, 0}, glued)) out.push_back(glued.after);
      continue;
    }
    for (int side = 0; side < 4; ++side)
      if (glue_hex(m, twin, deg, {q, static_cast<std::uint8_t>(1u << side)}, glued) &&
          why_not_simple(glued.after).empty())
        out.push_back(glued.after);
  }
}

}  // namespace

std::vector<QuadrangulationClass> enumerate_quadrangulations(
    int max_quads, const std::function<void(const QuadrangulationClass&)>& progress) {
  std::vector<QuadrangulationClass> classes;
  auto at = [&classes](int quads) -> const QuadrangulationClass* {
    for (const auto& c : classes)
      if (c.quads == quads) return &c;
    return nullptr;
  };
  for (int f = 6; f <= max_quads; ++f) {
    std::set<Code> found;
    auto add = [&found](const QuadMap& m) {
      if (why_not_simple(m).empty()) found.insert(canonical_unoriented(m).code);
    };
    if (f % 2 == 0) add(pseudo_double_wheel(f));
    std::vector<QuadMap> grown;
    if (const auto* c = at(f - 1))
      for (const Code& code : c->codes)
        for (QuadMap& s : vertex_splits(map_of_code(code))) add(s);
    if (const auto* c = at(f - 2))
      for (const Code& code : c->codes) hex_expansions(map_of_code(code), true, grown);
    if (const auto* c = at(f - 4))
      for (const Code& code : c->codes) hex_expansions(map_of_code(code), false, grown);
    for (const QuadMap& m : grown) add(m);
    QuadrangulationClass cls;
    cls.quads = f;
    cls.codes.assign(found.begin(), found.end());
    for (const Code& code : cls.codes) cls.three_connected.push_back(is_three_connected(map_of_code(code)));
    classes.push_back(std::move(cls));
    if (progress) progress(classes.back());
  }
  return classes;
}

std::vector<QuadMap> three_connected_quadrangulations(int quads) {
  if (quads < 6) throw std::invalid_argument("three_connected_quadrangulations: fewer than 6 quads");
  const auto classes = enumerate_quadrangulations(quads);
  std::vector<QuadMap> out;
  const auto& last = classes.back();
  for (std::size_t i = 0; i < last.codes.size(); ++i)
    if (last.three_connected[i]) out.push_back(map_of_code(last.codes[i]));
  return out;
}

}  // namespace loom::quadmap
