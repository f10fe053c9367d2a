// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Text_cursor.h
/// \brief Tokens, numbers and line numbers of the text mesh formats.
#ifndef SPECTRALSEG_IO_INTERNAL_TEXT_CURSOR_H
#define SPECTRALSEG_IO_INTERNAL_TEXT_CURSOR_H

#include <SpectralSeg/IO/internal/Polygon_soup.h>
#include <SpectralSeg/exceptions.h>

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <system_error>

namespace SpectralSeg {
namespace IO {
/// \cond SKIP_IN_MANUAL
namespace internal {

// A number token parsed in full: `ok` if the whole token is a number of the
// asked kind, `overflow` if it is one but out of range.
enum class Parse_status { ok, malformed, overflow };

inline Parse_status parse_double(std::string_view token, double& value)
{
  if(!token.empty() && token.front() == '+')
    token.remove_prefix(1);
  if(token.empty())
    return Parse_status::malformed;
  const auto r = std::from_chars(token.data(), token.data() + token.size(), value);
  if(r.ptr != token.data() + token.size())
    return Parse_status::malformed;
  if(r.ec == std::errc::result_out_of_range)
    return Parse_status::overflow;
  return r.ec == std::errc() ? Parse_status::ok : Parse_status::malformed;
}

// a non-negative decimal integer: digits only, no sign, no fraction
inline Parse_status parse_unsigned(std::string_view token, std::uint64_t& value)
{
  if(!token.empty() && token.front() == '+')
    token.remove_prefix(1);
  if(token.empty() || token.front() < '0' || token.front() > '9')
    return Parse_status::malformed;
  const auto r = std::from_chars(token.data(), token.data() + token.size(), value);
  if(r.ptr != token.data() + token.size())
    return Parse_status::malformed;
  if(r.ec == std::errc::result_out_of_range)
    return Parse_status::overflow;
  return r.ec == std::errc() ? Parse_status::ok : Parse_status::malformed;
}

// a decimal integer with an optional sign
inline Parse_status parse_signed(std::string_view token, std::int64_t& value)
{
  const bool negative = !token.empty() && token.front() == '-';
  if(negative)
    token.remove_prefix(1);
  if(negative && !token.empty() && token.front() == '+')
    return Parse_status::malformed; // "-+5"
  std::uint64_t magnitude = 0;
  const Parse_status s = parse_unsigned(token, magnitude);
  if(s != Parse_status::ok)
    return s;
  if(magnitude > std::uint64_t(INT64_MAX))
    return Parse_status::overflow;
  value = negative ? -std::int64_t(magnitude) : std::int64_t(magnitude);
  return Parse_status::ok;
}

// a token for a message: at most 40 characters, unprintable bytes as '?'
inline std::string quoted(std::string_view token)
{
  std::string out = "'";
  for(std::size_t i = 0; i < token.size() && i < 40; ++i)
    out += (token[i] >= 32 && token[i] < 127) ? token[i] : '?';
  return out + (token.size() > 40 ? "...'" : "'");
}

// What a value is, for messages, composed only when one is needed: a
// text and an optional number ("the x coordinate of vertex" and 12).
struct Label
{
  static constexpr std::size_t none = std::size_t(-1);
  Label(const char* t, std::size_t i = none) : text(t), index(i) {}
  Label(const std::string& t, std::size_t i = none) : text(t), index(i) {}
  std::string str() const { return std::string(text) + (index == none ? "" : " " + std::to_string(index)); }
  std::string_view text;
  std::size_t index;
};

// Whitespace-separated tokens of a text, with the line they are on; an
// optional comment character hides the rest of its line.
class Text_cursor
{
public:
  // `comment`: the character that starts a comment ('\0': none);
  // `continuation`: whether a backslash at the end of a line joins the next (OBJ)
  Text_cursor(const File_bytes& file, std::size_t begin, char comment = '\0', bool continuation = false)
    : file_(&file), p_(file.data.data() + begin), end_(file.data.data() + file.data.size()), comment_(comment),
      continuation_(continuation)
  {
    for(const char* c = file.data.data(); c < p_; ++c)
      line_ += *c == '\n' ? 1 : 0;
  }

  // the next token, across line ends; false at the end of the text
  bool next(std::string_view& token)
  {
    skip_space(true);
    return take(token);
  }
  // the next token of the current line; false at the end of the line
  bool next_on_line(std::string_view& token)
  {
    skip_space(false);
    if(p_ == end_ || *p_ == '\n')
      return false;
    return take(token);
  }
  // moves past the end of the current line
  void skip_line()
  {
    while(p_ != end_ && *p_ != '\n')
      ++p_;
    if(p_ != end_)
    {
      ++p_;
      ++line_;
    }
  }
  // whether only whitespace and comments are left
  bool at_end()
  {
    skip_space(true);
    return p_ == end_;
  }
  // bytes left, an upper bound on what the rest of the file can hold
  std::size_t remaining() const { return std::size_t(end_ - p_); }
  // the offset of the next byte in the file
  std::size_t offset() const { return std::size_t(p_ - file_->data.data()); }
  std::size_t line() const { return line_; }
  std::string where() const { return ", line " + std::to_string(line_); }
  [[noreturn]] void fail(const std::string& what) const { file_->fail(where(), what); }

  // the next token, which must exist: `what` says what was expected
  std::string_view expect(const Label& what)
  {
    std::string_view token;
    if(!next(token))
      fail("the file ends where " + what.str() + " was expected (truncated file or wrong counts in the header)");
    return token;
  }
  // the next token as a finite number
  double number(const Label& what)
  {
    const std::string_view token = expect(what);
    double value = 0.;
    const Parse_status s = parse_double(token, value);
    if(s == Parse_status::malformed)
      fail("expected " + what.str() + ", found " + quoted(token));
    if(s == Parse_status::overflow || !std::isfinite(value))
      throw Invalid_input(file_->message(where(), what.str() + " " + quoted(token) +
                                                   " is non-finite (NaN, infinity or out of range)"));
    return value;
  }
  // the next token as a non-negative integer at most `limit`
  std::uint64_t integer(const Label& what, std::uint64_t limit)
  {
    const std::string_view token = expect(what);
    std::uint64_t value = 0;
    const Parse_status s = parse_unsigned(token, value);
    if(s == Parse_status::malformed)
      fail("expected " + what.str() + " (a non-negative integer), found " + quoted(token));
    if(s == Parse_status::overflow || value > limit)
      fail(what.str() + " " + quoted(token) + " is out of range (at most " + std::to_string(limit) + ")");
    return value;
  }

private:
  void skip_space(bool across_lines)
  {
    while(p_ != end_)
    {
      const char c = *p_;
      if(c == '\n')
      {
        if(!across_lines)
          return;
        ++line_;
        ++p_;
      }
      else if(c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v')
        ++p_;
      else if(continuation_ && c == '\\' && joins_next_line())
        continue;
      else if(comment_ != '\0' && c == comment_)
      {
        while(p_ != end_ && *p_ != '\n')
          ++p_;
      }
      else
        return;
    }
  }
  bool take(std::string_view& token)
  {
    const char* start = p_;
    while(p_ != end_ && !is_space(*p_) && !(comment_ != '\0' && *p_ == comment_) &&
          !(continuation_ && *p_ == '\\' && p_ != start))
      ++p_;
    token = std::string_view(start, std::size_t(p_ - start));
    return p_ != start;
  }
  // a backslash followed by the line end: skipped with it
  bool joins_next_line()
  {
    const char* q = p_ + 1;
    while(q != end_ && (*q == ' ' || *q == '\t' || *q == '\r'))
      ++q;
    if(q == end_ || *q != '\n')
      return false;
    p_ = q + 1;
    ++line_;
    return true;
  }
  static bool is_space(char c)
  {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
  }

  const File_bytes* file_;
  const char* p_;
  const char* end_;
  char comment_;
  bool continuation_;
  std::size_t line_ = 1;
};

} // namespace internal
/// \endcond
} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_INTERNAL_TEXT_CURSOR_H
