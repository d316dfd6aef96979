// libc++'s std::to_chars(double) (Dump::number: the dumps) prints a large
// integer value in fixed notation through Ryu's __d2fixed_buffered_n, whose
// tables (__POW10_SPLIT, _2) are 100 KB of the module's data. Defined here
// for the WebAssembly build, the archive member that holds them (d2fixed.o)
// is never linked: the same digits through musl's printf, which is exact
// (correctly rounded at any precision), as Ryu's d2fixed is. The member's
// other functions come along: __d2exp_buffered_n (the precision overloads:
// format_g's general format, engine/format.hpp) and the two digit writers of
// float's to_chars. The dumps are checked against the native build's byte for byte
// (make web-test); web/test/to_chars_check.cpp checks these against libc++'s.
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>

namespace std {
inline namespace __2 {

namespace {
to_chars_result printed(char* first, char* last, const char* format, double d, std::uint32_t precision) {
  char buf[1500];  // DBL_MAX in fixed notation is 309 digits, and a precision of 1074 at most follows
  const int n = std::snprintf(buf, sizeof buf, format, static_cast<int>(precision), d);
  if (n < 0 || n >= static_cast<int>(sizeof buf) || n > last - first) return {last, errc::value_too_large};
  std::memcpy(first, buf, static_cast<std::size_t>(n));
  return {first + n, errc{}};
}
}  // namespace

to_chars_result __d2fixed_buffered_n(char* first, char* const last, const double d, const std::uint32_t precision) {
  return printed(first, last, "%.*f", d, precision);
}

to_chars_result __d2exp_buffered_n(char* first, char* const last, const double d, std::uint32_t precision) {
  return printed(first, last, "%.*e", d, precision);
}

// Ryu's: `digits` (olength decimal digits) written at result, exactly olength chars.
void __append_n_digits(const std::uint32_t olength, std::uint32_t digits, char* const result) {
  for (std::uint32_t i = olength; i-- > 0; digits /= 10) result[i] = static_cast<char>('0' + digits % 10);
}

// Ryu's: `digits` as exactly nine decimal digits, leading zeros included.
void __append_nine_digits(std::uint32_t digits, char* const result) { __append_n_digits(9, digits, result); }

}  // namespace __2
}  // namespace std
