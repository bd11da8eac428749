// gen::quadrangulation: one of the enumerated 3-connected quadrangulations.
#include <random>

#include <fmt/format.h>

#include "src/gen/generator_args.hpp"
#include "src/gen/generators.hpp"
#include "src/gen/sphere_embedding.hpp"
#include "src/quadmap/enumerate.hpp"
#include "src/util/error.hpp"

namespace loom::gen {

QuadSurface quadrangulation(int faces, int index) {
  require_at_least("quadrangulation", {{"F", faces}}, 6);
  require_at_least("quadrangulation", {{"I", index}}, 0);
  if (faces > kMaxEnumeratedFaces)
    fail_input("gen quadrangulation", fmt::format("F is {}, more than the limit of {}", faces, kMaxEnumeratedFaces),
               "choose a smaller F");
  const auto all = quadmap::three_connected_quadrangulations(faces);
  if (static_cast<std::size_t>(index) >= all.size())
    fail_input("gen quadrangulation",
               fmt::format("I is {}, but there {} {} 3-connected quadrangulation{} with {} quads", index,
                           all.size() == 1 ? "is" : "are", all.size(), all.size() == 1 ? "" : "s", faces),
               all.empty() ? "choose another F" : fmt::format("choose I from 0 to {}", all.size() - 1));
  return quadrangulation(all[static_cast<std::size_t>(index)], index);
}

QuadSurface quadrangulation(const quadmap::QuadMap& map, int index) {
  std::mt19937_64 rng(static_cast<std::uint64_t>(map.quads.size()) * 1000003u + static_cast<std::uint64_t>(index));
  return {embed_on_sphere(map.quads, map.vertex_bound, rng), map.quads};
}

}  // namespace loom::gen
