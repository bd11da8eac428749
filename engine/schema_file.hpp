#pragma once
// A schema given as data, so that a new rewriting domain needs no C++. One
// declaration a line; '#' starts a comment:
//
//   kind vertex
//   kind triangle
//   port triangle.vertex 3 cyclic required -> vertex
//   attribute vertex.degree 0
//
// `port OWNER.NAME ARITY [cyclic] [required] -> TARGET` (ordered and optional
// unless said); `attribute OWNER.NAME [DEFAULT]` (default 0). Kinds are
// declared before they are used.
#include <memory>
#include <string>

#include "engine/schema.hpp"

namespace loom::engine {

/// Throws RuleError at FILE:LINE:COL naming what is wrong.
std::shared_ptr<Schema> parse_schema(const std::string& text, const std::string& file);

/// parse_schema() of a file's content; RuleError if it cannot be read.
std::shared_ptr<Schema> load_schema(const std::string& path);

}  // namespace loom::engine
