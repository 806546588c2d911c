#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest.h>

#include "../../cli/retain_freed_memory.hpp"

int main(int argc, char** argv) {
  pdesurf::platform::retainFreedMemory();  // as the CLI does (2 s of page faults less)
  doctest::Context context(argc, argv);
  return context.run();
}
