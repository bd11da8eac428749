#include "src/check/validity.hpp"

#include <algorithm>
#include <limits>

#include "src/check/criteria.hpp"
#include "src/util/error.hpp"

namespace loom {

std::string criterion_name(int number) {
  switch (number) {
    case 1:
      return "distinct nodes";
    case 2:
      return "faces in one or two hexes";
    case 3:
      return "no doublets";
    case 4:
      return "manifold";
    case 5:
      return "Euler characteristic";
    case 6:
      return "boundary matches surface";
    case 7:
      return "positive scaled Jacobian";
    default:
      return "unknown";
  }
}

bool ValidityReport::combinatorial_valid() const {
  return std::all_of(criteria.begin(), criteria.end(),
                     [](const CriterionResult& c) { return c.number == 7 || c.passed; });
}

bool ValidityReport::valid() const {
  return !criteria.empty() &&
         std::all_of(criteria.begin(), criteria.end(), [](const CriterionResult& c) { return c.passed; });
}

const CriterionResult* ValidityReport::first_failure() const {
  for (const auto& c : criteria)
    if (!c.passed) return &c;
  return nullptr;
}

ValidityReport check_hex_mesh(const HexMesh& mesh, const QuadSurface* boundary) {
  // Face and edge incidences are numbered in 32 bits as 12 * hex + local edge.
  if (mesh.hexes.size() > std::numeric_limits<std::uint32_t>::max() / 12 ||
      mesh.points.size() >= std::numeric_limits<std::uint32_t>::max())
    fail_input(
        "check",
        fmt::format("{} hexes and {} nodes are more than the checker handles", mesh.hexes.size(), mesh.points.size()),
        "split the mesh");
  ValidityReport report;
  report.hexes = mesh.hexes.size();
  report.nodes = mesh.points.size();
  report.criteria.push_back(criteria::distinct_nodes(mesh));
  std::vector<int> topological{2, 3, 4, 5};
  if (boundary) topological.push_back(6);
  if (report.criteria.front().passed) {
    const HexTopology topo = build_hex_topology(mesh);
    report.criteria.push_back(criteria::faces_in_one_or_two_hexes(mesh, topo));
    report.criteria.push_back(criteria::no_doublets(mesh, topo));
    report.criteria.push_back(criteria::manifold(mesh, topo));
    criteria::BoundaryShape shape;
    report.criteria.push_back(criteria::euler_characteristic(mesh, topo, shape));
    report.boundary_components = shape.components;
    report.boundary_genus = shape.genus;
    if (boundary) report.criteria.push_back(criteria::boundary_matches(mesh, topo, *boundary));
  } else {
    for (int number : topological) {
      CriterionResult skipped = criteria::failed(number, "not evaluated: criterion 1 fails");
      skipped.evaluated = false;
      report.criteria.push_back(std::move(skipped));
    }
  }
  report.criteria.push_back(criteria::positive_scaled_jacobian(mesh, report.quality));
  return report;
}

}  // namespace loom
