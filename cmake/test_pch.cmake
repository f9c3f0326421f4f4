# The headers nearly every test includes, precompiled once per test executable: parsing
# gtest, glm and the standard library was 2 of a test file's 3-5 s to compile (g++ 12,
# -O3), in the main build and again in the sanitized one (docs/PERFORMANCE.md).
set(DRAUGHT_TEST_PRECOMPILED_HEADERS
  <algorithm> <cmath> <cstdio> <filesystem> <numbers> <string> <vector>
  <glm/glm.hpp> <gtest/gtest.h>)
