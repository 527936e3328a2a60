// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fast text output for large files (100K-face pictures and OBJ files):
// numbers formatted by std::to_chars into one buffer, handed to the stream
// in large blocks. Several times faster than iostream or printf formatting.

#ifndef DLF_CLI_TEXT_BUFFER_H
#define DLF_CLI_TEXT_BUFFER_H

#include <charconv>
#include <ostream>
#include <string>

namespace dlf_cli {

class Text_buffer
{
public:
  explicit Text_buffer(std::ostream& out) : m_out(out) { m_text.reserve(block + 256); }
  Text_buffer(const Text_buffer&) = delete;
  Text_buffer& operator=(const Text_buffer&) = delete;
  ~Text_buffer() { flush(); }

  Text_buffer& operator<<(const char* s) { m_text += s; return spill(); }
  Text_buffer& operator<<(const std::string& s) { m_text += s; return spill(); }
  Text_buffer& operator<<(char c) { m_text += c; return spill(); }
  Text_buffer& operator<<(long long i) { return format(i); }
  Text_buffer& operator<<(int i) { return format(i); }

  /// The shortest text that reads back as exactly `x`.
  Text_buffer& exact(double x) { return format(x); }
  /// `x` with two decimals (SVG coordinates: 1/100 of a pixel).
  Text_buffer& fixed2(double x)
  {
    char b[64];
    const std::to_chars_result r = std::to_chars(b, b + sizeof(b), x, std::chars_format::fixed, 2);
    m_text.append(b, r.ptr);
    return spill();
  }

  void flush()
  {
    m_out.write(m_text.data(), std::streamsize(m_text.size()));
    m_text.clear();
  }

private:
  static constexpr std::size_t block = std::size_t(1) << 20;

  template <class T>
  Text_buffer& format(T x)
  {
    char b[64];
    const std::to_chars_result r = std::to_chars(b, b + sizeof(b), x);
    m_text.append(b, r.ptr);
    return spill();
  }
  Text_buffer& spill()
  {
    if(m_text.size() >= block) flush();
    return *this;
  }

  std::ostream& m_out;
  std::string m_text;
};

} // namespace dlf_cli

#endif
