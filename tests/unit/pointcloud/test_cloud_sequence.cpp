// Numbered point cloud files as a sequence: the run found from one frame or a pattern,
// the frame shown at a time, and frames read on demand into a cache of a few.
#include "core/io/files.hpp"
#include "core/pointcloud/cloud_files.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <unistd.h>

namespace draught {
namespace {

// A fresh folder per test, removed afterwards.
class TempDir {
 public:
  explicit TempDir(const std::string& what)
      : path_(std::filesystem::temp_directory_path() / ("draught_test_seq_" + what + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// Frame n is one point at x = n.
void write_frame(const std::filesystem::path& dir, const std::string& name, int n) {
  write_file_atomic(dir / name, std::to_string(n) + " 0 0\n");
}

std::string frame_name(int n, int width = 4, const char* ext = ".csv") {
  char buf[64];
  std::snprintf(buf, sizeof buf, "frame_%0*d%s", width, n, ext);
  return buf;
}

std::string sequence_error_of(const std::filesystem::path& p) {
  try {
    PointCloudSequence s(p);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error for " << p;
  return "";
}

TEST(PointCloudSequence, FoundFromAnyFrameOrAPattern) {
  TempDir d("find");
  for (int n = 1; n <= 5; ++n) write_frame(d.path(), frame_name(n), n);
  write_frame(d.path(), frame_name(7), 7);                 // after a gap: not part of the run
  write_frame(d.path(), frame_name(2, 4, ".ply"), 2);      // another extension
  write_frame(d.path(), frame_name(3, 3), 3);              // another width
  for (const auto& given : {frame_name(1), frame_name(3), frame_name(5), std::string("frame_%04d.csv")}) {
    SCOPED_TRACE(given);
    PointCloudSequence s(d.path() / given);
    EXPECT_EQ(s.frame_count(), 5u);
    EXPECT_EQ(s.first_number(), 1u);
    EXPECT_EQ(s.frame_path(0), d.path() / frame_name(1));
    EXPECT_EQ(s.frame_path(4), d.path() / frame_name(5));
    EXPECT_EQ(s.frame(4).position.at(0).x, 5.0f);
  }
  // The run after the gap is a sequence of its own.
  PointCloudSequence after(d.path() / frame_name(7));
  EXPECT_EQ(after.frame_count(), 1u);
  EXPECT_EQ(after.first_number(), 7u);
  // A pattern starts at 0 when frame 0 exists.
  write_frame(d.path(), frame_name(0), 0);
  EXPECT_EQ(PointCloudSequence(d.path() / "frame_%04d.csv").frame_count(), 6u);
  EXPECT_EQ(PointCloudSequence(d.path() / "frame_%04d.csv").first_number(), 0u);
}

TEST(PointCloudSequence, NumbersGrowPastTheirWidth) {
  TempDir d("width");
  for (int n = 8; n <= 12; ++n) write_frame(d.path(), "drop" + std::to_string(n) + ".xyz", n);
  PointCloudSequence s(d.path() / "drop8.xyz");
  EXPECT_EQ(s.frame_count(), 5u);
  EXPECT_EQ(s.frame(4).position.at(0).x, 12.0f);
  EXPECT_THROW(PointCloudSequence(d.path() / "drop%d.xyz"), InputError);  // no frame 0 or 1
  write_frame(d.path(), "drop1.xyz", 1);  // 1, then a gap at 2
  EXPECT_EQ(PointCloudSequence(d.path() / "drop%d.xyz").frame_count(), 1u);
}

TEST(PointCloudSequence, MissingFramesAreErrorsNamingThem) {
  TempDir d("missing");
  write_frame(d.path(), frame_name(2), 2);
  EXPECT_EQ(sequence_error_of(d.path() / frame_name(9)),
            (d.path() / frame_name(9)).string() + ": no such frame: expected an existing file of the sequence");
  EXPECT_EQ(sequence_error_of(d.path() / "frame_%04d.csv"),
            (d.path() / "frame_%04d.csv").string() + ": no first frame: expected " + (d.path() / frame_name(0)).string() +
                " or " + (d.path() / frame_name(1)).string());
  EXPECT_EQ(sequence_error_of(d.path() / "frame_%4d.csv"),
            (d.path() / "frame_%4d.csv").string() + ": expected one %d or %0Nd in the file name (N from 1 to 9), such as frame_%04d.ply");
  EXPECT_EQ(sequence_error_of(d.path() / "frame.csv"),
            (d.path() / "frame.csv").string() +
                ": no frame number in the file name: expected digits before the extension (frame_0001.ply) or a pattern (frame_%04d.ply)");
  EXPECT_EQ(sequence_error_of(d.path() / "frame_0002.obj"),
            (d.path() / "frame_0002.obj").string() + ": unknown point cloud extension \".obj\": expected .ply, .xyz, .csv or .txt");
}

TEST(PointCloudSequence, FrameIndexByTimeRateAndLoop) {
  TempDir d("index");
  for (int n = 1; n <= 4; ++n) write_frame(d.path(), frame_name(n), n);
  PointCloudSequence s(d.path() / frame_name(1));
  EXPECT_EQ(s.frame_index(0.0, 10, false), 0u);
  EXPECT_EQ(s.frame_index(0.099, 10, false), 0u);
  EXPECT_EQ(s.frame_index(0.25, 10, false), 2u);
  EXPECT_EQ(s.frame_index(0.39, 10, false), 3u);
  EXPECT_EQ(s.frame_index(100.0, 10, false), 3u);   // held at the last frame
  EXPECT_EQ(s.frame_index(0.45, 10, true), 0u);     // wraps: floor(4.5) = 4 -> 0
  EXPECT_EQ(s.frame_index(0.65, 10, true), 2u);
  EXPECT_LT(s.frame_index(1e30, 10, true), 4u);     // far beyond any count: still a frame
  EXPECT_EQ(s.frame_index(-1.0, 10, true), 0u);     // before the start
  EXPECT_EQ(s.frame_index(std::nan(""), 10, false), 0u);
  EXPECT_THROW(s.frame_index(1.0, 0, false), std::invalid_argument);
}

TEST(PointCloudSequence, FramesAreCachedAFewAtATime) {
  TempDir d("cache");
  for (int n = 1; n <= 6; ++n) write_frame(d.path(), frame_name(n), n);
  PointCloudSequence s(d.path() / frame_name(1));
  EXPECT_EQ(s.cached_frames(), 0u);
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(s.frame(i).position.at(0).x, float(i + 1));
    EXPECT_EQ(s.cached_frames(), std::min<std::size_t>(i + 1, kCloudSequenceCache));
  }
  // Frames 3, 4, 5 are held: removing their files does not matter until they are evicted.
  const PointCloud* five = &s.frame(5);
  std::filesystem::remove(d.path() / frame_name(6));
  EXPECT_EQ(&s.frame(5), five);  // the same object, not read again
  EXPECT_EQ(s.frame(3).position.at(0).x, 4.0f);
  // Frame 0 was evicted; read again it comes from its file.
  write_frame(d.path(), frame_name(1), 100);
  EXPECT_EQ(s.frame(0).position.at(0).x, 100.0f);
  EXPECT_EQ(s.cached_frames(), kCloudSequenceCache);
  EXPECT_THROW(s.frame(6), std::out_of_range);
}

TEST(PointCloudSequence, AFrameThatFailsNamesItsFileAndTheSequenceGoesOn) {
  TempDir d("fail");
  for (int n = 1; n <= 3; ++n) write_frame(d.path(), frame_name(n), n);
  PointCloudSequence s(d.path() / frame_name(1));
  EXPECT_EQ(s.frame(0).position.at(0).x, 1.0f);
  write_file_atomic(d.path() / frame_name(2), "1 2 oops\n");
  try {
    s.frame(1);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), (d.path() / frame_name(2)).string() + ": line 1, column 3 (z): expected a number, got \"oops\"");
  }
  EXPECT_EQ(s.cached_frames(), 1u);
  std::filesystem::remove(d.path() / frame_name(3));
  try {
    s.frame(2);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind((d.path() / frame_name(3)).string() + ": cannot open file", 0), 0u) << e.what();
  }
  write_frame(d.path(), frame_name(2), 2);  // mended: the sequence reads it now
  EXPECT_EQ(s.frame(1).position.at(0).x, 2.0f);
  EXPECT_EQ(s.frame(0).position.at(0).x, 1.0f);
}

}  // namespace
}  // namespace draught
