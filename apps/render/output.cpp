#include "output.hpp"

#include "core/io/files.hpp"
#include "core/io/temporaries.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdio.h>  // renameat2
#include <fcntl.h>

namespace draught::cli {

namespace fs = std::filesystem;

namespace {

// Is `inner` `outer` or somewhere below it? Both must exist.
bool inside(const fs::path& inner, const fs::path& outer) {
  std::error_code ec;
  const fs::path a = fs::canonical(inner, ec), b = fs::canonical(outer, ec);
  if (ec) return false;
  auto [end, _] = std::mismatch(b.begin(), b.end(), a.begin(), a.end());
  return end == b.end();
}

bool is_frame_name(const std::string& name) {  // frame_ + at least five digits + .png
  if (!name.starts_with("frame_") || !name.ends_with(".png") || name.size() < 6 + 5 + 4) return false;
  for (size_t i = 6; i + 4 < name.size(); ++i)
    if (name[i] < '0' || name[i] > '9') return false;
  return true;
}

}  // namespace

void refuse_overwriting_inputs(const fs::path& dest, const std::string& shown, const std::vector<InputFile>& inputs,
                               bool folder) {
  for (const InputFile& in : inputs) {
    std::error_code ec;
    if (in.path.empty() || !fs::exists(in.path, ec) || !fs::exists(dest, ec)) continue;
    if (fs::equivalent(dest, in.path, ec))
      throw InputError("-o " + shown + ": is the " + in.what + " input (" + in.path.string() +
                       "); refusing to write over an input, choose another output");
    if (folder && inside(in.path, dest))
      throw InputError("-o " + shown + ": holds the " + in.what + " input (" + in.path.string() +
                       "), which writing the sequence there would remove; choose another folder");
  }
}

fs::path SequenceFolder::destination(const std::string& shown) {
  fs::path p = shown.empty() ? fs::path(".") : fs::path(shown);
  // weakly_canonical follows links in the part that exists (the folder itself included)
  // and drops the trailing slash of "frames/".
  std::error_code ec;
  fs::path d = fs::weakly_canonical(fs::absolute(p), ec);
  if (ec) throw InputError("-o " + shown + ": " + ec.message());
  if (!d.has_filename()) d = d.parent_path();
  return d;
}

std::string SequenceFolder::frame_name(int index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", index);
  return name;
}

SequenceFolder::SequenceFolder(const fs::path& dest, const std::string& shown, bool overwrite)
    : dest_(dest), shown_(shown) {
  std::error_code ec;
  const auto st = fs::status(dest_, ec);
  if (fs::exists(st) && !fs::is_directory(st))
    throw InputError("-o " + shown + ": is a file, expected a folder for PNG frames");
  if (fs::is_directory(st) && !overwrite) {
    std::string foreign;
    size_t count = 0;
    for (auto& e : fs::directory_iterator(dest_, ec)) {
      const std::string name = e.path().filename().string();
      if (!is_frame_name(name) && foreign.empty()) foreign = name;
      ++count;
    }
    if (!foreign.empty())
      throw InputError(
          "-o " + shown + ": the folder is not empty (it holds " + foreign +
          (count > 1 ? " and " + std::to_string(count - 1) + " more" : std::string()) +
          "); add --overwrite to replace all of its contents with the new frames, or choose another folder");
  }
  fs::create_directories(dest_.parent_path(), ec);
  if (ec) throw InputError("-o " + shown + ": cannot create " + dest_.parent_path().string() + ": " + ec.message());
  tmp_ = temporary_path_beside(dest_);
  temporary_created(tmp_, true);
  if (!fs::create_directory(tmp_, ec) || ec) {
    temporary_gone(tmp_);
    throw InputError("-o " + shown +
                     ": cannot create a folder beside it: " + (ec ? ec.message() : std::string("it exists")));
  }
}

SequenceFolder::~SequenceFolder() {
  if (tmp_.empty()) return;
  std::error_code ec;
  fs::remove_all(tmp_, ec);
  temporary_gone(tmp_);
}

void SequenceFolder::publish() {
  std::error_code ec;
  if (!fs::exists(dest_, ec)) {
    fs::rename(tmp_, dest_, ec);
    if (ec) throw InputError("-o " + shown_ + ": cannot move the frames into place: " + ec.message());
    temporary_gone(tmp_);
    tmp_.clear();
    return;
  }
  // Swap the two folders in one step; tmp_ then holds the old contents, removed below.
  if (::renameat2(AT_FDCWD, tmp_.c_str(), AT_FDCWD, dest_.c_str(), RENAME_EXCHANGE) != 0) {
    if (errno != EINVAL && errno != ENOSYS && errno != ENOTSUP)
      throw InputError("-o " + shown_ + ": cannot move the frames into place: " + std::strerror(errno));
    // A file system without the exchange: move the old folder aside first.
    const fs::path old = temporary_path_beside(dest_);
    temporary_created(old, true);
    fs::rename(dest_, old, ec);
    if (!ec) {
      fs::rename(tmp_, dest_, ec);
      std::error_code back;
      if (ec) fs::rename(old, dest_, back);  // put the old folder back: nothing is lost
    }
    if (ec) {
      temporary_gone(old);
      throw InputError("-o " + shown_ + ": cannot move the frames into place: " + ec.message());
    }
    temporary_gone(tmp_);
    tmp_ = old;
  }
  // tmp_ (registered for cleanup) now holds the old frames; the destructor removes it.
  fs::remove_all(tmp_, ec);
  temporary_gone(tmp_);
  tmp_.clear();
}

}  // namespace draught::cli
