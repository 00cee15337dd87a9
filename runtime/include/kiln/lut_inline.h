// kiln/lut_inline.h: the inlining macros of the runtime's lookup paths (kiln/lut.h,
// kiln/lut_float_path.h). Depends on nothing.
#pragma once

/// Keeps a rarely taken function out of line, so the lookup fast paths stay small.
#ifndef KILN_NOINLINE
#if defined(__GNUC__) || defined(__clang__)
#define KILN_NOINLINE __attribute__((noinline))
#elif defined(_MSC_VER)
#define KILN_NOINLINE __declspec(noinline)
#else
#define KILN_NOINLINE
#endif
#endif

/// Inlines a small function of a lookup fast path (which compilers may otherwise keep out of
/// line, judging it by its rarely taken branches).
#ifndef KILN_INLINE
#if defined(__GNUC__) || defined(__clang__)
#define KILN_INLINE inline __attribute__((always_inline))
#elif defined(_MSC_VER)
#define KILN_INLINE __forceinline
#else
#define KILN_INLINE inline
#endif
#endif
