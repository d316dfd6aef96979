// Numbers as text without a stream: what `std::ostream << std::setprecision(p)
// << v` writes (printf's "%.*g", which both standard libraries' streams call),
// for messages, summaries and the dumps. No iostreams in the code the browser
// build runs: their locale machinery was a quarter of its module (docs/web.md).
#pragma once

#include <cstdio>
#include <string>

namespace physics {

inline std::string format_g(double v, int precision = 6) {
  char buf[48];  // "%.17g" writes 24 characters at most
  const int n = std::snprintf(buf, sizeof buf, "%.*g", precision, v);
  return std::string(buf, static_cast<std::size_t>(n));
}

}  // namespace physics
