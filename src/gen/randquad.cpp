// gen::randquad: a random quadrangulation of the sphere (docs/generators.md).
#include <random>
#include <stdexcept>

#include <fmt/format.h>

#include "src/gen/generator_args.hpp"
#include "src/gen/generators.hpp"
#include "src/gen/random_draws.hpp"
#include "src/gen/sphere_embedding.hpp"
#include "src/gen/sphere_quadrangulation.hpp"
#include "src/mesh/surface_validation.hpp"
#include "src/util/error.hpp"

namespace loom::gen {

namespace {

// Attempted mixing moves after each growth step, and per quad at the end.
constexpr std::uint64_t kMixingAttemptsPerGrowth = 8;
constexpr std::uint64_t kMixingAttemptsPerQuad = 20;
// Rounds of mixing (each as long as the final one) allowed to part quads
// that share a diagonal: a bound, so a walk that cannot part them fails
// loudly instead of looping.
constexpr int kMixingRoundsForProperQuads = 1000;
// Random picks tried for a k = 2 flip before growing by a k = 1 flip instead.
constexpr int kHexFlip2Picks = 8;

class RandomWalk {
 public:
  RandomWalk(int start_faces, std::uint64_t seed) : rng_(seed), mesh_(start_faces) {}

  std::size_t size() const { return mesh_.quads().size(); }
  std::mt19937_64& rng() { return rng_; }
  const SphereQuadrangulation& mesh() const { return mesh_; }

  void grow_by_4() { mesh_.hex_flip_1(random_quad()); }

  bool try_grow_by_2() {
    for (int pick = 0; pick < kHexFlip2Picks; ++pick)
      if (mesh_.hex_flip_2(random_quad(), random_corner())) return true;
    return false;
  }

  // +6 in two flips; the k = 2 flip on the edge the k = 1 flip kept is always allowed.
  void grow_by_6() {
    const std::size_t quad = random_quad();
    mesh_.hex_flip_1(quad);
    if (!mesh_.hex_flip_2(quad, 0)) throw std::logic_error("randquad: hex flip k=2 after k=1 refused");
  }

  // Moves that keep the number of quads: diagonal slides and k = 3 hex flips.
  void mix(std::uint64_t attempts) {
    for (std::uint64_t i = 0; i < attempts; ++i) {
      const std::size_t quad = random_quad();
      const int corner = random_corner();
      const std::uint64_t move = uniform_index(rng_, 3);
      if (move < 2)
        mesh_.diagonal_slide(quad, corner, static_cast<int>(move));
      else
        mesh_.hex_flip_3(quad, corner);
    }
  }

 private:
  std::size_t random_quad() { return uniform_index(rng_, mesh_.quads().size()); }
  int random_corner() { return static_cast<int>(uniform_index(rng_, 4)); }

  std::mt19937_64 rng_;
  SphereQuadrangulation mesh_;
};

}  // namespace

QuadSurface randquad(int faces, std::uint64_t seed) {
  require_at_least("randquad", {{"F", faces}}, 6);
  if (faces > kMaxRandquadFaces)
    fail_input("gen randquad", fmt::format("F is {}, more than the limit of {}", faces, kMaxRandquadFaces),
               "choose a smaller F");
  if (faces % 2 != 0)
    fail_input("gen randquad",
               fmt::format("F is {}, an odd number, and no hex mesh has an odd number of boundary quads", faces),
               "choose an even F");
  // From the cube only a k = 1 flip is allowed (every node has degree 3), so
  // 8 quads are out of reach: start from the spindle, the only 8-quad
  // quadrangulation with every degree >= 3.
  RandomWalk walk(faces == 8 ? 8 : 6, seed);
  const auto target = static_cast<std::size_t>(faces);
  while (walk.size() < target) {
    // Keep the remainder reachable: +2 alone is only sure to be allowed right after a +4.
    const std::size_t remaining = target - walk.size();
    if (remaining == 6)
      walk.grow_by_6();
    else if (remaining == 4 || uniform_index(walk.rng(), 4) == 0 || !walk.try_grow_by_2())
      walk.grow_by_4();
    walk.mix(kMixingAttemptsPerGrowth);
  }
  walk.mix(kMixingAttemptsPerQuad * target);
  // Two quads sharing a diagonal of one can bound no valid hex mesh
  // (surface_validation.hpp): mix on until there are none.
  for (int round = 0; quads_meeting_improperly({{}, walk.mesh().quads()}); ++round) {
    if (round == kMixingRoundsForProperQuads)
      throw std::logic_error(fmt::format("randquad {} {}: two quads still share a diagonal after {} rounds of mixing",
                                         faces, seed, round));
    walk.mix(kMixingAttemptsPerQuad * target);
  }
  return {embed_on_sphere(walk.mesh().quads(), walk.mesh().node_count(), walk.rng()), walk.mesh().quads()};
}

}  // namespace loom::gen
