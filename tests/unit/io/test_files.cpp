// Reading text inputs (regular files only, size-capped) and atomic writes (short
// temporary names, links followed, nothing left behind).
#include "core/io/files.hpp"
#include "core/io/temporaries.hpp"

#include "test_common.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <future>
#include <sys/stat.h>
#include <unistd.h>

namespace draught {
namespace {

namespace fs = std::filesystem;
using test::input_error_of;

class Files : public test::TempDirTest {
 protected:
  Files() : TempDirTest("draught-files") {}
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
};

bool has(const std::string& s, const std::string& needle) { return s.find(needle) != std::string::npos; }

TEST_F(Files, ReadsARegularFile) {
  std::ofstream(dir_ / "a.json") << "{ \"x\": 1 }";
  EXPECT_EQ(read_text_file(dir_ / "a.json"), "{ \"x\": 1 }");
  std::ofstream(dir_ / "empty.json");
  EXPECT_EQ(read_text_file(dir_ / "empty.json"), "");
}

TEST_F(Files, RefusesWhatIsNotARegularFile) {
  const std::string d = input_error_of([&] { read_text_file(dir_); });
  EXPECT_TRUE(has(d, dir_.string() + ": is a directory, expected a regular file")) << d;
  const std::string z = input_error_of([] { read_text_file("/dev/zero"); });
  EXPECT_TRUE(has(z, "/dev/zero: is a character device, expected a regular file")) << z;
  const std::string m = input_error_of([&] { read_text_file(dir_ / "missing.json"); });
  EXPECT_TRUE(has(m, "missing.json: cannot open file")) << m;
}

TEST_F(Files, RefusesAFifoWithoutWaitingForAWriter) {
  const fs::path fifo = dir_ / "pipe.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // If the read blocked, the future would not be ready; the test then fails (and the
  // stuck reader is released by opening the FIFO for writing).
  auto f = std::async(std::launch::async, [&] { return input_error_of([&] { read_text_file(fifo); }); });
  if (f.wait_for(std::chrono::seconds(5)) != std::future_status::ready) {
    std::ofstream(fifo) << "x";
    FAIL() << "reading a FIFO blocked";
  }
  const std::string e = f.get();
  EXPECT_TRUE(has(e, fifo.string() + ": is a FIFO (named pipe), expected a regular file")) << e;
}

TEST_F(Files, RefusesFilesOverTheSizeLimit) {
  const fs::path big = dir_ / "big.json";
  { std::ofstream(big) << "{}"; }
  fs::resize_file(big, kMaxTextFileBytes + 1);  // sparse: costs no disk
  const std::string e = input_error_of([&] { read_text_file(big); });
  EXPECT_TRUE(has(e, big.string() + ": 16.0 MiB, larger than the limit of 16 MiB")) << e;
  fs::resize_file(big, kMaxTextFileBytes);  // exactly the limit is fine
  EXPECT_EQ(read_text_file(big).size(), kMaxTextFileBytes);
}

TEST_F(Files, TemporaryNamesAreShortAndCarryThePid) {
  const std::string long_name(249, 'n');
  const fs::path t = temporary_path_beside(dir_ / (long_name + ".png"));
  EXPECT_EQ(t.parent_path(), dir_);
  EXPECT_LE(t.filename().string().size(), 40u) << t;
  EXPECT_EQ(temporary_owner(t.filename().string()), long(::getpid()));
  EXPECT_NE(temporary_path_beside(dir_ / "a.png"), temporary_path_beside(dir_ / "a.png"));
}

TEST_F(Files, TemporaryOwnerOfOldAndNewNames) {
  EXPECT_EQ(temporary_owner(".draught-tmp-4242-0-abcdef"), 4242);
  EXPECT_EQ(temporary_owner("frame.png.tmp-977"), 977);  // as written by older versions
  EXPECT_EQ(temporary_owner("drink.json.tmp-31"), 31);
  EXPECT_EQ(temporary_owner("notes.tmp-2024"), std::nullopt);  // a user's file, not ours
  EXPECT_EQ(temporary_owner("x.png"), std::nullopt);
  EXPECT_EQ(temporary_owner(".draught-tmp-abc-0"), std::nullopt);
  EXPECT_EQ(temporary_owner("x.png.tmp-"), std::nullopt);
  EXPECT_EQ(temporary_owner("x.png.tmp-12a"), std::nullopt);
}

TEST_F(Files, AtomicWriteWithANameOfNameMaxLength) {
  // 255 bytes, the most a file name may have: the temporary beside it must still fit.
  const fs::path p = dir_ / (std::string(251, 'n') + ".png");
  write_file_atomic(p, "data");
  EXPECT_EQ(read_text_file(p), "data");
  EXPECT_EQ(listing(), std::vector<std::string>{p.filename().string()}) << "a temporary was left";
}

TEST_F(Files, AtomicWriteFollowsSymbolicLinks) {
  std::ofstream(dir_ / "target.png") << "old";
  fs::create_symlink("target.png", dir_ / "link.png");  // relative, as ln -s makes them
  EXPECT_EQ(write_destination(dir_ / "link.png"), dir_ / "target.png");
  write_file_atomic(dir_ / "link.png", "new");
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.png")) << "the link was replaced by a file";
  EXPECT_EQ(read_text_file(dir_ / "target.png"), "new");
  // A dangling link: its target is created.
  fs::create_symlink(dir_ / "sub-missing.png", dir_ / "dangling.png");
  write_file_atomic(dir_ / "dangling.png", "made");
  EXPECT_TRUE(fs::is_symlink(dir_ / "dangling.png"));
  EXPECT_EQ(read_text_file(dir_ / "sub-missing.png"), "made");
  // A loop of links is an error, not a hang.
  fs::create_symlink("loop-b", dir_ / "loop-a");
  fs::create_symlink("loop-a", dir_ / "loop-b");
  EXPECT_TRUE(
      has(input_error_of([&] { write_file_atomic(dir_ / "loop-a", "x"); }), "too many levels of symbolic links"));
}

TEST_F(Files, FailedWriteLeavesNothingAndTellsTheObserver) {
  static std::vector<std::string> created, gone;
  created.clear();
  gone.clear();
  set_temporary_observer({[](const fs::path& p, bool) { created.push_back(p.string()); },
                          [](const fs::path& p) { gone.push_back(p.string()); }});
  fs::create_directories(dir_ / "taken.png");  // a folder where the file should go
  const std::string e = input_error_of([&] { write_file_atomic(dir_ / "taken.png", "x"); });
  write_file_atomic(dir_ / "ok.png", "y");
  set_temporary_observer({});
  EXPECT_TRUE(has(e, "taken.png: cannot write")) << e;
  EXPECT_EQ(listing(), (std::vector<std::string>{"ok.png", "taken.png"}));
  ASSERT_EQ(created.size(), 2u);
  EXPECT_EQ(created, gone) << "every temporary announced is also reported gone";
}

}  // namespace
}  // namespace draught
