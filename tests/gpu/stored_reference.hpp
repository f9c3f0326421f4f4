// The reference comparisons' path-traced references, kept beside the goldens in
// tests/golden/reference/ so a run does not path-trace them again (they were about half
// of the suite's CPU time). Per comparison case:
//   <case>.exr        the reference radiance (32-bit float, linear) at the case's paths;
//   <case>.check.exr  the same frame at its first kCheckPaths paths per pixel.
// A run path-traces only the check (a few hundredths of the cost) and requires it to equal
// the stored one. Every pixel's paths are seeded by the pixel alone, so the check is the
// reference's own first paths: a change in the scene, the camera, the settings or the
// path tracer that changes what those paths carry fails the test, naming the pixel and
// the command that renders the references afresh (scripts/bless-references.sh). A change
// that touches none of them (a path no pixel's first few take) goes unseen until then.
#pragma once

#include "core/reference/path_tracer.hpp"

#include <filesystem>
#include <string>

namespace draught::test {

inline constexpr int kCheckPaths = 4;

struct StoredReference {
  RadianceImage radiance;
  std::string how;    // where it came from, for the test's log
  std::string error;  // set: no usable stored reference (missing, another size, stale)
};

// The reference of case `name` (file names: the case's test name), read from `dir` and
// checked as above; with `bless`, path-traced in full and written there first (atomically).
StoredReference stored_reference(const std::filesystem::path& dir, const std::string& name, const FrameState&,
                                 int width, int height, const ReferenceSettings&, bool bless);

}  // namespace draught::test
