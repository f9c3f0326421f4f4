// gpu_tests entry point: GoogleTest, plus --bless to re-write the golden images
// (scripts/bless-goldens.sh). Blessing is deliberate: look at every image it writes.
#include "gpu_fixture.hpp"

#include <gtest/gtest.h>

#include <cstring>

namespace draught::test {
bool g_bless = false;
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  for (int i = 1; i < argc; ++i)
    if (!std::strcmp(argv[i], "--bless")) draught::test::g_bless = true;
  return RUN_ALL_TESTS();
}
