#pragma once
// Where a hex of a closed mesh came from: reported per hex (the `source` cell
// field and the report's quality_by_source, docs/closure.md).
#include <cstdint>

namespace loom::closure {

enum class HexSource : std::uint8_t { woven, searched, database, filled, pillow };
const char* source_name(HexSource s);

}  // namespace loom::closure
