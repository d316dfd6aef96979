// The C++ exception runtime of the WebAssembly build, for clang's
// -fwasm-exceptions (WebAssembly's exception handling: try/catch/rethrow
// instructions, one phase, no stack walk). Debian's libc++abi for
// wasm32-wasi (14, and 16, 19, 22 alike) is built without exceptions: it has
// no __cxa_throw, __cxa_begin_catch..., so a program that throws does not
// link. Here, in one place: the exception's header and allocation, throw
// and rethrow, begin and end of a catch, and the personality that reads a
// function's exception table (LSDA) to say which of its catch clauses takes
// the exception, with libc++abi's own type matching (can_catch: bases,
// pointers, qualifiers). Single-threaded, as the module is.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <typeinfo>

namespace __cxxabiv1 {
// libc++abi's base of every type_info (private_typeinfo.h), declared in the
// same order so that can_catch is the same virtual slot.
class __shim_type_info : public std::type_info {
 public:
  ~__shim_type_info() override;
  virtual void noop1() const;
  virtual void noop2() const;
  virtual bool can_catch(const __shim_type_info* thrown_type, void*& adjusted) const = 0;
};
}  // namespace __cxxabiv1

namespace {

using __cxxabiv1::__shim_type_info;

// In WebAssembly's C++ ABI destructors return `this` (as on 32-bit ARM), so
// the one __cxa_throw gets has this type: called through another, it traps.
using Destructor = void* (*)(void*);

// Before each thrown object. `handlers`: the catch clauses that hold it
// (nested catches of one exception count each); `rethrown`: a throw; is on
// its way, so the end of the catch it leaves does not free it.
struct Header {
  std::type_info* type;
  Destructor destroy;
  Header* next_caught;  // the caught exceptions, innermost first
  void* adjusted;       // the object as the clause chosen takes it
  int handlers;
  bool rethrown;
  // What the `throw` instruction carries: this field's address.
  std::uint64_t tag;
};
constexpr std::size_t header_size = (sizeof(Header) + 15) & ~std::size_t{15};  // the object stays 16-aligned

Header* header_of_object(void* object) { return reinterpret_cast<Header*>(static_cast<char*>(object) - header_size); }
void* object_of(Header* h) { return reinterpret_cast<char*>(h) + header_size; }
Header* header_of_thrown(void* thrown) {
  return reinterpret_cast<Header*>(static_cast<char*>(thrown) - offsetof(Header, tag));
}

// The innermost exception being handled. (std::uncaught_exceptions is
// libc++'s, built without exceptions: always 0; nothing here uses it.)
Header* caught = nullptr;

// The LSDA's variable-length numbers.
std::uintptr_t uleb(const std::uint8_t*& p) {
  std::uintptr_t v = 0;
  for (unsigned shift = 0;; shift += 7) {
    const std::uint8_t b = *p++;
    v |= std::uintptr_t(b & 0x7f) << shift;
    if (!(b & 0x80)) return v;
  }
}
std::intptr_t sleb(const std::uint8_t*& p) {
  std::uintptr_t v = 0;
  unsigned shift = 0;
  std::uint8_t b;
  do {
    b = *p++;
    v |= std::uintptr_t(b & 0x7f) << shift;
    shift += 7;
  } while (b & 0x80);
  if (shift < 8 * sizeof v && (b & 0x40)) v |= ~std::uintptr_t(0) << shift;
  return static_cast<std::intptr_t>(v);
}

// The catch clause of landing pad `index` in `lsda` that takes `h`: its
// type's index in the type table (what the compiled code compares with), or 0.
std::uintptr_t select(const std::uint8_t* lsda, std::uintptr_t index, Header* h) {
  const std::uint8_t* p = lsda;
  if (*p++ != 0xff) std::abort();  // @LPStart: always omitted by clang for wasm
  const std::uint8_t ttype_encoding = *p++;
  const std::uint8_t* types = nullptr;
  if (ttype_encoding != 0xff) {
    const std::uintptr_t offset = uleb(p);
    types = p + offset;
  }
  if (*p++ != 0x01) std::abort();  // call sites in uleb128
  const std::uintptr_t length = uleb(p);
  const std::uint8_t* actions = p + length;
  std::uintptr_t action = 0;
  for (std::uintptr_t i = 0; i <= index; ++i) {
    uleb(p);  // the landing pad's number
    action = uleb(p);
  }
  if (action == 0 || !types) return 0;  // a cleanup only
  for (const std::uint8_t* a = actions + action - 1;;) {
    const std::intptr_t type_index = sleb(a);
    const std::uint8_t* at = a;
    const std::intptr_t next = sleb(a);
    if (type_index > 0) {
      const std::type_info* t;
      std::memcpy(&t, types - type_index * sizeof(void*), sizeof t);  // absptr: 4 bytes
      void* adjusted = object_of(h);
      if (!t || static_cast<const __shim_type_info*>(t)->can_catch(static_cast<const __shim_type_info*>(h->type), adjusted)) {
        h->adjusted = adjusted;
        return static_cast<std::uintptr_t>(type_index);
      }
    }
    if (next == 0) return 0;
    a = at + next;
  }
}

[[noreturn]] void raise(Header* h) {
  __builtin_wasm_throw(0, &h->tag);
}

}  // namespace

extern "C" {

// What the compiled catch pads fill in before calling the personality:
// the landing pad's index in the function's LSDA, the LSDA, and back the
// selector (the clause's type index, or 0 for none).
struct LandingPadContext {
  std::uintptr_t lpad_index;
  const std::uint8_t* lsda;
  std::uintptr_t selector;
} __wasm_lpad_context;

int _Unwind_CallPersonality(void* thrown) {
  __wasm_lpad_context.selector = select(__wasm_lpad_context.lsda, __wasm_lpad_context.lpad_index, header_of_thrown(thrown));
  return __wasm_lpad_context.selector ? 6 : 8;  // _URC_HANDLER_FOUND, _URC_CONTINUE_UNWIND
}

void* __cxa_allocate_exception(std::size_t size) noexcept {
  void* p = std::aligned_alloc(16, header_size + ((size + 15) & ~std::size_t{15}));
  if (!p) std::terminate();
  std::memset(p, 0, header_size);
  return static_cast<char*>(p) + header_size;
}

void __cxa_free_exception(void* object) noexcept { std::free(header_of_object(object)); }

[[noreturn]] void __cxa_throw(void* object, std::type_info* type, Destructor destroy) {
  Header* h = header_of_object(object);
  h->type = type;
  h->destroy = destroy;
  raise(h);
}

void* __cxa_begin_catch(void* thrown) noexcept {
  Header* h = header_of_thrown(thrown);
  h->rethrown = false;
  if (h->handlers++ == 0) {
    h->next_caught = caught;
    caught = h;
  }
  return h->adjusted ? h->adjusted : object_of(h);
}

void __cxa_end_catch() {
  Header* h = caught;
  if (!h || --h->handlers > 0) return;
  caught = h->next_caught;
  if (h->rethrown) return;  // on its way out: the next catch ends it
  if (h->destroy) h->destroy(object_of(h));
  __cxa_free_exception(object_of(h));
}

[[noreturn]] void __cxa_rethrow() {
  Header* h = caught;
  if (!h) std::terminate();
  h->rethrown = true;
  raise(h);
}

void* __cxa_get_exception_ptr(void* thrown) noexcept {
  Header* h = header_of_thrown(thrown);
  return h->adjusted ? h->adjusted : object_of(h);
}

}
