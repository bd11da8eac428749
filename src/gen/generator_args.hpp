#pragma once
// Argument checks shared by the generators: every size positive, every result
// within kMaxGeneratedElements. Failures are InputErrors naming "gen KIND".
#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>

namespace loom::gen {

/// Throws unless every (name, value) is at least `minimum`.
void require_at_least(const std::string& kind, std::initializer_list<std::pair<const char*, int>> sizes,
                      int minimum = 1);

/// Throws if `elements` (quads or hexes, computed in 64 bits by the caller)
/// exceeds kMaxGeneratedElements.
void require_not_too_large(const std::string& kind, std::uint64_t elements);

}  // namespace loom::gen
