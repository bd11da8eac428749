#include "src/quadmap/canonical.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include <fmt/format.h>

namespace loom::quadmap {

namespace {

constexpr std::uint16_t unlabelled = UINT16_MAX;

/// Reads the map from `start`, comparing as it goes with `best` (when not
/// empty): stops early, returning +1, as soon as the reading is greater.
/// Returns -1 if less than best (or best is empty), 0 if equal; `out` holds
/// the reading when not +1.
class Reader {
public:
  Reader(const QuadMap& m, const std::vector<Dart>& twin) : m_(m), twin_(twin) {
    if (m.vertex_bound >= unlabelled) throw std::length_error("canonical code: too many vertices");
  }

  int read(Dart start, const Code& best, Code& out) {
    label_.assign(m_.vertex_bound, unlabelled);
    entry_.assign(m_.size(), no_dart);
    queue_.clear();
    out.clear();
    std::uint16_t next = 0;
    int order = best.empty() ? -1 : 0;
    entry_[start / 4] = start;
    queue_.push_back(start);
    for (std::size_t head = 0; head < queue_.size(); ++head) {
      const Dart first = queue_[head];
      Dart d = first;
      for (int k = 0; k < 4; ++k, d = next_in_quad(d)) {
        const Vertex v = m_.tail(d);
        if (label_[v] == unlabelled) label_[v] = next++;
        const std::uint16_t x = label_[v];
        if (order == 0) {
          const std::uint16_t b = best[out.size()];
          if (x > b) return +1;
          if (x < b) order = -1;
        }
        out.push_back(x);
      }
      d = first;
      for (int k = 0; k < 4; ++k, d = next_in_quad(d)) {
        const Dart t = twin_[d];
        if (t == no_dart) throw std::logic_error("canonical code: the map is not closed");
        if (entry_[t / 4] == no_dart) {
          entry_[t / 4] = t;
          queue_.push_back(t);
        }
      }
    }
    if (queue_.size() != m_.size()) throw std::logic_error("canonical code: the map is not connected");
    return order;
  }

  const std::vector<std::uint16_t>& labels() const { return label_; }

private:
  const QuadMap& m_;
  const std::vector<Dart>& twin_;
  std::vector<std::uint16_t> label_;
  std::vector<Dart> entry_, queue_;
};

}  // namespace

Canonical canonical_oriented(const QuadMap& m, const std::vector<Dart>& twin) {
  // Only starts whose quad has the least corner degrees (read from the start)
  // can give the least code once those degrees lead it: an invariant prefix
  // that spares reading the map from most darts.
  const auto degree = degrees(m);
  auto prefix = [&](Dart d) {
    std::array<std::uint16_t, 4> p{};
    for (int k = 0; k < 4; ++k, d = next_in_quad(d)) p[k] = static_cast<std::uint16_t>(degree[m.tail(d)]);
    return p;
  };
  std::array<std::uint16_t, 4> least{UINT16_MAX, UINT16_MAX, UINT16_MAX, UINT16_MAX};
  for (Dart d = 0; d < 4 * m.size(); ++d) least = std::min(least, prefix(d));
  Canonical c;
  Reader reader(m, twin);
  Code reading, best;
  for (Dart d = 0; d < 4 * m.size(); ++d) {
    if (prefix(d) != least) continue;
    const int order = reader.read(d, best, reading);
    if (order < 0) {
      best.swap(reading);
      c.starts.assign(1, d);
    } else if (order == 0) {
      c.starts.push_back(d);
    }
  }
  c.code.assign(least.begin(), least.end());
  c.code.insert(c.code.end(), best.begin(), best.end());
  return c;
}

Canonical canonical_oriented(const QuadMap& m) { return canonical_oriented(m, twins(m)); }

Canonical canonical_unoriented(const QuadMap& m) { return canonical_unoriented(m, twins(m)); }

Canonical canonical_unoriented(const QuadMap& m, const std::vector<Dart>& twin) {
  Canonical own = canonical_oriented(m, twin);
  Canonical mirror = canonical_oriented(mirrored(m), mirrored_twins(twin));
  if (mirror.code < own.code) {
    mirror.mirrored = true;
    return mirror;
  }
  return own;
}

std::vector<Vertex> labels_from(const QuadMap& m, const std::vector<Dart>& twin, Dart start) {
  Reader reader(m, twin);
  Code reading;
  reader.read(start, {}, reading);
  std::vector<Vertex> labels(m.vertex_bound, no_vertex);
  for (Vertex v = 0; v < m.vertex_bound; ++v)
    if (reader.labels()[v] != unlabelled) labels[v] = reader.labels()[v];
  return labels;
}

QuadMap map_of_code(const Code& code) {
  QuadMap m;
  for (std::size_t i = kCodePrefix; i + 3 < code.size(); i += 4) {
    m.quads.push_back({code[i], code[i + 1], code[i + 2], code[i + 3]});
    for (int k = 0; k < 4; ++k) m.vertex_bound = std::max<std::uint32_t>(m.vertex_bound, code[i + k] + 1u);
  }
  return m;
}

std::string code_text(const Code& code) {
  std::string s;
  for (std::size_t i = 0; i < code.size(); ++i) {
    if (i > 0) s += i % 4 == 0 ? ' ' : ',';
    s += std::to_string(code[i]);
  }
  return s;
}

}  // namespace loom::quadmap
