#include "src/geometry/inversion_causes.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "src/check/criteria.hpp"
#include "src/check/edge_valence.hpp"
#include "src/check/hex_topology.hpp"
#include "src/check/validity.hpp"

namespace loom::geometry {

const char* cause_name(InversionCause cause) {
  switch (cause) {
    case InversionCause::none: return "none";
    case InversionCause::locked_corner: return "locked_corner";
    case InversionCause::crowded_edge: return "crowded_edge";
    case InversionCause::unexplained: return "unexplained";
  }
  return "?";
}

InversionDiagnosis diagnose_inversions(const HexMesh& mesh) {
  if (!criteria::distinct_nodes(mesh).passed) {  // no topology to go by
    InversionDiagnosis d;
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
      const bool inverted = scaled_jacobian(mesh, h) <= 0;
      d.cause.push_back(inverted ? InversionCause::unexplained : InversionCause::none);
      if (inverted) ++d.count[static_cast<std::size_t>(InversionCause::unexplained)];
    }
    return d;
  }
  const HexTopology topo = build_hex_topology(mesh);
  const EdgeValences valences = edge_valences(mesh, topo);
  const std::vector<std::uint32_t>& hexes_round = valences.hexes_round;
  const std::vector<bool>& boundary_edge = valences.on_boundary;
  const std::vector<bool>& on_boundary = valences.node_on_boundary;
  InversionDiagnosis d;
  d.cause.assign(mesh.hexes.size(), InversionCause::none);
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
    const Hex& hex = mesh.hexes[h];
    bool locked = false, inverted = false;
    for (int c = 0; c < 8; ++c) {
      if (corner_scaled_jacobian(mesh, h, c) > 0) continue;
      inverted = true;
      auto fixed = [&](int k) { return on_boundary[hex[static_cast<std::size_t>(k)]]; };
      const auto& n = hex_corner_neighbours(c);
      if (fixed(c) && std::all_of(n.begin(), n.end(), fixed)) locked = true;
    }
    if (!inverted) continue;
    std::uint32_t crowded = 0;
    for (int e = 0; e < 12; ++e) {
      const std::uint32_t edge = topo.hex_edges[12 * h + static_cast<std::size_t>(e)];
      if (!boundary_edge[edge]) crowded = std::max(crowded, hexes_round[edge]);
    }
    InversionCause& cause = d.cause[h];
    if (locked) cause = InversionCause::locked_corner;
    else if (crowded >= kCrowdedEdge) {
      cause = InversionCause::crowded_edge;
      d.most_crowded = std::max(d.most_crowded, crowded);
    } else
      cause = InversionCause::unexplained;
    ++d.count[static_cast<std::size_t>(cause)];
  }
  return d;
}

std::string describe(const InversionDiagnosis& d) {
  std::vector<std::string> parts;
  if (auto n = d.of(InversionCause::locked_corner))
    parts.push_back(fmt::format("{} with a corner locked by the boundary (no placement can fix it)", n));
  if (auto n = d.of(InversionCause::crowded_edge))
    parts.push_back(d.most_crowded == kCrowdedEdge
                        ? fmt::format("{} on interior edges of {} hexes", n, kCrowdedEdge)
                        : fmt::format("{} on interior edges of {} to {} hexes", n, kCrowdedEdge, d.most_crowded));
  if (auto n = d.of(InversionCause::unexplained))
    parts.push_back(fmt::format("{} where the untangler stopped short with no such cause", n));
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i) out += (i ? ", " : "") + parts[i];
  return out;
}

}  // namespace loom::geometry
