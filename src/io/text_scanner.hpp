#pragma once
// Reads a whole file and hands out whitespace-separated tokens with their line
// numbers, so parsers can say "line 12: ..." and notice a file that stops early.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "src/mesh/vec3.hpp"

namespace loom {

/// The bytes of `file`. InputError if it is missing, not a regular file,
/// unreadable or empty.
std::string read_input_file(const std::filesystem::path& file);

class TextScanner {
 public:
  /// `comment`: a character that starts a comment running to the end of the line
  /// ('\0' for none).
  TextScanner(std::string_view text, std::string where, char comment = '\0');

  /// Next token, crossing line ends; empty at the end of the file.
  std::string_view token();
  /// The token token() would return, without consuming it.
  std::string_view peek_token();
  /// Next token on the current line; empty at the end of the line.
  std::string_view token_on_line();
  /// Like token(), but the end of the file is an error naming what was expected.
  std::string_view expect_token(std::string_view what);
  /// Line mode (for line-based formats such as OBJ and OFF): real(), integer(),
  /// count() and point() read only from the current line; call next_record() to
  /// move on to the next non-blank line.
  void set_line_mode(bool on) { line_mode_ = on; }
  /// Skips blank lines and comments up to the next token.
  void next_record() { skip_blanks(true); }
  /// Drops the rest of the current line; the next token comes from a later line.
  void skip_line();
  /// True when only whitespace and comments remain.
  bool at_end();
  /// True at the very end of the text (unlike at_end(), skips nothing).
  bool at_eof() const { return pos_ >= text_.size(); }
  /// The rest of the current line, without its end; moves to the next line.
  std::string_view rest_of_line();
  /// Line of the last token returned (1-based).
  int line() const { return token_line_; }
  /// Byte offset just after the current line's end ("\n"), for binary payloads
  /// that follow a keyword line.
  std::size_t offset_after_line();
  std::string_view text() const { return text_; }
  std::size_t offset() const { return pos_; }
  /// Moves the read position (after a binary payload).
  void seek(std::size_t offset);

  /// Parse the next token (must exist) as a number; `what` names it in errors.
  double real(std::string_view what);
  std::int64_t integer(std::string_view what);
  /// A count of items that each take at least `min_bytes_each` of the bytes
  /// after it (an ASCII number and its separator: 2), so that a corrupt count
  /// is refused before anything is allocated for it.
  std::size_t count(std::string_view what, std::size_t min_bytes_each = 1);
  /// Three coordinates; NaN and inf are rejected naming `node_label`.
  Vec3 point(std::string_view node_label);

  /// InputError "WHERE: line N: WHAT; HINT" for the last token's line.
  [[noreturn]] void fail(const std::string& what, const std::string& hint) const;
  /// Like fail(), at the end of the file: says the file looks truncated.
  [[noreturn]] void fail_truncated(std::string_view expected) const;

  const std::string& where() const { return where_; }

 private:
  void skip_blanks(bool cross_lines);

  std::string_view text_;
  std::string where_;
  std::string_view value_token(std::string_view what);

  char comment_;
  bool line_mode_ = false;
  std::size_t pos_ = 0;
  int line_ = 1;        // line of pos_
  int token_line_ = 1;  // line of the last token
};

/// `text` made safe for a one-line message: single-quoted, cut to 40 characters,
/// control and non-ASCII bytes shown as \xNN (the input may be binary garbage).
std::string quote_token(std::string_view text);
/// Like quote_token(), without quotes or length limit.
std::string printable(std::string_view text);

/// Parses a whole token as a double (accepts nan/inf; callers check). False if
/// the token is not a number.
bool parse_real(std::string_view token, double& value);
bool parse_integer(std::string_view token, std::int64_t& value);

}  // namespace loom
