// The native programs keep freed memory in the process (cli/retain_freed_memory.hpp): a large
// block, once freed, stays in glibc's heap for the next allocation instead of going back to the
// kernel, whose page faults made a new 1024² mesh cost 142 ms instead of 5 on a VM.
#include <doctest.h>

#include <vector>

#include "../../cli/retain_freed_memory.hpp"
#include "test_util.hpp"

// glibc's own allocator only: wasm has no glibc, and ASan replaces it (and ignores mallopt).
#if defined(__GLIBC__)
#include <malloc.h>

TEST_CASE("freed blocks stay in the process for the next allocation" *
          doctest::skip(pdesurf::testing::kAddressSanitizer)) {
  pdesurf::platform::retainFreedMemory();
  constexpr size_t kMiB = size_t(1) << 20;
  const auto before = mallinfo2();
  // More than the heap has free, so that at least 80 MiB extend its top: freed again, they form
  // a free top beyond glibc's own trim threshold (at most 64 MiB), which would hand it back.
  const size_t count = before.fordblks / kMiB + 80;
  struct mallinfo2 held {};
  {
    std::vector<std::vector<char>> blocks;
    blocks.reserve(count);
    for (size_t i = 0; i < count; ++i) blocks.emplace_back(kMiB, char(i));
    held = mallinfo2();
    // From the heap, not mappings of their own (glibc's default maps any block above 128 KiB).
    CHECK(held.hblkhd == before.hblkhd);
    CHECK(held.uordblks >= before.uordblks + count * kMiB);
    while (!blocks.empty()) blocks.pop_back();  // the newest first, each next to the heap's top
  }
  const auto after = mallinfo2();
  CHECK(after.hblkhd == before.hblkhd);
  // Freed but kept: the heap did not shrink, and the blocks' bytes became free space in it.
  CHECK(after.arena >= held.arena);
  CHECK(after.fordblks >= held.fordblks + count * kMiB);
}
#endif
