#pragma once
// The distribution of the scaled Jacobians of a hex mesh (docs/validity.md,
// criterion 7): counts in twenty bins of width 0.1 from -1 to 1, as the report
// gives it, and the same as an SVG bar chart (`loom weave --plot`, `loom check
// --plot`).
#include <array>
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "src/mesh/hex_mesh.hpp"

namespace loom {

struct QualityHistogram {
  static constexpr double kFrom = -1.0, kWidth = 0.1;
  /// counts[i]: hexes with a scaled Jacobian in [kFrom + i kWidth, kFrom + (i+1) kWidth),
  /// the last bin closed at 1.
  std::array<std::size_t, 20> counts{};
  std::size_t total() const;
  /// Counts one hex of scaled Jacobian `sj` (a NaN, a degenerate hex, with the worst).
  void add(double sj);
};

QualityHistogram quality_histogram(const HexMesh& mesh);

/// {"from": -1, "width": 0.1, "counts": [20 numbers]}
nlohmann::json histogram_json(const QualityHistogram& h);

/// A bar chart: bins at or below 0 red, those below 0.2 orange, the rest
/// green; the axis from -1 to 1; `title` above it.
std::string histogram_svg(const QualityHistogram& h, const std::string& title);

}  // namespace loom
