#include "src/closure/hex_source.hpp"

namespace loom::closure {

const char* source_name(HexSource s) {
  switch (s) {
    case HexSource::woven: return "woven";
    case HexSource::searched: return "searched";
    case HexSource::database: return "database";
    case HexSource::filled: return "filled";
    case HexSource::pillow: return "pillow";
  }
  return "?";
}

}  // namespace loom::closure
