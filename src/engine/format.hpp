// Numbers as text without a stream: what `std::ostream << std::setprecision(p)
// << v` writes, printf's "%.*g" (std::to_chars' general format with a
// precision is defined as that), for messages, summaries and the dumps. No
// iostreams in the code the browser build runs: their locale machinery was a
// quarter of its module (docs/web.md).
#pragma once

#include <charconv>
#include <string>

namespace physics {

inline std::string format_g(double v, int precision = 6) {
  char buf[48];  // "%.17g" writes 24 characters at most
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, precision);
  return ec == std::errc{} ? std::string(buf, end) : std::string("?");  // never too long at precision <= 17
}

}  // namespace physics
