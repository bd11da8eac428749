#include "src/gen/sphere_quadrangulation.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace loom::gen {

namespace {

bool all_distinct(const std::array<std::uint32_t, 6>& nodes) {
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (std::size_t j = i + 1; j < nodes.size(); ++j)
      if (nodes[i] == nodes[j]) return false;
  return true;
}

int corner_of(const Quad& q, std::uint32_t node) {
  for (int k = 0; k < 4; ++k)
    if (q[k] == node) return k;
  throw std::logic_error("SphereQuadrangulation: node missing from its quad");
}

}  // namespace

SphereQuadrangulation::SphereQuadrangulation(int faces) {
  if (faces < 6 || faces % 2 != 0) throw std::logic_error("SphereQuadrangulation: needs an even count >= 6");
  const auto cycle = static_cast<std::uint32_t>(faces);
  const std::uint32_t top = cycle, bottom = cycle + 1;
  auto c = [cycle](std::uint32_t i) { return i % cycle; };
  degree_.assign(cycle + 2, 3);
  degree_[top] = degree_[bottom] = faces / 2;
  // The cycle runs counter-clockwise seen from above the top hub.
  for (std::uint32_t i = 0; i < cycle; i += 2) {
    quads_.push_back({top, c(i), c(i + 1), c(i + 2)});
    quads_.push_back({bottom, c(i + 3), c(i + 2), c(i + 1)});
  }
  for (std::uint32_t q = 0; q < quads_.size(); ++q) set_quad(q, quads_[q]);
}

void SphereQuadrangulation::set_quad(std::uint32_t index, const Quad& quad) {
  quads_[index] = quad;
  for (int k = 0; k < 4; ++k) quad_left_of_[key(quad[k], quad[(k + 1) % 4])] = index;
}

void SphereQuadrangulation::unlink_quad(std::uint32_t index) {
  const Quad& quad = quads_[index];
  for (int k = 0; k < 4; ++k) quad_left_of_.erase(key(quad[k], quad[(k + 1) % 4]));
}

std::uint32_t SphereQuadrangulation::add_quad(const Quad& quad) {
  quads_.push_back(quad);
  const auto index = static_cast<std::uint32_t>(quads_.size() - 1);
  set_quad(index, quad);
  return index;
}

std::uint32_t SphereQuadrangulation::add_node(int degree) {
  degree_.push_back(degree);
  return static_cast<std::uint32_t>(degree_.size() - 1);
}

std::array<std::uint32_t, 6> SphereQuadrangulation::hexagon(std::size_t quad, int side,
                                                            std::uint32_t& neighbour) const {
  // quad = (u, v, a1, a0); its neighbour = (v, u, b0, b1).
  const Quad& qa = quads_[quad];
  const std::uint32_t u = qa[side], v = qa[(side + 1) % 4], a1 = qa[(side + 2) % 4], a0 = qa[(side + 3) % 4];
  neighbour = quad_along(v, u);
  const Quad& qb = quads_[neighbour];
  const int j = corner_of(qb, v);
  return {u, qb[(j + 2) % 4], qb[(j + 3) % 4], v, a1, a0};
}

void SphereQuadrangulation::hex_flip_1(std::size_t quad) {
  const auto index = static_cast<std::uint32_t>(quad);
  const Quad old = quads_[index];
  unlink_quad(index);
  Quad inner;
  for (int k = 0; k < 4; ++k) {
    inner[k] = add_node(3);
    ++degree_[old[k]];
  }
  for (int k = 0; k < 4; ++k) {
    const Quad side{old[k], old[(k + 1) % 4], inner[(k + 1) % 4], inner[k]};
    if (k == 0)
      set_quad(index, side);
    else
      add_quad(side);
  }
  add_quad(inner);
}

bool SphereQuadrangulation::hex_flip_2(std::size_t quad, int side) {
  std::uint32_t b = 0;
  const std::array<std::uint32_t, 6> h = hexagon(quad, side, b);
  if (degree_[h[0]] < 4 || degree_[h[3]] < 4 || !all_distinct(h)) return false;
  const auto a = static_cast<std::uint32_t>(quad);
  unlink_quad(a);
  unlink_quad(b);
  // x is joined to h[1] and h[5] (the u side), y to h[2] and h[4] (the v side).
  const std::uint32_t x = add_node(3), y = add_node(3);
  set_quad(a, {h[0], h[1], x, h[5]});
  set_quad(b, {h[1], h[2], y, x});
  add_quad({h[2], h[3], h[4], y});
  add_quad({h[4], h[5], x, y});
  --degree_[h[0]], --degree_[h[3]];
  for (int k : {1, 2, 4, 5}) ++degree_[h[k]];
  return true;
}

bool SphereQuadrangulation::diagonal_slide(std::size_t quad, int side, int which) {
  std::uint32_t b = 0;
  const std::array<std::uint32_t, 6> h = hexagon(quad, side, b);
  const auto a = static_cast<std::uint32_t>(quad);
  const std::uint32_t u = h[0], v = h[3];
  const int s = 1 + which;
  auto at = [&h, s](int k) { return h[(s + k) % 6]; };
  if (degree_[u] < 4 || degree_[v] < 4 || !all_distinct(h) || has_edge(at(0), at(3))) return false;
  unlink_quad(a);
  unlink_quad(b);
  set_quad(a, {at(0), at(1), at(2), at(3)});
  set_quad(b, {at(3), at(4), at(5), at(0)});
  --degree_[u], --degree_[v];
  ++degree_[at(0)], ++degree_[at(3)];
  return true;
}

bool SphereQuadrangulation::hex_flip_3(std::size_t quad, int corner) {
  const std::uint32_t c = quads_[quad][corner];
  if (degree_[c] != 3) return false;
  // The three quads around c in counter-clockwise order, each as (c, n_i, m_i, n_{i+1}).
  std::array<std::uint32_t, 3> around{static_cast<std::uint32_t>(quad), 0, 0};
  std::array<std::uint32_t, 3> n{}, m{};
  for (int i = 0; i < 3; ++i) {
    const Quad& q = quads_[around[i]];
    const int k = corner_of(q, c);
    n[i] = q[(k + 1) % 4];
    m[i] = q[(k + 2) % 4];
    if (i < 2) around[i + 1] = quad_along(c, q[(k + 3) % 4]);
  }
  if (!all_distinct({n[0], m[0], n[1], m[1], n[2], m[2]})) return false;
  for (std::uint32_t node : n)
    if (degree_[node] < 4) return false;
  for (std::uint32_t q : around) unlink_quad(q);
  // c moves to the hex's far corner, joined to the three m_i.
  for (int i = 0; i < 3; ++i) set_quad(around[i], {c, m[(i + 2) % 3], n[i], m[i]});
  for (int i = 0; i < 3; ++i) --degree_[n[i]], ++degree_[m[i]];
  return true;
}

}  // namespace loom::gen
