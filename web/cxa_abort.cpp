// The C++ exception runtime of the WebAssembly build, reduced to throwing.
// Debian's libc++abi for wasm32-wasi (14, and 16, 19, 22 alike) is built
// without exceptions: it has no __cxa_throw, so a program that throws does not
// link (wasm-ld: undefined symbol: __cxa_allocate_exception, __cxa_throw).
// Here a throw writes its message (every exception this code base throws is a
// std::exception: SceneError, physics::Error, std::invalid_argument, JSON's)
// and traps; the page shows it. Without -fwasm-exceptions clang keeps the
// try blocks and drops their handlers, so nothing is ever caught: the web
// build runs the paths that throw only on bad input, and its inputs are the
// committed scenes (docs/web.md, "Exceptions").
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <typeinfo>

extern "C" {

void* __cxa_allocate_exception(std::size_t size) noexcept {
  void* p = std::calloc(1, size);
  if (!p) std::abort();
  return p;
}

void __cxa_free_exception(void* p) noexcept { std::free(p); }

[[noreturn]] void __cxa_throw(void* object, std::type_info* type, void (*)(void*)) {
  // The thrown classes derive from std::exception first (single inheritance),
  // so the object's address is its std::exception's.
  const auto* e = static_cast<const std::exception*>(object);
  std::fprintf(stderr, "error: %s (%s thrown; the web build stops on an exception)\n", e->what(), type->name());
  std::fflush(stderr);
  __builtin_trap();
}

}
