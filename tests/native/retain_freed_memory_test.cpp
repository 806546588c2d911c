// The native programs keep freed memory in the process (cli/retain_freed_memory.hpp): a large
// block, once freed, stays in glibc's heap for the next allocation instead of going back to the
// kernel, whose page faults made a new 1024² mesh cost 142 ms instead of 5 on a VM.
#include <doctest.h>

#include <vector>

#include "../../cli/retain_freed_memory.hpp"

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PDESURF_TEST_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define PDESURF_TEST_ASAN 1
#endif

// glibc's own allocator only: ASan replaces it (and ignores mallopt), wasm has no glibc.
#if defined(__GLIBC__) && !defined(PDESURF_TEST_ASAN)
#include <malloc.h>

TEST_CASE("a freed 16 MiB block stays in the process for the next allocation") {
  pdesurf::platform::retainFreedMemory();
  constexpr size_t kBytes = size_t(16) << 20;
  const auto before = mallinfo2();
  {
    std::vector<char> block(kBytes, 1);
    const auto held = mallinfo2();
    // From the heap, not a mapping of its own (glibc's default maps any block above 128 KiB).
    CHECK(held.hblkhd == before.hblkhd);
    CHECK(held.uordblks >= before.uordblks + kBytes);
  }
  const auto after = mallinfo2();
  CHECK(after.hblkhd == before.hblkhd);
  // Freed but kept: the heap still holds the block's bytes as free space.
  CHECK(after.fordblks >= before.fordblks + kBytes - (size_t(1) << 20));
  CHECK(after.arena >= before.arena + kBytes - (size_t(1) << 20));
}
#endif
