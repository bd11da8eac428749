#pragma once
// The linking number of two disjoint closed polygons in space.
#include <optional>
#include <vector>

#include "src/mesh/vec3.hpp"

namespace loom {

/// The Gauss linking number of closed polygons `a` and `b` (each a list of
/// corners, the first not repeated), from their projection along `direction`:
/// the signed crossings where `a` passes over `b`. nullopt when the projection
/// is not generic enough to trust (a corner on the other's segment, parallel
/// overlapping segments, or the two ways of counting disagree): try another
/// direction. The polygons must not meet.
std::optional<long> linking_number_along(const std::vector<Vec3>& a, const std::vector<Vec3>& b, const Vec3& direction);

/// linking_number_along for fixed, irrational-looking directions in turn,
/// until one is generic; nullopt only if none is.
std::optional<long> linking_number(const std::vector<Vec3>& a, const std::vector<Vec3>& b);

}  // namespace loom
