// A deterministic mutation fuzzer for the preset loader: every shipped preset, mutated
// thousands of times (flipped, deleted, duplicated and inserted bytes, JSON punctuation,
// extreme numbers); scenes with objects are also resolved (glasses, drinks, footprints).
// The loader must either accept a fully valid preset or throw InputError; any other
// exception, a crash or (under the sanitizer build in scripts/test.sh) a memory error fails.
#include "core/io/files.hpp"
#include "test_common.hpp"

#include <gtest/gtest.h>

#include <random>

namespace draught::test {
namespace {

std::string mutate(std::string s, std::mt19937& rng) {
  static const char* tokens[] = {"{", "}", "[", "]", ",", ":", "\"", "1e999", "-0", "null", "true",
                                 "\"x\"", "[[0,0]]", "1e-320", "9007199254740993", "\\u0000", "nan"};
  const int edits = 1 + int(rng() % 4);
  for (int e = 0; e < edits && !s.empty(); ++e) {
    const size_t at = rng() % s.size();
    switch (rng() % 5) {
      case 0: s[at] = char(rng() % 256); break;
      case 1: s.erase(at, 1 + rng() % 8); break;
      case 2: {  // (drawn in this order: compilers take a call's arguments in either)
        const size_t length = 1 + rng() % 16, from = rng() % s.size();
        s.insert(at, s.substr(from, length));
        break;
      }
      case 3: s.insert(at, tokens[rng() % std::size(tokens)]); break;
      case 4: s.resize(at); break;
    }
  }
  return s;
}

TEST(PresetFuzz, MutatedPresetsAreAcceptedWholeOrRejectedWithInputError) {
  std::mt19937 rng(20261121);
  int accepted = 0, rejected = 0;
  for (const char* sub : {"glasses", "drinks", "scenes"}) {
    for (auto& entry : std::filesystem::directory_iterator(preset_source_dir() / sub)) {
      const std::string text = read_text_file(entry.path());
      for (int i = 0; i < 400; ++i) {
        const std::string m = mutate(text, rng);
        try {
          Preset p = parse_preset(m, "fuzz.json");
          Params params = default_params();
          apply_preset(p, params);  // every accepted value passed validation
          for (auto& [d, v] : p.values) EXPECT_NO_THROW(validate_value(*d, v));
          // A scene with objects: its glasses, drinks and footprints are checked too.
          if (!p.objects.empty()) {
            const Scene scene = scene_from_preset(p);
            EXPECT_EQ(scene.objects.size(), p.objects.size());
          }
          ++accepted;
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("fuzz.json"), std::string::npos) << e.what() << "\non input:\n" << m;
          ++rejected;
        } catch (const std::exception& e) {
          ADD_FAILURE() << "unexpected " << typeid(e).name() << ": " << e.what() << "\non input:\n" << m;
        }
      }
    }
  }
  std::printf("fuzzed presets: %d accepted, %d rejected with a clear error\n", accepted, rejected);
  EXPECT_GT(rejected, 1000);
}

}  // namespace
}  // namespace draught::test
