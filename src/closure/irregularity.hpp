#pragma once
// The irregularity the closure search can cost (shelling_search.hpp): the sum
// of edge_irregularity (check/edge_valence.hpp) over the interior edges,
// counted by how each gluing changes it. Edges on a surface quad of the front
// (owner -1) are boundary edges, not counted. Every change is >= 0, so a
// search's lower bound on hexes stays a bound.
#include <cstdint>
#include <functional>
#include <vector>

#include "src/closure/cavity.hpp"
#include "src/mesh/hex_mesh.hpp"
#include "src/quadmap/hex_glue.hpp"

namespace loom::closure {

/// Hexes round the edge u-v before the change (every hex at a front vertex).
using HexesRound = std::function<int(std::uint32_t u, std::uint32_t v)>;

/// What gluing `glued` onto the front quads `covered` adds.
int gluing_irregularity(const quadmap::GluedHex& glued, const quadmap::QuadMap& front,
                        const std::vector<std::int32_t>& owner, const QuadsAtVertex& at,
                        const std::vector<std::uint32_t>& covered, const HexesRound& round);

/// What `hexes` add when they close the whole front: every edge they have closes.
int closing_irregularity(const std::vector<Hex>& hexes, const quadmap::QuadMap& front,
                         const std::vector<std::int32_t>& owner, const HexesRound& round);

/// Whether u-v is an edge of the hex.
bool hex_has_edge(const Hex& hex, std::uint32_t u, std::uint32_t v);

}  // namespace loom::closure
