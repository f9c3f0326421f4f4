#include "core/pointcloud/cloud_files.hpp"

#include "core/io/files.hpp"
#include "core/pointcloud/ply.hpp"
#include "core/pointcloud/point_fields.hpp"
#include "core/pointcloud/point_text.hpp"
#include "core/text/echo.hpp"

#include <cmath>
#include <stdexcept>
#include <system_error>

namespace draught {

namespace {

std::string lower_extension(const std::filesystem::path& p) {
  std::string e = p.extension().string();
  for (char& c : e)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  return e;
}

bool accepted_extension(const std::string& e) { return e == ".ply" || e == ".xyz" || e == ".csv" || e == ".txt"; }

std::string shown(const std::filesystem::path& p) { return std::string(utf8_prefix(p.string(), kEchoPathBytes)); }

bool is_digit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

PointCloud load_point_cloud(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  if (!accepted_extension(ext))
    throw InputError(shown(path) + ": unknown point cloud extension " + quote_token(ext) +
                     ": expected .ply, .xyz, .csv or .txt");
  const std::string bytes = read_whole_file(path, kMaxPointCloudFileBytes, "a point cloud");
  return ext == ".ply" ? parse_ply(bytes, shown(path)) : parse_point_text(bytes, shown(path));
}

PointCloudSequence::PointCloudSequence(const std::filesystem::path& given) {
  dir_ = given.parent_path();
  const std::string file = given.filename().string();
  if (!accepted_extension(lower_extension(given)))
    throw InputError(shown(given) + ": unknown point cloud extension " + quote_token(lower_extension(given)) +
                     ": expected .ply, .xyz, .csv or .txt");
  const std::string stem = given.stem().string(), ext = given.extension().string();
  if (const std::size_t pct = stem.find('%'); pct != std::string::npos) {
    // A pattern: %d or %0Nd, once.
    std::size_t i = pct + 1;
    int width = 1;
    if (i < stem.size() && stem[i] == '0') {
      ++i;
      if (i >= stem.size() || !is_digit(stem[i]) || stem[i] == '0')
        throw InputError(shown(given) + ": expected the pattern's number as %d or %0Nd (N from 1 to 9)");
      width = stem[i++] - '0';
    }
    if (i >= stem.size() || stem[i] != 'd' || stem.find('%', i) != std::string::npos)
      throw InputError(shown(given) + ": expected one %d or %0Nd in the file name (N from 1 to 9), such as frame_%04d.ply");
    prefix_ = stem.substr(0, pct);
    suffix_ = stem.substr(i + 1) + ext;
    width_ = width;
    std::error_code ec;
    if (std::filesystem::is_regular_file(frame_path_of(0), ec)) first_ = 0;
    else if (std::filesystem::is_regular_file(frame_path_of(1), ec)) first_ = 1;
    else
      throw InputError(shown(given) + ": no first frame: expected " + shown(frame_path_of(0)) + " or " +
                       shown(frame_path_of(1)));
  } else {
    std::size_t end = stem.size(), start = end;
    while (start > 0 && is_digit(stem[start - 1])) --start;
    if (start == end)
      throw InputError(shown(given) + ": no frame number in the file name: expected digits before the extension "
                                      "(frame_0001.ply) or a pattern (frame_%04d.ply)");
    if (end - start > 9)
      throw InputError(shown(given) + ": a frame number of " + std::to_string(end - start) +
                       " digits: expected at most 9");
    prefix_ = stem.substr(0, start);
    suffix_ = stem.substr(end) + ext;
    width_ = int(end - start);
    first_ = std::stoul(stem.substr(start, end - start));
    std::error_code ec;
    if (!std::filesystem::is_regular_file(given, ec))
      throw InputError(shown(given) + ": no such frame: expected an existing file of the sequence");
    // The run includes this frame: earlier frames down to the first gap.
    for (std::size_t back = 0; first_ > 0 && back <= kMaxCloudSequenceFrames &&
                               std::filesystem::is_regular_file(frame_path_of(first_ - 1), ec);
         ++back)
      --first_;
  }
  std::error_code ec;
  while (std::filesystem::is_regular_file(frame_path_of(first_ + count_), ec)) {
    if (++count_ > kMaxCloudSequenceFrames)
      throw InputError(shown(given) + ": more than " + std::to_string(kMaxCloudSequenceFrames) +
                       " frames: expected at most that many");
  }
}

std::filesystem::path PointCloudSequence::frame_path_of(std::size_t number) const {
  std::string digits = std::to_string(number);
  if (digits.size() < std::size_t(width_)) digits.insert(0, std::size_t(width_) - digits.size(), '0');
  return dir_ / (prefix_ + digits + suffix_);
}

std::filesystem::path PointCloudSequence::frame_path(std::size_t i) const {
  if (i >= count_) throw std::out_of_range("PointCloudSequence: frame " + std::to_string(i) + " of " + std::to_string(count_));
  return frame_path_of(first_ + i);
}

std::size_t PointCloudSequence::frame_index(double seconds, double rate, bool loop) const {
  if (!(rate > 0) || !std::isfinite(rate)) throw std::invalid_argument("PointCloudSequence: the rate must be positive");
  const double f = std::floor(seconds * rate);
  if (!(f > 0)) return 0;  // before the start, and NaN
  const double n = double(count_);
  if (loop) return std::isfinite(f) ? std::size_t(std::fmod(f, n)) : 0;
  return f >= n - 1 ? count_ - 1 : std::size_t(f);
}

const PointCloud& PointCloudSequence::frame(std::size_t i) {
  const std::filesystem::path path = frame_path(i);
  for (auto it = cache_.begin(); it != cache_.end(); ++it) {
    if (it->first != i) continue;
    cache_.splice(cache_.begin(), cache_, it);  // now the most recent
    return *cache_.front().second;
  }
  // Loaded before anything is evicted: a frame that fails leaves the cache as it was.
  auto cloud = std::make_unique<PointCloud>(load_point_cloud(path));
  if (cache_.size() == kCloudSequenceCache) cache_.pop_back();
  cache_.emplace_front(i, std::move(cloud));
  return *cache_.front().second;
}

}  // namespace draught
