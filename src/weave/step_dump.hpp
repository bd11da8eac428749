#pragma once
// Pictures of a weave, step by step (`loom weave --dot-steps`): for every rule
// application, the elements it matched and made, and the diagram of every
// sheet the step touched. The DOT files are written as the weave goes; the
// SVGs are drawn by render(), once the run knows which attempt it keeps: a
// layout costs a hundred times a DOT file, and the pictures of an attempt
// that is started again are thrown away.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/engine.hpp"
#include "src/stc/pictures.hpp"
#include "src/stc/stc.hpp"

namespace loom::weave {

class StepDumper {
public:
  /// Writes into `dir` (created if needed); SVG too when `svg`.
  StepDumper(std::filesystem::path dir, bool svg);
  /// step-NNNN-RULE.dot (the elements matched and made, highlighted) and
  /// step-NNNN-sheet-K.dot (K: the sheet's rank, as in `loom stc`).
  void dump(const engine::Application& step, const stc::Stc& stc);
  /// Removes every file written so far, and forgets the SVGs not yet drawn
  /// (a weave that starts again).
  void clear();
  /// Draws the SVG of every DOT file written since the last clear(), if the
  /// dumper makes SVGs. Returns how many it drew.
  std::size_t render();
  /// The pictures Graphviz could not draw (their DOT files are written).
  const stc::PictureFailures& picture_failures() const { return failures_; }

private:
  void emit(const std::string& stem, const std::string& dot);
  std::filesystem::path dir_;
  bool svg_;
  std::vector<std::filesystem::path> written_;
  std::vector<std::filesystem::path> to_draw_;  ///< stems whose .dot is written and .svg not yet
  stc::PictureFailures failures_;
};

}  // namespace loom::weave
