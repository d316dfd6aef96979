// The library functions the WebAssembly build pins (docs/web.md, "The same
// bits"), on many arguments, one result a line: hypot (web/hypot.cpp against
// glibc's, built natively: the same bits) and to_chars of doubles, shortest
// and with a precision (web/to_chars_fixed.cpp against libc++'s own). make
// web-test builds it four ways (-DTO_CHARS: to_chars) and compares the outputs.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <initializer_list>

namespace {

std::uint64_t state = 2026;
std::uint64_t next() {  // SplitMix64, as course/utils/random.hpp
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
double any_double() {  // every finite bit pattern alike
  for (;;) {
    const std::uint64_t bits = next();
    double d;
    std::memcpy(&d, &bits, sizeof d);
    if (std::isfinite(d)) return d;
  }
}
// A double's bits in hex (printf's %a writes subnormals differently in glibc and musl).
unsigned long long bits(double d) {
  std::uint64_t b;
  std::memcpy(&b, &d, sizeof b);
  return b;
}
double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53 * 2 - 1; }

[[maybe_unused]] void hypots() {
  for (int i = 0; i < 1000000; ++i) {
    const int scale = static_cast<int>(next() % 40) - 20, shift = static_cast<int>(next() % 8);
    const double a = std::ldexp(unit(), scale), b = std::ldexp(unit(), scale - shift);
    std::printf("%016llx\n", bits(std::hypot(a, b)));
  }
  for (const double a : {0.0, 1e-320, 1e-300, 1e300, 1.7976931348623157e308, double(INFINITY), double(NAN)})
    std::printf("%016llx %016llx\n", bits(std::hypot(a, 3.0)), bits(std::hypot(a, a)));
}

void put(std::to_chars_result r, char* buf) {
  *r.ptr = '\0';
  std::puts(buf);
}

[[maybe_unused]] void shortest_and_precise() {
  char buf[400];
  for (int i = 0; i < 200000; ++i) put(std::to_chars(buf, buf + sizeof buf, any_double()), buf);
  for (int i = 0; i < 200000; ++i) {  // integers past 2^53 (printed in fixed notation through d2fixed)
    const std::uint64_t m = next() >> (next() % 40);
    const double d = std::ldexp(static_cast<double>(m), static_cast<int>(next() % 80));
    put(std::to_chars(buf, buf + sizeof buf, d), buf);
    put(std::to_chars(buf, buf + sizeof buf, -d), buf);
  }
  for (int e = 0; e < 1024; ++e) put(std::to_chars(buf, buf + sizeof buf, std::ldexp(1.0, e)), buf);
  for (int i = 0; i < 20000; ++i) {
    const int p = static_cast<int>(next() % 30);
    put(std::to_chars(buf, buf + sizeof buf, any_double(), std::chars_format::scientific, p), buf);
    const double v = std::ldexp(static_cast<double>(next() >> 12), static_cast<int>(next() % 60) - 30);
    put(std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, p), buf);
    // The general format (format_g: messages, the summary, the dumps' sizes), through both helpers.
    put(std::to_chars(buf, buf + sizeof buf, any_double(), std::chars_format::general, p % 18), buf);
    put(std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, p % 18), buf);
  }
}

}  // namespace

int main() {
#ifdef TO_CHARS
  shortest_and_precise();
#else
  hypots();
#endif
  return 0;
}
