#pragma once
// Output files are written only on success and atomically: content goes to a
// temporary file in the target's directory, which is renamed over the target.
#include <filesystem>
#include <functional>
#include <string>

namespace loom {

/// Calls write(tmp) with a temporary path in the same directory as `target` and
/// with the same extension (so writers that choose a format by extension still
/// work), then renames it to `target`. If write throws, the temporary file is
/// removed and the exception propagates; `target` is never half-written.
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path& tmp)>& write);

/// Convenience: writes `content` to `target` atomically.
void write_text_atomically(const std::filesystem::path& target, const std::string& content);

}  // namespace loom
