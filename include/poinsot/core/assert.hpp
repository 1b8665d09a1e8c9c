#pragma once
/// @file assert.hpp
/// POINSOT_ASSERT(condition, message): a check of an internal invariant (an index in range, the sizes a
/// factorisation was built for, a pivot of a positive definite matrix), never of user input (that is
/// InvalidInput, check.hpp). Active in debug and sanitizer builds (NDEBUG undefined) or when
/// POINSOT_ENABLE_ASSERTS is defined; in release builds the condition is not evaluated and costs nothing. A
/// failure is a bug in poinsot: it prints `poinsot: internal error: FILE:LINE: CONDITION (MESSAGE)` on
/// stderr and aborts, since the state can no longer be trusted.

namespace poinsot::detail {

/// Prints the failed assertion on stderr and aborts.
[[noreturn]] void assertion_failed(const char* condition, const char* message, const char* file,
                                   int line) noexcept;

}  // namespace poinsot::detail

#if defined(NDEBUG) && !defined(POINSOT_ENABLE_ASSERTS)
#define POINSOT_ASSERTS_ENABLED 0
// Not evaluated (sizeof), but its names count as used, so that release builds warn about nothing.
#define POINSOT_ASSERT(condition, message) static_cast<void>(sizeof((condition) ? 1 : 0))
#else
#define POINSOT_ASSERTS_ENABLED 1
#define POINSOT_ASSERT(condition, message) \
  ((condition) ? static_cast<void>(0)      \
               : ::poinsot::detail::assertion_failed(#condition, (message), __FILE__, __LINE__))
#endif
