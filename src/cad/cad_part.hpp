#pragma once
// The first stage of `loom mesh`: a CAD part to a closed all-quad surface with
// an even number of quads, by Gmsh (its OpenCASCADE kernel for STEP, IGES and
// BREP; its own parser for .geo). Gmsh runs in a child process, so a crash or a
// stray message on a malformed file becomes one error line.
#include <array>
#include <filesystem>
#include <optional>

#include "src/mesh/quad_surface.hpp"

namespace loom::cad {

struct PartSurface {
  QuadSurface surface;  ///< oriented consistently, not yet validated
  double size = 0;      ///< the quads' target edge length that was used
  double diagonal = 0;  ///< of the part's bounding box
  int faces = 0;        ///< CAD faces on the part's boundary
  /// How many meshes Gmsh made to choose from, and the balls of smaller size
  /// the one kept was made with (gmsh_quads.hpp, mesh_refined_quads).
  int meshings = 1, refinement_balls = 0;
};

/// The least corner sine `loom mesh` refines a part's surface towards: at
/// most the least scaled Jacobian any hex mesh of that surface can have.
inline constexpr double kLeastCornerSine = 0.2;

/// The file kinds `loom mesh` reads, by extension (any case).
inline constexpr std::array<const char*, 7> kCadExtensions{".step", ".stp", ".iges", ".igs", ".brep", ".brp", ".geo"};
bool is_cad_file(const std::filesystem::path& part);

/// The boundary of the one solid in `part`, meshed free and all-quad (see
/// mesh_free_quads: triangles, recombination, then the subdivision that makes
/// every element quads and the count even), then meshed again finer round
/// quads with a corner sine below kLeastCornerSine (mesh_refined_quads). `size` is the quads' edge length
/// wanted; by default the bounding box's diagonal / kDefaultDivisions. Throws
/// InputError when the file cannot be read, holds no solid or several, or the
/// size is out of range.
PartSurface quad_surface_of_part(const std::filesystem::path& part, std::optional<double> size);

/// The default size's divisor of the diagonal: a few hundred quads on a
/// compact part, which the weave and cavity closure mesh in minutes.
inline constexpr double kDefaultDivisions = 12;
/// Finer than diagonal / kFinestDivisions is refused: millions of quads.
inline constexpr double kFinestDivisions = 2000;

}  // namespace loom::cad
