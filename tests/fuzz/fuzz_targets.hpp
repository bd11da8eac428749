#pragma once
// Fuzz targets: each feeds arbitrary bytes to one of Loom's readers
// (docs/fuzzing.md). A reader may accept the bytes or refuse them with its
// documented error; anything else (another exception, a crash, a hang, an
// unbounded allocation) is a finding. The same targets run under libFuzzer
// (fuzz_main.cpp, -DLOOM_FUZZ=ON with clang) and in test_fuzz_replay, which
// replays the seed corpora and every crash found.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace loom::fuzz {

/// What a reader made of the bytes: nullopt when it accepted them, else the
/// message of the documented error it threw. Other exceptions propagate.
using Outcome = std::optional<std::string>;

struct Target {
  std::string_view name;  ///< also the corpus directory: tests/fuzz/corpus/NAME
  Outcome (*run)(std::string_view bytes);
  std::size_t max_len;  ///< libFuzzer's -max_len for it (scripts/fuzz.sh)
  /// Whether a message that is not one printable line is a finding.
  bool checks_message = true;
};

/// Every target, in the order scripts/fuzz.sh runs them.
std::span<const Target> targets();
/// The target called `name`, or nullptr.
const Target* find_target(std::string_view name);

/// Whether `message` is one printable line as it stands (docs/cli.md): not
/// empty, and nothing for the CLI's last guard, one_line(), to repair: no
/// line end or other control byte, no invalid UTF-8, at most 1,000 bytes.
bool is_one_printable_line(std::string_view message);

/// Runs `target` on the bytes and aborts, as libFuzzer expects of a finding,
/// when the reader threw its documented error with a message that is not one
/// printable line (if the target checks messages). Returns 0.
int run_for_fuzzer(const Target& target, const std::uint8_t* data, std::size_t size);

int fuzz_obj(const std::uint8_t* data, std::size_t size);
int fuzz_off(const std::uint8_t* data, std::size_t size);
int fuzz_vtk(const std::uint8_t* data, std::size_t size);
int fuzz_vtu(const std::uint8_t* data, std::size_t size);
int fuzz_msh(const std::uint8_t* data, std::size_t size);
int fuzz_rules(const std::uint8_t* data, std::size_t size);
int fuzz_schema(const std::uint8_t* data, std::size_t size);
int fuzz_cap(const std::uint8_t* data, std::size_t size);
int fuzz_database(const std::uint8_t* data, std::size_t size);
int fuzz_strategy(const std::uint8_t* data, std::size_t size);

}  // namespace loom::fuzz
