// The stored references of the reference comparisons (stored_reference.hpp): what is
// stored comes back as path-traced; a scene changed since, another size, a missing or
// damaged file are refused with the command that renders them afresh.
#include "gpu_fixture.hpp"
#include "stored_reference.hpp"

#include "core/io/files.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace draught::test {
namespace {

namespace fs = std::filesystem;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

class StoredReferenceFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("draught-stored-reference-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    settings_.samples = 8;  // small: this checks the bookkeeping, not the light
    settings_.threads = 1;
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
  ReferenceSettings settings_;
  const FrameState pint_ = scene_frame(SceneRequest{"lager", "pint"});
};

TEST_F(StoredReferenceFiles, WhatIsStoredComesBackAsPathTraced) {
  const StoredReference blessed = stored_reference(dir_, "pint", pint_, 12, 10, settings_, true);
  ASSERT_TRUE(blessed.error.empty()) << blessed.error;
  EXPECT_TRUE(fs::exists(dir_ / "pint.exr"));
  EXPECT_TRUE(fs::exists(dir_ / "pint.check.exr"));
  const StoredReference read = stored_reference(dir_, "pint", pint_, 12, 10, settings_, false);
  ASSERT_TRUE(read.error.empty()) << read.error;
  EXPECT_TRUE(has(read.how, "check")) << read.how;
  ASSERT_EQ(read.radiance.pixels.size(), blessed.radiance.pixels.size());
  double brightest = 0;
  for (size_t i = 0; i < read.radiance.pixels.size(); ++i) {
    for (int c = 0; c < 3; ++c)  // float, as stored
      EXPECT_EQ(read.radiance.pixels[i][c], double(float(blessed.radiance.pixels[i][c]))) << i;
    brightest = std::max(brightest, read.radiance.pixels[i].g);
  }
  EXPECT_GT(brightest, 0.0);  // a picture, not zeros
}

TEST_F(StoredReferenceFiles, AChangedSceneIsRefusedNamingAPixelAndTheCommand) {
  ASSERT_TRUE(stored_reference(dir_, "pint", pint_, 12, 10, settings_, true).error.empty());
  const FrameState stout = scene_frame(SceneRequest{"stout", "pint"});
  const StoredReference stale = stored_reference(dir_, "pint", stout, 12, 10, settings_, false);
  EXPECT_TRUE(stale.radiance.pixels.empty());
  EXPECT_TRUE(has(stale.error, "pint.exr was path-traced from another scene or other code")) << stale.error;
  EXPECT_TRUE(has(stale.error, "pixel (")) << stale.error;
  EXPECT_TRUE(has(stale.error, "scripts/bless-references.sh pint")) << stale.error;
  // The same scene with other random numbers is other paths too.
  ReferenceSettings reseeded = settings_;
  reseeded.seed = 7;
  EXPECT_TRUE(has(stored_reference(dir_, "pint", pint_, 12, 10, reseeded, false).error, "another scene or other code"));
}

TEST_F(StoredReferenceFiles, AnotherSizeAMissingAndADamagedFileAreRefused) {
  EXPECT_TRUE(has(stored_reference(dir_, "pint", pint_, 12, 10, settings_, false).error,
                  "pint.exr or its check is missing: path-trace it with scripts/bless-references.sh pint"));
  ASSERT_TRUE(stored_reference(dir_, "pint", pint_, 12, 10, settings_, true).error.empty());
  EXPECT_TRUE(has(stored_reference(dir_, "pint", pint_, 16, 10, settings_, false).error, "is 12 x 10, the case 16 x 10"));
  {
    std::ofstream cut(dir_ / "pint.exr", std::ios::binary | std::ios::trunc);
    cut << "v/1\x01 not an image";
  }
  const std::string damaged = stored_reference(dir_, "pint", pint_, 12, 10, settings_, false).error;
  EXPECT_TRUE(has(damaged, "OpenEXR")) << damaged;
  EXPECT_TRUE(has(damaged, "scripts/bless-references.sh pint")) << damaged;
}

}  // namespace
}  // namespace draught::test
