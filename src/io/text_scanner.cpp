#include "src/io/text_scanner.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <system_error>

#include "src/util/error.hpp"

namespace loom {

namespace {
bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
bool is_space(char c) { return is_blank(c) || c == '\n'; }
}  // namespace

std::string read_input_file(const std::filesystem::path& file) {
  namespace fs = std::filesystem;
  const std::string where = file.string();
  std::error_code ec;
  auto status = fs::status(file, ec);
  if (ec || !fs::exists(status)) fail_input(where, "file not found", "check the path");
  if (fs::is_directory(status)) fail_input(where, "is a directory, not a mesh file", "give a file");
  std::ifstream in(file, std::ios::binary);
  if (!in) fail_input(where, "cannot open file for reading", "check its permissions");
  std::ostringstream content;
  content << in.rdbuf();
  if (in.bad()) fail_input(where, "cannot read file", "check that it is a readable regular file");
  std::string text = std::move(content).str();
  if (text.empty()) fail_input(where, "file is empty", "give a mesh file with content");
  return text;
}

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f)
      out += c;
    else
      out += fmt::format("\\x{:02x}", byte);
  }
  return out;
}

std::string quote_token(std::string_view text) {
  constexpr std::size_t limit = 40;
  return "'" + printable(text.substr(0, limit)) + (text.size() > limit ? "...'" : "'");
}

bool parse_real(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (ec == std::errc::result_out_of_range) {
    // Overflowing literals (1e999) are infinite for our purposes; underflow is 0.
    auto e = token.find_first_of("eE");
    bool underflow = e != std::string_view::npos && e + 1 < token.size() && token[e + 1] == '-';
    value = underflow ? 0.0 : (token.front() == '-' ? -HUGE_VAL : HUGE_VAL);
    return end == token.data() + token.size();
  }
  return ec == std::errc() && end == token.data() + token.size();
}

bool parse_integer(std::string_view token, std::int64_t& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

TextScanner::TextScanner(std::string_view text, std::string where, char comment)
    : text_(text), where_(std::move(where)), comment_(comment) {}

void TextScanner::skip_blanks(bool cross_lines) {
  while (pos_ < text_.size()) {
    char c = text_[pos_];
    if (c == '\n') {
      if (!cross_lines) return;
      ++line_;
      ++pos_;
    } else if (is_blank(c)) {
      ++pos_;
    } else if (comment_ != '\0' && c == comment_) {
      while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    } else {
      return;
    }
  }
}

std::string_view TextScanner::token() {
  skip_blanks(true);
  std::size_t start = pos_;
  while (pos_ < text_.size() && !is_space(text_[pos_]) && !(comment_ != '\0' && text_[pos_] == comment_)) ++pos_;
  token_line_ = line_;
  return text_.substr(start, pos_ - start);
}

std::string_view TextScanner::peek_token() {
  auto saved_pos = pos_;
  auto saved_line = line_, saved_token_line = token_line_;
  auto t = token();
  pos_ = saved_pos;
  line_ = saved_line;
  token_line_ = saved_token_line;
  return t;
}

std::string_view TextScanner::token_on_line() {
  skip_blanks(false);
  if (pos_ < text_.size() && text_[pos_] == '\n') return {};
  return token();
}

std::string_view TextScanner::expect_token(std::string_view what) {
  auto t = token();
  if (t.empty()) fail_truncated(what);
  return t;
}

void TextScanner::skip_line() {
  while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
  if (pos_ < text_.size()) {
    ++pos_;
    ++line_;
  }
}

std::string_view TextScanner::rest_of_line() {
  std::size_t start = pos_;
  while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
  std::string_view rest = text_.substr(start, pos_ - start);
  if (pos_ < text_.size()) {
    ++pos_;
    ++line_;
  }
  return rest;
}

bool TextScanner::at_end() {
  skip_blanks(true);
  return pos_ >= text_.size();
}

std::size_t TextScanner::offset_after_line() {
  std::size_t p = pos_;
  while (p < text_.size() && text_[p] != '\n') ++p;
  return p < text_.size() ? p + 1 : p;
}

void TextScanner::seek(std::size_t offset) {
  for (std::size_t p = pos_; p < offset && p < text_.size(); ++p)
    if (text_[p] == '\n') ++line_;
  pos_ = offset;
}

std::string_view TextScanner::value_token(std::string_view what) {
  if (!line_mode_) return expect_token(what);
  auto t = token_on_line();
  if (t.empty()) {
    if (pos_ >= text_.size()) fail_truncated(what);
    token_line_ = line_;
    fail(fmt::format("missing {}", what), "complete the line");
  }
  return t;
}

double TextScanner::real(std::string_view what) {
  auto t = value_token(what);
  double value = 0;
  if (!parse_real(t, value))
    fail(fmt::format("expected {} (a number), found {}", what, quote_token(t)), "fix the syntax");
  return value;
}

std::int64_t TextScanner::integer(std::string_view what) {
  auto t = value_token(what);
  std::int64_t value = 0;
  if (!parse_integer(t, value))
    fail(fmt::format("expected {} (an integer), found {}", what, quote_token(t)), "fix the syntax");
  return value;
}

std::size_t TextScanner::count(std::string_view what, std::size_t min_bytes_each) {
  std::int64_t value = integer(what);
  // The last item may end the file without a separator, hence the + 1.
  const std::size_t bytes_left = text_.size() - std::min(pos_, text_.size());
  if (value < 0 || static_cast<std::uint64_t>(value) > (bytes_left + 1) / min_bytes_each)
    fail(fmt::format("{} is {}, which this file cannot hold", what, value), "fix the count (the file may be corrupt)");
  return static_cast<std::size_t>(value);
}

Vec3 TextScanner::point(std::string_view node_label) {
  Vec3 p{};
  for (int k = 0; k < 3; ++k) p[k] = real(fmt::format("coordinate {} of {}", "xyz"[k], node_label));
  for (double x : p)
    if (!std::isfinite(x))
      fail(fmt::format("{} has a{} coordinate", node_label, std::isnan(x) ? " NaN" : "n infinite"),
           "every coordinate must be a finite number; fix or remove that node");
  return p;
}

void TextScanner::fail(const std::string& what, const std::string& hint) const {
  fail_input(where_, fmt::format("line {}: {}", token_line_, what), hint);
}

void TextScanner::fail_truncated(std::string_view expected) const {
  fail_input(where_, fmt::format("file ends at line {} where {} was expected (truncated?)", line_, expected),
             "the file is incomplete; write or download it again");
}

}  // namespace loom
