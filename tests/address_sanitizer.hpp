#pragma once
// Whether this test binary was built with AddressSanitizer (gcc defines __SANITIZE_ADDRESS__, clang answers
// __has_feature). ASan reserves terabytes of address space for its shadow memory, so a test that limits the address
// space (`ulimit -v`, setrlimit) must take another way there, or skip.
namespace heliostand::testing {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool address_sanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool address_sanitizer = true;
#else
inline constexpr bool address_sanitizer = false;
#endif
#else
inline constexpr bool address_sanitizer = false;
#endif

}  // namespace heliostand::testing
