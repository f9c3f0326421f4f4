// End-to-end tests of what the CLI writes (issue "Hardening"): nothing is left behind
// when a run is killed, temporaries of dead runs are swept, long names work, a PNG
// sequence arrives whole, inputs are never written over, links are followed, and GIFs
// stream through ffmpeg in passes that do not hold every frame.
#include "cli_helpers.hpp"

#include <chrono>
#include <csignal>
#include <dirent.h>

namespace draught_cli_test {
namespace {

// A run of draught in the background, to be interrupted.
struct Background {
  pid_t pid = -1;
  int wait_status = 0;
};

// sigint_ignored: started as under nohup or in a script's background, SIGINT ignored.
Background start_draught(const std::vector<std::string>& args, const fs::path& capture_dir,
                         bool sigint_ignored = false) {
  fs::create_directories(capture_dir);
  std::vector<std::string> argv_s = {kExe.string()};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env_s;
  for (char** e = environ; *e; ++e) {
    std::string entry = *e;
    if (!entry.starts_with("DRAUGHT_DEVICE=") && !entry.starts_with("DRAUGHT_PRESET_DIR=")) env_s.push_back(entry);
  }
  env_s.push_back("DRAUGHT_DEVICE=software");
  std::vector<char*> envp;
  for (auto& e : env_s) envp.push_back(e.data());
  envp.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 1, (capture_dir / "bg-stdout").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, 2, (capture_dir / "bg-stderr").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  // The signals the tests send start at their defaults in the child, as a foreground
  // shell gives them: a test binary started in the background by a script (or under
  // nohup) has SIGINT ignored, which draught keeps ignoring by design (cleanup.cpp).
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t defaults;
  sigemptyset(&defaults);
  for (int sig : {SIGINT, SIGTERM, SIGHUP})
    if (!(sigint_ignored && sig == SIGINT)) sigaddset(&defaults, sig);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF);
  struct sigaction ignore {}, before {};
  ignore.sa_handler = SIG_IGN;
  if (sigint_ignored) sigaction(SIGINT, &ignore, &before);  // (inherited by the child)
  Background b;
  if (posix_spawn(&b.pid, argv[0], &fa, &attr, argv.data(), envp.data()) != 0) b.pid = -1;
  if (sigint_ignored) sigaction(SIGINT, &before, nullptr);
  posix_spawnattr_destroy(&attr);
  posix_spawn_file_actions_destroy(&fa);
  return b;
}

// The processes whose parent is `pid` (read from /proc).
std::vector<pid_t> children_of(pid_t pid) {
  std::vector<pid_t> kids;
  for (auto& e : fs::directory_iterator("/proc")) {
    const std::string name = e.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::string stat = read_file(e.path() / "stat");
    const auto close = stat.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream rest(stat.substr(close + 2));
    char state;
    pid_t ppid = 0;
    rest >> state >> ppid;
    if (ppid == pid) kids.push_back(pid_t(std::stol(name)));
  }
  return kids;
}

// Alive and not a zombie.
bool running(pid_t pid) {
  const std::string stat = read_file(fs::path("/proc") / std::to_string(pid) / "stat");
  const auto close = stat.rfind(')');
  return close != std::string::npos && close + 2 < stat.size() && stat[close + 2] != 'Z' && stat[close + 2] != 'X';
}

// Polls until `pred` holds or `seconds` pass.
bool wait_until(const std::function<bool()>& pred, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (pred()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return pred();
}

// A dead process's PID (one we started and reaped).
pid_t dead_pid() {
  pid_t pid = 0;
  char arg0[] = "/bin/true";
  char* argv[] = {arg0, nullptr};
  posix_spawn(&pid, "/bin/true", nullptr, nullptr, argv, environ);
  waitpid(pid, nullptr, 0);
  return pid;
}

class Outputs : public CliTest {
 protected:
  // A long animation (1800 frames at 32x32) that is still running when interrupted. No
  // floor: a tipping glass retraces its floor map every frame, and these tests are about
  // being interrupted, not about the floor (under a loaded CI the first frames came late).
  Background start_long(const std::string& output) {
    return start_draught({"render", "--timeline", "gentle-tilt", "--size", "32x32", "--supersample", "1", "--fps", "30",
                          "--duration", "60", "--set", "env.floor=false", "-o", output},
                         dir_ / "cap");
  }
  // Names in out/ (not below) that are draught's temporaries.
  std::vector<std::string> temporaries() const {
    std::vector<std::string> t;
    for (auto& n : list_tree(out()))
      if (n.find(".draught-tmp-") != std::string::npos) t.push_back(n);
    return t;
  }
  // Starts a long run to `output`, waits until `ready` holds (writing is under way),
  // sends `sig`, and checks that draught died of it and its ffmpeg (if any) with it.
  void interrupt(const std::string& output, int sig, const std::function<bool()>& ready, bool with_ffmpeg) {
    Background b = start_long(output);
    ASSERT_GT(b.pid, 0);
    const bool started = wait_until(ready, 60);
    const std::vector<pid_t> kids = children_of(b.pid);
    EXPECT_EQ(kids.size(), with_ffmpeg ? 1u : 0u) << "ffmpeg is not (or unexpectedly) running";
    kill(b.pid, sig);
    waitpid(b.pid, &b.wait_status, 0);
    ASSERT_TRUE(started) << "the run never started writing\n" << read_file(dir_ / "cap" / "bg-stderr");
    EXPECT_TRUE(WIFSIGNALED(b.wait_status) && WTERMSIG(b.wait_status) == sig)
        << "did not die of signal " << sig << " (status " << b.wait_status << ")\n"
        << read_file(dir_ / "cap" / "bg-stderr");
    for (pid_t k : kids)
      EXPECT_TRUE(wait_until([&] { return !running(k); }, 5)) << "child " << k << " outlived draught";
  }
};

// ---------------------------------------------------------------- 11. killed runs leave nothing

TEST_F(Outputs, SigtermDuringMp4LeavesNothingAndEndsFfmpeg) {
  interrupt((out() / "clip.mp4").string(), SIGTERM,
            [&] {
              auto t = temporaries();
              return !t.empty() && fs::file_size(out() / t.front()) > 0;
            },
            true);
  EXPECT_EQ(join(list_tree(out())), "") << "a temporary or a partial video was left";
}

TEST_F(Outputs, SigintDuringGifLeavesNothing) {
  interrupt((out() / "clip.gif").string(), SIGINT,
            [&] {
              auto t = temporaries();
              return !t.empty() &&
                     std::any_of(t.begin(), t.end(), [&](auto& n) { return fs::file_size(out() / n) > 0; });
            },
            true);
  EXPECT_EQ(join(list_tree(out())), "");
}

TEST_F(Outputs, StartedWithSigintIgnoredItKeepsIgnoringIt) {
  // As under nohup: an interrupt meant for the shell's foreground leaves the run alone; it
  // finishes its GIF and leaves no temporary.
  Background b = start_draught({"render", "--timeline", "gentle-tilt", "--size", "32x32", "--supersample", "1", "--fps",
                                "30", "--duration", "2", "--set", "env.floor=false", "-o", (out() / "clip.gif").string()},
                               dir_ / "cap", true);
  ASSERT_GT(b.pid, 0);
  const bool started = wait_until([&] { return !temporaries().empty(); }, 60);
  kill(b.pid, SIGINT);
  waitpid(b.pid, &b.wait_status, 0);
  ASSERT_TRUE(started) << read_file(dir_ / "cap" / "bg-stderr");
  EXPECT_TRUE(WIFEXITED(b.wait_status) && WEXITSTATUS(b.wait_status) == 0)
      << "status " << b.wait_status << "\n" << read_file(dir_ / "cap" / "bg-stderr");
  EXPECT_EQ(join(list_tree(out())), "clip.gif");
}

TEST_F(Outputs, SigtermDuringPngSequenceKeepsTheOldOneAndLeavesNoHalfSequence) {
  write_file(out() / "seq" / "frame_00000.png", "older run");
  interrupt((out() / "seq").string() + "/", SIGTERM,
            [&] {
              for (auto& t : temporaries())
                if (list_tree(out() / t).size() >= 3) return true;  // a few frames written
              return false;
            },
            false);
  EXPECT_EQ(join(list_tree(out())), "seq, seq/frame_00000.png") << "half a sequence or a temporary folder was left";
  EXPECT_EQ(read_file(out() / "seq" / "frame_00000.png"), "older run");
}

TEST_F(Outputs, SigkilledRunIsSweptByTheNextOneAndItsFfmpegDies) {
  Background b = start_long((out() / "clip.mp4").string());
  ASSERT_GT(b.pid, 0);
  ASSERT_TRUE(wait_until([&] { return !temporaries().empty() && !children_of(b.pid).empty(); }, 60));
  const std::vector<pid_t> kids = children_of(b.pid);
  kill(b.pid, SIGKILL);
  waitpid(b.pid, nullptr, 0);
  for (pid_t k : kids)
    EXPECT_TRUE(wait_until([&] { return !running(k); }, 5)) << "ffmpeg " << k << " kept running after SIGKILL";
  ASSERT_FALSE(temporaries().empty()) << "SIGKILL cannot be handled: a temporary stays until the next run";
  // The next run into the same folder removes it (its owner is dead), and only it.
  const std::string live = ".draught-tmp-" + std::to_string(getpid()) + "-0-000000";  // our PID: alive
  write_file(out() / live, "in use");
  write_file(out() / ("old.png.tmp-" + std::to_string(dead_pid())), "stale, older name");
  write_file(out() / "notes.tmp-1", "a user's file");
  auto r = render({"-o", (out() / "x.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(join(list_tree(out())), join({live, "notes.tmp-1", "x.png"}));
}

TEST_F(Outputs, LegacyPartOfTheSameVideoIsSweptWhenStale) {
  // Older versions wrote "X.mp4.part" / "X.gif.part", with no PID to tell whether their
  // writer is alive. A run writing X removes X's own part when nothing wrote it for ten
  // minutes; a fresh one (a run may still be encoding it) and parts of other names (a
  // browser's download) stay.
  namespace chr = std::chrono;
  const auto hour_ago = fs::file_time_type::clock::now() - chr::hours(1);
  for (const char* name : {"clip.mp4.part", "anim.gif.part", "other.mp4.part"}) {
    write_file(out() / name, "half a video from an older version");
    fs::last_write_time(out() / name, hour_ago);
  }
  write_file(out() / "fresh.mp4.part", "being written right now");
  for (const char* video : {"clip.mp4", "anim.gif", "fresh.mp4"}) {
    auto r = draught({"render", "--timeline", "gentle-tilt", "--size", "16x16", "--supersample", "1", "--fps", "4",
                      "--duration", "0.5", "-o", (out() / video).string()});
    ASSERT_EQ(r.exit_code, 0) << r.describe();
  }
  EXPECT_EQ(join(list_tree(out())), join({"anim.gif", "clip.mp4", "fresh.mp4", "fresh.mp4.part", "other.mp4.part"}));
}

TEST_F(Outputs, OutputNameOf249CharactersWorks) {
  // The temporary suffix used to push such names past NAME_MAX (255).
  const std::string stem(245, 'n');
  auto r = render({"-o", (out() / (stem + ".png")).string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(png_info(out() / (stem + ".png")).error, "");
  for (const char* ext : {".mp4", ".gif"}) {
    auto v = draught({"render", "--timeline", "gentle-tilt", "--size", "16x16", "--supersample", "1", "--fps", "4",
                      "--duration", "0.5", "-o", (out() / (stem + ext)).string()});
    ASSERT_EQ(v.exit_code, 0) << v.describe();
  }
  EXPECT_EQ(join(list_tree(out())), join({stem + ".gif", stem + ".mp4", stem + ".png"}));
}

// ---------------------------------------------------------------- 12. sequences arrive whole

class Sequence : public Outputs {
 protected:
  RunResult frames(const std::string& dir, double duration, std::vector<std::string> extra = {}) {
    std::vector<std::string> a = {"render",
                                  "--timeline",
                                  "gentle-tilt",
                                  "--size",
                                  "16x16",
                                  "--supersample",
                                  "1",
                                  "--fps",
                                  "4",
                                  "--duration",
                                  std::to_string(duration),
                                  "-o",
                                  dir};
    a.insert(a.end(), extra.begin(), extra.end());
    return draught(a);
  }
};

TEST_F(Sequence, NonEmptyFolderIsRefusedWithoutOverwrite) {
  write_file(out() / "seq" / "notes.txt", "keep me");
  auto r = frames((out() / "seq").string() + "/", 1);
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  EXPECT_TRUE(contains(r.err, "the folder is not empty (it holds notes.txt)")) << r.describe();
  EXPECT_TRUE(contains(r.err, "--overwrite")) << r.describe();
  EXPECT_EQ(join(list_tree(out())), "seq, seq/notes.txt");
  EXPECT_EQ(read_file(out() / "seq" / "notes.txt"), "keep me");
}

TEST_F(Sequence, OverwriteReplacesTheWholeFolder) {
  write_file(out() / "seq" / "notes.txt", "old");
  write_file(out() / "seq" / "sub" / "deep.txt", "old");
  auto r = frames((out() / "seq").string(), 0.5, {"--overwrite"});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(join(list_tree(out())), "seq, seq/frame_00000.png, seq/frame_00001.png");
}

TEST_F(Sequence, AnOlderSequenceIsReplacedNotMixedIn) {
  ASSERT_EQ(frames((out() / "seq").string() + "/", 1.5).exit_code, 0);  // 6 frames
  ASSERT_EQ(join(list_tree(out() / "seq")).size(), std::string("frame_00000.png, ").size() * 6 - 2);
  auto r = frames((out() / "seq").string() + "/", 0.5);  // 2 frames, no --overwrite needed
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(join(list_tree(out())), "seq, seq/frame_00000.png, seq/frame_00001.png")
      << "frames of the older run remain";
}

TEST_F(Sequence, AFileWhereTheFolderShouldBe) {
  write_file(out() / "seq", "a file");
  auto r = frames((out() / "seq").string() + "/", 0.5);
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  EXPECT_TRUE(contains(r.err, "is a file, expected a folder for PNG frames")) << r.describe();
  EXPECT_EQ(read_file(out() / "seq"), "a file");
}

// ---------------------------------------------------------------- 13. inputs and links

TEST_F(Outputs, RefusesToWriteOverThePresetItReads) {
  // A valid preset that happens to be called x.png.
  const fs::path preset = in() / "x.png";
  const std::string text =
      R"({ "draught_preset": 1, "kind": "drink", "name": "p", "params": { "liquid": { "fill": 0.5 } } })";
  write_file(preset, text);
  auto r = render({"--preset", preset.string(), "-o", preset.string()});
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  EXPECT_TRUE(contains(r.err, "-o " + preset.string() + ": is the --preset input")) << r.describe();
  EXPECT_EQ(read_file(preset), text) << "the input was replaced";
  // Through a link it is the same file.
  fs::create_symlink(preset, out() / "link.png");
  auto l = render({"--preset", preset.string(), "-o", (out() / "link.png").string()});
  EXPECT_EQ(l.exit_code, 1) << l.describe();
  EXPECT_TRUE(contains(l.err, "is the --preset input")) << l.describe();
  EXPECT_EQ(read_file(preset), text);
}

TEST_F(Outputs, RefusesASequenceFolderThatHoldsTheTimeline) {
  write_file(in() / "t.json", R"({ "draught_timeline": 1, "duration": 0.5, "actions": [] })");
  auto r = draught({"render", "--timeline", (in() / "t.json").string(), "--size", "16x16", "--fps", "4", "-o",
                    in().string() + "/", "--overwrite"});
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  EXPECT_TRUE(contains(r.err, "holds the --timeline input")) << r.describe();
  EXPECT_TRUE(fs::exists(in() / "t.json"));
}

TEST_F(Outputs, SymbolicLinksAreFollowed) {
  write_file(out() / "real.png", "old");
  fs::create_symlink("real.png", out() / "link.png");
  auto r = render({"-o", (out() / "link.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_TRUE(fs::is_symlink(out() / "link.png")) << "the link was replaced by a file";
  EXPECT_EQ(png_info(out() / "real.png").error, "") << "the link's target did not get the picture";
  EXPECT_TRUE(contains(r.out, "through the symbolic link, to " + (out() / "real.png").string())) << r.describe();
  // A folder link for a sequence: the folder it points to gets the frames.
  fs::create_directories(out() / "frames-real");
  fs::create_symlink("frames-real", out() / "frames");
  auto s = draught({"render", "--timeline", "gentle-tilt", "--size", "16x16", "--supersample", "1", "--fps", "4",
                    "--duration", "0.5", "-o", (out() / "frames").string() + "/"});
  ASSERT_EQ(s.exit_code, 0) << s.describe();
  EXPECT_TRUE(fs::is_symlink(out() / "frames"));
  EXPECT_EQ(join(list_tree(out() / "frames-real")), "frame_00000.png, frame_00001.png");
  EXPECT_TRUE(contains(s.out, "through the symbolic link")) << s.describe();
}

// ---------------------------------------------------------------- 6. GIF in passes

TEST_F(Outputs, GifIsEncodedInPassesOverALosslessTemporary) {
  // An ffmpeg that logs its arguments, then runs the real one.
  const fs::path log = in() / "ffmpeg.log", wrapper = in() / "ffmpeg";
  write_file(wrapper, "#!/bin/sh\necho \"$*\" >> '" + log.string() + "'\nexec ffmpeg \"$@\"\n");
  fs::permissions(wrapper, fs::perms::owner_all);
  auto r = draught({"render", "--timeline", "gentle-tilt", "--size", "24x24", "--supersample", "1", "--fps", "8",
                    "--duration", "1", "-o", (out() / "clip.gif").string()},
                   {{"DRAUGHT_FFMPEG", wrapper.string()}});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(read_file(out() / "clip.gif").substr(0, 6), "GIF89a");
  EXPECT_EQ(join(list_tree(out())), "clip.gif") << "temporaries left";
  std::vector<std::string> runs;
  std::istringstream lines(read_file(log));
  for (std::string line; std::getline(lines, line);) runs.push_back(line);
  ASSERT_EQ(runs.size(), 3u) << read_file(log);
  EXPECT_TRUE(contains(runs[0], "-i - -c:v ffv1 -f nut")) << "pass 1 does not stream to a lossless file: " << runs[0];
  EXPECT_TRUE(contains(runs[1], "palettegen")) << runs[1];
  EXPECT_TRUE(contains(runs[2], "paletteuse") && contains(runs[2], "-f gif")) << runs[2];
  // The one-pass graph that held every frame in memory is gone.
  EXPECT_FALSE(contains(read_file(log), "split")) << read_file(log);
}

}  // namespace
}  // namespace draught_cli_test
