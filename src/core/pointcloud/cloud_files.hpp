// Point cloud files by path: one cloud by its extension (.ply, .xyz, .csv, .txt), and
// numbered sequences of them (a simulation's frames), loaded on demand a few at a time.
// docs/POINT_CLOUDS.md.
#pragma once

#include "core/pointcloud/cloud.hpp"

#include <cstddef>
#include <filesystem>
#include <list>
#include <memory>
#include <string>
#include <utility>

namespace draught {

// The cloud in a file: .ply by parse_ply, .xyz, .csv and .txt by parse_point_text (the
// extension in any case). Read whole (at most kMaxPointCloudFileBytes; folders, FIFOs and
// devices refused); errors name the file. An unknown extension is an error that lists
// the accepted ones.
PointCloud load_point_cloud(const std::filesystem::path&);

// The most frames of a sequence (an hour at 25 frames a second is 90,000).
inline constexpr std::size_t kMaxCloudSequenceFrames = 100000;
// Frames a sequence keeps loaded: the one shown, the one before and the next.
inline constexpr std::size_t kCloudSequenceCache = 3;

// Numbered clouds, frame_0001.ply, frame_0002.ply, ... Opened from either
//  - the path of one frame ("flow/frame_0012.ply"): the number is the last run of digits
//    in the file's name before the extension; the sequence is the contiguous run of
//    existing frames with the same prefix, the same count of digits (zero-padded, wider
//    only when a number needs it) and the same extension that includes this frame, which
//    must exist; or
//  - a pattern with one %d or %0Nd ("flow/frame_%04d.ply"): from the first of 0 and 1
//    that exists, up to the first missing number.
// Frames are found when the sequence is opened; each is read when asked for.
class PointCloudSequence {
 public:
  explicit PointCloudSequence(const std::filesystem::path& any_frame_or_pattern);

  std::size_t frame_count() const { return count_; }
  // The number in the name of the first frame, and the file of frame i (0-based).
  std::size_t first_number() const { return first_; }
  std::filesystem::path frame_path(std::size_t i) const;

  // The frame shown at `seconds` played at `rate` frames a second: floor(seconds x rate),
  // held at the last frame, or wrapped around when `loop`; before 0 it is frame 0.
  std::size_t frame_index(double seconds, double rate, bool loop) const;

  // Frame i, read on first use and kept among the last kCloudSequenceCache asked for. The
  // reference stays valid until kCloudSequenceCache other frames have been asked for. A
  // frame that fails to read throws its InputError (naming its file) and is not kept; the
  // sequence stays usable.
  const PointCloud& frame(std::size_t i);

  // Frames in memory now (for tests and the integrator's statistics).
  std::size_t cached_frames() const { return cache_.size(); }

 private:
  std::filesystem::path frame_path_of(std::size_t number) const;

  std::filesystem::path dir_;
  std::string prefix_, suffix_;  // the file name around the number
  int width_ = 1;                // digits, zero-padded
  std::size_t first_ = 0, count_ = 0;
  std::list<std::pair<std::size_t, std::unique_ptr<PointCloud>>> cache_;  // most recent first
};

}  // namespace draught
