# How the test executables are compiled (tests/ and the sanitized unit suite in fuzz/).
#
# The headers nearly every test includes, precompiled once per test executable: parsing
# gtest, glm and the standard library was 2 of a test file's 3-5 s to compile (g++ 12,
# -O3), in the main build and again in the sanitized one (docs/PERFORMANCE.md).
set(DRAUGHT_TEST_PRECOMPILED_HEADERS
  <algorithm> <cmath> <cstdio> <filesystem> <numbers> <string> <vector>
  <glm/glm.hpp> <gtest/gtest.h>)

# The tests' own files at -O1 in the main build; the libraries they test keep the build
# type's -O3. A test file is assertions and setup: at -O3 the three suites took 495 s of
# CPU to compile, at -O1 335 s, and the unit suite ran in the same time (60 s); at -O0 it
# ran twice as long. (In the sanitized build clang gained 6 % from -O1, so it keeps -O2.)
set(DRAUGHT_TEST_COMPILE_OPTIONS -O1)
