// Where the CLI writes, and what it refuses to write over:
//  - an output that is one of the run's inputs (a preset, a timeline, a shader folder),
//    or, for a PNG sequence, a folder that holds one: refused, nothing is rendered;
//  - a symbolic link: followed. The file (or folder) it points to gets the new content
//    and the link stays a link, as with a shell's `>`;
//  - a PNG sequence is written into a temporary folder beside its destination and moved
//    into place whole when the last frame is written, so a failed or killed run leaves
//    no half sequence and an older run's frames never mix in. A destination folder that
//    holds anything but an earlier sequence (frame_NNNNN.png) is replaced only with
//    --overwrite.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace draught::cli {

struct InputFile {
  std::string what;  // "--preset", "the timeline's preset", ...
  std::filesystem::path path;
};

// Throws InputError when writing `dest` (given as `shown`) would replace one of `inputs`:
// the same file, or, when `dest` is a folder that is replaced whole, anything in it.
void refuse_overwriting_inputs(const std::filesystem::path& dest, const std::string& shown,
                               const std::vector<InputFile>& inputs, bool folder);

// A PNG sequence on its way to `dest`.
class SequenceFolder {
 public:
  // Checks that `dest` may be replaced (see above) and creates the temporary folder.
  SequenceFolder(const std::filesystem::path& dest, const std::string& shown, bool overwrite);
  ~SequenceFolder();  // removes the temporary folder unless it was published
  SequenceFolder(const SequenceFolder&) = delete;
  SequenceFolder& operator=(const SequenceFolder&) = delete;

  const std::filesystem::path& folder() const { return tmp_; }  // where the frames go
  // Moves the finished sequence into place: renamed onto a missing destination, else
  // swapped with the old folder in one step (renameat2 RENAME_EXCHANGE), which is then
  // removed.
  void publish();

  // The destination of a sequence given as -o: links followed, no trailing slash.
  static std::filesystem::path destination(const std::string& shown);
  // frame_00042.png
  static std::string frame_name(int index);

 private:
  std::filesystem::path dest_, tmp_;
  std::string shown_;
};

}  // namespace draught::cli
