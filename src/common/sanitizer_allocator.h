#pragma once

// VDC_SANITIZER_ALLOCATOR is defined when a sanitizer's allocator replaces the C library's: the
// C library's heap count then misses every block, and its trim has nothing to give back.

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define VDC_SANITIZER_ALLOCATOR 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define VDC_SANITIZER_ALLOCATOR 1
#endif
