#pragma once
// Test inputs for `loom gen`: closed, outward-oriented quad surfaces and
// structured hex meshes (docs/generators.md). Every generator is deterministic,
// welds shared nodes exactly (no two nodes at the same coordinates) and throws
// InputError (where "gen KIND") for a non-positive size or a result larger than
// kMaxGeneratedElements.
#include <cstddef>
#include <cstdint>

#include "src/mesh/hex_mesh.hpp"
#include "src/mesh/quad_surface.hpp"

namespace loom::quadmap {
struct QuadMap;
}

namespace loom::gen {

/// Largest number of quads or hexes a generator produces.
inline constexpr std::size_t kMaxGeneratedElements = 20'000'000;
/// Largest F for randquad (100,000 quads take about a minute, mostly placing them).
inline constexpr int kMaxRandquadFaces = 100'000;

/// Surface of the box [0,a]x[0,b]x[0,c] with unit quads (a*b*2 + b*c*2 + c*a*2 quads).
QuadSurface box(int a, int b, int c);
/// Surface of an L-shaped prism: the unit blocks [0,2]x[0,1]x[0,1] and
/// [0,1]x[1,2]x[0,1], each cut into n x n x n cells (14 n^2 quads).
QuadSurface lshape(int n);
/// Ring depth of the cylinder's cap O-grid: ceil(n/2) cells between the centre
/// square (half-width 1/2) and the unit circle, so ring cells are about as deep
/// as the centre cells are wide.
int cylinder_ring_depth(int n);
/// Cylinder of radius 1 and height 2 on the z axis, z in [0,2]. Each cap is an
/// O-grid: an n x n centre square and four n x d ring blocks (d =
/// cylinder_ring_depth(n)), so the rim has 4n edges; the wall has h layers.
/// Quads: 2(n^2 + 4nd) + 4nh. It is the boundary of ogrid_cylinder(n, h).
QuadSurface cylinder(int n, int h);
/// The structured hex mesh of cylinder(n, h): the cap O-grid swept through h
/// layers, n^2 + 4nd hexes per layer, positively oriented.
HexMesh ogrid_cylinder(int n, int h);
/// Unit sphere from the cube [-1,1]^3 with n x n quads per face, projected
/// radially (6 n^2 quads, 6 n^2 + 2 nodes).
QuadSurface cubesphere(int n);
/// Schneiders' pyramid (16 quads, 18 nodes; literature.md §5, coordinates as listed).
QuadSurface schneiders();
/// A regular tetrahedron split into four hexes, its boundary: 12 quads, 14 nodes
/// (literature.md §5; coordinates computed exactly rather than the rounded listing).
QuadSurface tet4();
/// The octagonal spindle (tetragonal trapezohedron): 8 quads, 10 nodes
/// (literature.md §5, coordinates as listed).
QuadSurface spindle();
/// The parity-infeasible cube: the unit cube whose top face is split by a
/// valence-2 node at (0.5,0.5,1) into two quads, 7 quads in all (literature.md
/// §5). It is a valid closed surface but no hex mesh has it as boundary.
QuadSurface odd7();
/// Torus with n quads around the axis (major radius 2) and m around the tube
/// (minor radius 1): n*m quads, genus 1. Needs n, m >= 3 and n*m even.
QuadSurface torus(int n, int m);
/// Tori in a row along x, each with n quads around its axis (major radius 2)
/// and tubes[t] around its tube (minor radius 1), 7 apart, each joined to the
/// next by a straight tube of 4 quads: a surface of genus tubes.size(), with
/// n sum(tubes) + 2 (tubes.size() - 1) quads. Torus t's meridian has tubes[t]
/// edges. Needs n >= 4 and even for two tori or more, every tube >= 3.
QuadSurface torus_chain(int n, const std::vector<int>& tubes);
/// A plate of (2N + 1) x 3 x 1 unit cubes with N square holes through it (hole
/// h is [2h+1, 2h+2] x [1, 2]), each cube cut into K^3: genus N, every meridian
/// 4K edges, and its hex mesh is its grid. Needs N, K >= 1.
QuadSurface plate_with_holes(int holes, int k);
/// A ring of unit cubes round a square hole (the square loop of side L, the
/// least L >= 3 with 4 (L - 1) >= 3N cells) with N unit-cube bosses on top,
/// spread evenly round it and never touching; each cube cut into K^3. Genus 1,
/// meridian 4K edges, and its hex mesh is its grid. Needs N, K >= 1.
QuadSurface ring_of_bosses(int bosses, int k);
/// A random quadrangulation of the sphere with exactly `faces` quads (even,
/// 6..kMaxRandquadFaces), simple, every node of degree >= 3, nodes on the unit
/// sphere. Grown from the cube by hex flips (k = 1, 2) mixed with k = 3 hex
/// flips and diagonal slides, then laid out on the sphere (docs/generators.md).
/// The same seed gives the same surface.
QuadSurface randquad(int faces, std::uint64_t seed);
/// Largest F for quadrangulation (F = 20 takes about 20 s to enumerate).
inline constexpr int kMaxEnumeratedFaces = 20;
/// The 3-connected quadrangulation of the sphere number `index` (from 0) among
/// those with `faces` quads, in the enumerator's order (src/quadmap/enumerate.hpp:
/// 1, 0, 1, 1, 3, 3, 11, ... for 6, 7, 8, ... quads), nodes on the unit
/// sphere as randquad places them. The closure corpus is every one of 6..16 quads.
QuadSurface quadrangulation(int faces, int index);
/// The same surface from the map the enumeration gave at `index`, for callers
/// that hold the enumeration (20 quads: 19 s to enumerate, not once per input).
QuadSurface quadrangulation(const quadmap::QuadMap& map, int index);
/// Surface of the box [0,6]x[0,4]x[0,1.5] with a cylindrical boss (radius 0.8
/// round (1.75, 2), up to z = 3) and a block boss ([3.5,5.5]x[1,3], up to z =
/// 2.5) on top, meshed all-quad by Gmsh. `bosses`: the part cut into 29
/// topological cubes (OpenCASCADE fragments; an O-grid round the cylinder),
/// its 70 four-sided boundary patches meshed transfinite with 2k x 2k quads
/// each (280 k^2 quads). k in 1..50.
QuadSurface bosses(int k);
/// The same part meshed free: OpenCASCADE fuse, Frontal-Delaunay, simple
/// recombination, subdivision into quads, element size 3/k (k in 1..50).
QuadSurface bosses_free(int k);
/// Structured hex mesh of [0,a]x[0,b]x[0,c] with unit cells, VTK node order,
/// positively oriented; node (i,j,k) has index i + (a+1)(j + (b+1)k).
HexMesh hexgrid(int a, int b, int c);

}  // namespace loom::gen
