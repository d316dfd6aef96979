// hypot for the WebAssembly build: glibc's (sysdeps/ieee754/dbl-64/e_hypot.c
// since glibc 2.35, the kernel without FMA that x86-64 runs), so that
// Vector::norm gives the native build's bits. wasi-libc's is musl's, which
// differs from glibc's in the last bit for about 13% of arguments (checked
// on 2 000 000 pairs), and changed the determinism scene's substeps hash.
// Carlos F. Borges's correction of sqrt(x^2 + y^2), "An Improved Algorithm
// for hypot(a, b)" (2019). Linked before libm, so this one is taken.
#include <cmath>

namespace {

constexpr double scale = 0x1p-600, large_val = 0x1p+511, tiny_val = 0x1p-511, eps = 0x1p-54;

// ax >= ay >= 0, their squares and (ax - ay)'s neither overflow nor underflow.
double kernel(double ax, double ay) {
  double h = std::sqrt(ax * ax + ay * ay);
  double t1, t2;
  if (h <= 2.0 * ay) {
    const double delta = h - ay;
    t1 = ax * (2.0 * delta - ax);
    t2 = (delta - 2.0 * (ax - ay)) * delta;
  } else {
    const double delta = h - ax;
    t1 = 2.0 * delta * (ax - 2.0 * ay);
    t2 = (4.0 * delta - ay) * ay + delta * delta;
  }
  h -= (t1 + t2) / (2.0 * h);
  return h;
}

}  // namespace

extern "C" double hypot(double x, double y) {
  if (!std::isfinite(x) || !std::isfinite(y)) {
    if (std::isinf(x) || std::isinf(y)) return INFINITY;
    return x + y;
  }
  x = std::fabs(x), y = std::fabs(y);
  double ax = x < y ? y : x, ay = x < y ? x : y;
  if (ax > large_val) {
    if (ay <= ax * eps) return ax + ay;
    return kernel(ax * scale, ay * scale) / scale;
  }
  if (ay < tiny_val) {
    if (ax >= ay / eps) return ax + ay;
    return kernel(ax / scale, ay / scale) * scale;
  }
  if (ay <= ax * eps) return ax + ay;
  return kernel(ax, ay);
}
