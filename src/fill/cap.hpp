#pragma once
// A cap: the hex mesh of the region between one surface quad and the inner
// surface the constructive fill builds under it (docs/fill.md). Its nodes are
// named by role relative to the quad a b c d (a and c black, b and d white in
// the surface's two-colouring):
//   a_t..d_t  the quad's own nodes;   a_b..d_b  their copies on the inner surface
//   b_m, d_m  the midpoints of the white corners' vertical edges
//   Mab Mbc Mcd Mda  inner midpoints of the quad's edges
//   Wab ...   centres of the odd walls (every wall but the even one)
//   Mdiag     midpoint of the inner diagonal a' c'; Gd0 Gd1 centroids of the
//             triangles at b' and at d'
//   iN        nodes inside the cap
// Caps are data (rules/fill/*.cap, written by scripts/make-caps.py), not code.
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "src/mesh/vec3.hpp"

namespace loom::fill {

/// A role: what a cap node stands for. `corner`/`edge` count from a (0) round
/// the quad; edge k joins corner k to corner k+1.
struct CapRole {
  enum class Kind : std::uint8_t { top, bottom, white_mid, edge_mid, wall_centre, diagonal_mid, triangle_centroid, inside };
  Kind kind = Kind::inside;
  std::uint32_t index = 0;  ///< corner, edge, triangle (0, 1) or inside node
};

struct Cap {
  std::uint32_t even_edge = 0;        ///< the one wall of two quads (0: ab .. 3: da)
  /// Cap coordinates of node iN: the quad is the unit square at z = 1, the
  /// inner quad the square [1/4, 3/4]^2 at z = 0, the sides straight between.
  std::vector<Vec3> inside;
  std::vector<std::array<CapRole, 8>> hexes;  ///< VTK node order, positive in cap coordinates
  std::string source;                 ///< file it was read from
};

/// One cap from the text of a .cap file; `where` names it in errors. Throws
/// loom::InputError naming the line of anything malformed.
Cap parse_cap(std::string_view text, const std::string& where);

/// The caps in `dir` (*.cap, sorted by name). Throws loom::InputError naming
/// the file and line of a malformed line, and when some even edge has no cap.
std::vector<Cap> load_caps(const std::filesystem::path& dir);

/// fill/ in weave::default_rules_dir() ($LOOM_RULES, else the shipped rules/):
/// the caps `loom weave` uses unless `--rules DIR` brings DIR/fill
/// (pipeline::default_meshing_options).
std::filesystem::path default_caps_dir();

}  // namespace loom::fill
