#pragma once
// Native programs only (the CLI, the benchmark, the native tests); the core stays free of platform code.
//
// glibc gives large blocks back to the kernel when they are freed: blocks above its mmap threshold
// are unmapped, and the heap's free top is trimmed. The next solve or mesh of the same size then
// faults every page in again. On a virtual machine a first touch is expensive (about 9 us per
// 4 KiB page on the Firecracker VM this project is built on), which made a new 1024x1024 mesh
// cost 142 ms instead of 5 ms, and a 16x16 membrane solve 60 ms instead of 7. Wasm never sees
// this: its linear memory only grows. The peak is unchanged (284 MB for the aeroplane's STEP
// export); what is freed stays resident until the process ends.
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace pdesurf::platform {

inline void retainFreedMemory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 32 << 20);  // the largest glibc accepts; larger blocks are still mapped
  mallopt(M_TRIM_THRESHOLD, 1 << 30);   // keep up to 1 GiB of freed heap for the next allocation
#endif
}

}  // namespace pdesurf::platform
