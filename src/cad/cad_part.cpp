#include "src/cad/cad_part.hpp"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>

#include <fmt/ranges.h>

#include "src/cad/gmsh_quads.hpp"
#include "src/io/gmsh_session.hpp"
#include "src/util/error.hpp"

namespace loom::cad {

namespace {

constexpr const char* kHint = "check that it opens in Gmsh as one closed solid";

std::string lower_extension(const std::filesystem::path& part) {
  std::string ext = part.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// The child's reply: size, diagonal, face count, meshings and refinement balls,
// then encode_quads's bytes.
using Header = std::array<double, 5>;

std::string mesh_in_child(const std::string& path, const std::string& where, std::optional<double> size) {
  gmsh::open(path);
  gmsh::vectorpair volumes, boundary;
  gmsh::model::getEntities(volumes, 3);
  if (volumes.size() != 1)
    fail_input(where, fmt::format("the file holds {} solids, not one", volumes.size()),
               volumes.empty() ? "give a closed solid (a surface model is not enough)"
                               : "fuse them into one (BooleanUnion in a .geo, or in the CAD tool)");
  double x0, y0, z0, x1, y1, z1;
  gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
  const double diagonal = std::hypot(x1 - x0, y1 - y0, z1 - z0);
  if (!(diagonal > 0) || !std::isfinite(diagonal)) fail_input(where, "the part's bounding box is empty", kHint);
  const double h = size.value_or(diagonal / kDefaultDivisions);
  if (h < diagonal / kFinestDivisions)
    fail_input(where,
               fmt::format("--size {} is finer than the part's diagonal ({:.4g}) / {}, which would give millions of quads",
                           h, diagonal, kFinestDivisions),
               "choose a larger --size");
  gmsh::model::getBoundary(volumes, boundary, true, false, false);
  std::vector<int> faces;
  for (const auto& [dim, tag] : boundary) faces.push_back(tag);
  // Subdivision halves every edge: Gmsh meshes at twice the size wanted.
  const RefinedQuads quads = mesh_refined_quads(2 * h, kLeastCornerSine, faces, where, kHint);
  const Header header{h, diagonal, static_cast<double>(faces.size()), static_cast<double>(quads.meshings),
                      static_cast<double>(quads.balls)};
  std::string out(reinterpret_cast<const char*>(header.data()), sizeof header);
  return out + quads.bytes;
}

}  // namespace

bool is_cad_file(const std::filesystem::path& part) {
  const std::string ext = lower_extension(part);
  return std::any_of(kCadExtensions.begin(), kCadExtensions.end(), [&](const char* k) { return ext == k; });
}

PartSurface quad_surface_of_part(const std::filesystem::path& part, std::optional<double> size) {
  const std::string where = part.string();
  if (!is_cad_file(part))
    fail_input(where, fmt::format("'{}' is not a CAD file loom mesh reads", lower_extension(part)),
               fmt::format("give {} (a quad surface goes to 'loom weave')", fmt::join(kCadExtensions, " ")));
  if (size && !(*size > 0 && std::isfinite(*size)))
    fail_input(where, fmt::format("--size {} is not a positive length", *size), "give the quads' edge length");
  const std::string bytes =
      run_gmsh_isolated(where, kHint, [&] { return mesh_in_child(std::filesystem::absolute(part).string(), where, size); });
  if (bytes.size() < sizeof(Header)) fail_input(where, "short message from Gmsh's process", "this is a bug in Loom");
  Header header;
  std::memcpy(header.data(), bytes.data(), sizeof header);
  PartSurface result;
  result.surface = decode_quads(std::string_view(bytes).substr(sizeof header), where);
  result.size = header[0];
  result.diagonal = header[1];
  result.faces = static_cast<int>(header[2]);
  result.meshings = static_cast<int>(header[3]);
  result.refinement_balls = static_cast<int>(header[4]);
  orient_consistently(result.surface);
  return result;
}

}  // namespace loom::cad
