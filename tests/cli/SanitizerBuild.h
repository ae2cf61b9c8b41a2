#pragma once
// Whether this test binary is built with AddressSanitizer (the `sanitize` and `debug` presets):
// tests that cannot run under it (ptrace, library lists) ask here.
namespace vl::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif
#else
inline constexpr bool kAddressSanitizer = false;
#endif

} // namespace vl::test
