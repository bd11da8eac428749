#include "src/gen/generator_args.hpp"

#include "src/gen/generators.hpp"
#include "src/util/error.hpp"

namespace loom::gen {

void require_at_least(const std::string& kind, std::initializer_list<std::pair<const char*, int>> sizes, int minimum) {
  for (const auto& [name, value] : sizes)
    if (value < minimum)
      fail_input("gen " + kind, fmt::format("{} is {}, it must be at least {}", name, value, minimum),
                 "see 'loom gen --help' for each kind's arguments");
}

void require_not_too_large(const std::string& kind, std::uint64_t elements) {
  if (elements > kMaxGeneratedElements)
    fail_input("gen " + kind,
               fmt::format("these sizes give {} elements, more than the limit of {}", elements, kMaxGeneratedElements),
               "choose smaller sizes");
}

}  // namespace loom::gen
