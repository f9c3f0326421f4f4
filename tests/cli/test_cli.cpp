// End-to-end tests of the `draught` CLI: the commands that should work.
#include "cli_helpers.hpp"

#include "core/io/image.hpp"
#include "core/params/params.hpp"

#include <set>

namespace draught_cli_test {
namespace {

std::string project_version() {
  const std::string cm = read_file(kSourceDir / "CMakeLists.txt");
  return first_group(cm, R"(project\s*\(\s*draught\s+VERSION\s+([0-9.]+))");
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// A rendered image: header checked, pixels decoded.
draught::Image load_png(const fs::path& p) { return draught::read_png(p); }

bool differ(const fs::path& a, const fs::path& b) { return read_file(a) != read_file(b); }

// ---------------------------------------------------------------- version and help

using Info = CliTest;

TEST_F(Info, VersionPrintsProjectVersion) {
  const std::string v = project_version();
  ASSERT_FALSE(v.empty()) << "no VERSION in CMakeLists.txt";
  auto r = draught({"--version"});
  EXPECT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_TRUE(contains(r.out, "draught " + v)) << r.describe();
}

TEST_F(Info, HelpListsSubcommands) {
  auto r = draught({"--help"});
  EXPECT_EQ(r.exit_code, 0) << r.describe();
  for (const char* s : {"render", "presets", "validate", "params", "--version", "--verbose"})
    EXPECT_TRUE(contains(r.out, s)) << "--help does not mention " << s << "\n" << r.describe();
}

TEST_F(Info, RenderHelpListsOptions) {
  auto r = draught({"render", "--help"});
  EXPECT_EQ(r.exit_code, 0) << r.describe();
  for (const char* s : {"--preset", "--glass", "--size", "--output", "--set", "--camera", "--debug", "--tonemap",
                        "--transparent", "--supersample", "--shader-dir", "depth", "normal", "material"})
    EXPECT_TRUE(contains(r.out, s)) << "render --help does not mention " << s << "\n" << r.describe();
}

TEST_F(Info, NoSubcommandIsAnError) {
  auto r = draught({});
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  EXPECT_TRUE(contains(r.err, "draught: error: expected a command: render, presets")) << r.describe();
}

TEST_F(Info, UnknownOptionIsAnError) {
  auto r = draught({"render", "--no-such-option", "-o", (out() / "x.png").string()});
  EXPECT_NE(r.exit_code, 0) << r.describe();
  EXPECT_TRUE(contains(r.err, "--no-such-option")) << r.describe();
  EXPECT_EQ(join(list_tree(out())), "");
}

// ---------------------------------------------------------------- render

using Render = CliTest;

TEST_F(Render, WritesPngOfExactSize) {
  const fs::path png = out() / "X.png";
  auto r = draught({"render", "--preset", "lager", "--glass", "pint", "--size", "48x32", "--supersample", "1", "-o",
                    png.string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_TRUE(contains(r.out, png.string())) << "does not say where the image is\n" << r.describe();
  PngInfo info = png_info(png);
  ASSERT_EQ(info.error, "");
  EXPECT_EQ(info.width, 48u);
  EXPECT_EQ(info.height, 32u);
  EXPECT_EQ(info.bit_depth, 8);
  EXPECT_EQ(info.color_type, 6) << "expected 8-bit RGBA";
  draught::Image img = load_png(png);
  ASSERT_EQ(img.width, 48);
  ASSERT_EQ(img.height, 32);
  std::set<std::vector<uint8_t>> colours;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) colours.insert({img.px(x, y), img.px(x, y) + 4});
  EXPECT_GT(colours.size(), 10u) << "the image is (nearly) flat: nothing was drawn";
  EXPECT_EQ(join(list_tree(out())), "X.png") << "stray files next to the image";
}

TEST_F(Render, DefaultSupersamplingKeepsExactSize) {
  for (auto [size, ss, w, h] : {std::tuple{"30x20", "", 30, 20}, std::tuple{"31x17", "3", 31, 17}}) {
    const fs::path png = out() / (std::string(size) + ".png");
    std::vector<std::string> args = {"render", "--size", size, "-o", png.string()};
    if (*ss) args.insert(args.end(), {"--supersample", ss});
    auto r = draught(args);
    ASSERT_EQ(r.exit_code, 0) << r.describe();
    PngInfo info = png_info(png);
    ASSERT_EQ(info.error, "");
    EXPECT_EQ(info.width, uint32_t(w)) << size << " supersample " << ss;
    EXPECT_EQ(info.height, uint32_t(h)) << size << " supersample " << ss;
  }
}

TEST_F(Render, CreatesMissingOutputFolders) {
  const fs::path png = out() / "a" / "b" / "x.png";
  auto r = render({"-o", png.string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(png_info(png).error, "");
}

TEST_F(Render, OverwritesExistingOutputWithoutLeftovers) {
  const fs::path png = out() / "x.png";
  write_file(png, "old contents");
  auto r = render({"-o", png.string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(png_info(png).error, "");
  EXPECT_EQ(join(list_tree(out())), "x.png");
}

TEST_F(Render, IsDeterministic) {
  const fs::path a = out() / "a.png", b = out() / "b.png";
  for (auto& p : {a, b}) {
    auto r = render({"--preset", "amber-ale", "--set", "liquid.fill=0.6", "-o", p.string()}, "40x40");
    ASSERT_EQ(r.exit_code, 0) << r.describe();
  }
  ASSERT_EQ(png_info(a).error, "");
  EXPECT_FALSE(differ(a, b)) << "the same command gave different bytes";
}

TEST_F(Render, SetChangesTheImage) {
  const fs::path base = out() / "base.png", set = out() / "set.png";
  auto r0 = render({"-o", base.string()}, "48x48");
  ASSERT_EQ(r0.exit_code, 0) << r0.describe();
  auto r1 = render({"--set", "liquid.fill=0.5", "--set", "glass.ior=1.52", "-o", set.string()}, "48x48");
  ASSERT_EQ(r1.exit_code, 0) << r1.describe();
  EXPECT_EQ(png_info(set).error, "");
  EXPECT_TRUE(differ(base, set)) << "--set liquid.fill=0.5 made no difference";
}

TEST_F(Render, AllSetTextFormsAreAccepted) {
  const fs::path png = out() / "x.png";
  auto r = render({"--set", "env.mode=constant", "--set", "env.color=0.5,0.5,0.6", "--set", "env.floor=off", "--set",
                   "render.max_events=8", "--set",
                   "glass.profile=0.03,0;0.035,0.05;0.04,0.1;0.043,0.14", "-o", png.string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(png_info(png).error, "");
}

TEST_F(Render, CameraChangesTheImage) {
  const fs::path base = out() / "base.png", cam = out() / "cam.png";
  auto r0 = render({"-o", base.string()});
  ASSERT_EQ(r0.exit_code, 0) << r0.describe();
  auto r1 = render({"--camera", "eye=0,0.1,0.4", "target=0,0.07,0", "vfov=30", "-o", cam.string()});
  ASSERT_EQ(r1.exit_code, 0) << r1.describe();
  EXPECT_EQ(png_info(cam).error, "");
  EXPECT_TRUE(differ(base, cam)) << "--camera made no difference";
  // Quoted as one word, as the help writes it: the same camera.
  const fs::path quoted = out() / "quoted.png";
  auto r2 = render({"--camera", "eye=0,0.1,0.4 target=0,0.07,0  vfov=30", "-o", quoted.string()});
  ASSERT_EQ(r2.exit_code, 0) << r2.describe();
  EXPECT_FALSE(differ(cam, quoted)) << "--camera quoted as one word is another camera";
}

TEST_F(Render, DebugViewsAreDistinctImages) {
  std::vector<fs::path> files = {out() / "beauty.png"};
  auto r = render({"-o", files[0].string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  for (const char* view : {"normal", "depth", "material"}) {
    files.push_back(out() / (std::string(view) + ".png"));
    auto rv = render({"--debug", view, "-o", files.back().string()});
    ASSERT_EQ(rv.exit_code, 0) << view << "\n" << rv.describe();
    PngInfo info = png_info(files.back());
    ASSERT_EQ(info.error, "") << view;
    EXPECT_EQ(info.width, 32u) << view;
    EXPECT_EQ(info.height, 32u) << view;
  }
  for (size_t i = 0; i < files.size(); ++i)
    for (size_t j = i + 1; j < files.size(); ++j)
      EXPECT_TRUE(differ(files[i], files[j])) << files[i].filename() << " == " << files[j].filename();
}

TEST_F(Render, TonemapNoneDiffersFromAces) {
  const fs::path aces = out() / "aces.png", none = out() / "none.png";
  auto r0 = render({"--tonemap", "aces", "-o", aces.string()});
  ASSERT_EQ(r0.exit_code, 0) << r0.describe();
  auto r1 = render({"--tonemap", "none", "-o", none.string()});
  ASSERT_EQ(r1.exit_code, 0) << r1.describe();
  EXPECT_EQ(png_info(none).error, "");
  EXPECT_TRUE(differ(aces, none)) << "--tonemap none made no difference";
}

TEST_F(Render, TransparentBackgroundHasZeroAlpha) {
  const fs::path opaque = out() / "opaque.png", clear = out() / "clear.png";
  auto r0 = render({"-o", opaque.string()});
  ASSERT_EQ(r0.exit_code, 0) << r0.describe();
  auto r1 = render({"--transparent", "-o", clear.string()});
  ASSERT_EQ(r1.exit_code, 0) << r1.describe();
  draught::Image o = load_png(opaque), c = load_png(clear);
  ASSERT_EQ(c.width, 32);
  // Without --transparent every pixel is opaque.
  for (int y = 0; y < o.height; ++y)
    for (int x = 0; x < o.width; ++x) ASSERT_EQ(o.px(x, y)[3], 255) << "opaque render, pixel " << x << "," << y;
  // With it, the corners (no glass there) are fully transparent, the glass is not.
  for (auto [x, y] : {std::pair{0, 0}, std::pair{31, 0}, std::pair{0, 31}, std::pair{31, 31}}) {
    EXPECT_EQ(c.px(x, y)[3], 0) << "corner " << x << "," << y;
    EXPECT_EQ(c.px(x, y)[0], 0) << "corner " << x << "," << y;
  }
  EXPECT_GT(c.px(16, 16)[3], 0) << "the glass in the middle is fully transparent";
  // The lager in the file is gold, as in the opaque picture: straight alpha (what a PNG
  // holds), its colour lit by the studio behind it. (It was nearly black: premultiplied
  // samples lit by the studio's dark ceiling, shown by every viewer as straight.)
  const std::uint8_t* lager = c.px(16, 18);
  EXPECT_GT(lager[3], 200) << "the drink lets most light through unchanged";
  EXPECT_GT(lager[0], 150) << "the lager is dark: " << int(lager[0]) << " " << int(lager[1]) << " " << int(lager[2]);
  EXPECT_GT(lager[0], lager[2] + 80) << "the lager is not gold";
  EXPECT_NEAR(lager[0], o.px(16, 18)[0], 30) << "the lager's red differs from the opaque picture's";
}

TEST_F(Render, VerboseSaysWhatWasUsed) {
  auto r = draught({"--verbose", "render", "--size", "16x16", "--supersample", "1", "--preset", "stout", "-o",
                    (out() / "x.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_TRUE(contains(r.err, "stout")) << r.describe();
  EXPECT_TRUE(contains(r.err, "nonic.json")) << "the drink's suggested glass\n" << r.describe();
  EXPECT_TRUE(contains(r.err, "renderer:")) << r.describe();
}

TEST_F(Render, EveryNamedPresetRenders) {
  auto list = draught({"presets"});
  ASSERT_EQ(list.exit_code, 0) << list.describe();
  int n = 0;
  for (auto& line : lines_of(list.out)) {
    std::istringstream ls(line);
    std::string kind, name;
    ls >> kind >> name;
    if (kind != "drink" && kind != "glass" && kind != "scene") continue;
    const fs::path png = out() / (kind + "-" + name + ".png");
    auto r = kind != "glass" ? render({"--preset", name, "-o", png.string()}, "16x16")
                             : render({"--glass", name, "-o", png.string()}, "16x16");
    EXPECT_EQ(r.exit_code, 0) << kind << " " << name << "\n" << r.describe();
    EXPECT_EQ(png_info(png).error, "");
    ++n;
  }
  EXPECT_GE(n, 10);
}

TEST_F(Render, PresetByPathAndFromPresetDir) {
  // A drink preset given as a file path.
  const fs::path file = in() / "mine.json";
  write_file(file, R"({ "draught_preset": 1, "kind": "drink", "name": "mine", "suggested_glass": "flute",
                        "params": { "liquid": { "fill": 0.4, "srm": 0, "absorption": [30, 5, 1] } } })");
  auto r = render({"--preset", file.string(), "-o", (out() / "a.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(png_info(out() / "a.png").error, "");

  // The same preset by name, found through $DRAUGHT_PRESET_DIR.
  const fs::path dir = in() / "presets";
  write_file(dir / "drinks" / "mine.json", read_file(file));
  auto r2 = render({"--preset", "mine", "-o", (out() / "b.png").string()}, "32x32",
                   {{"DRAUGHT_PRESET_DIR", dir.string()}});
  ASSERT_EQ(r2.exit_code, 0) << r2.describe();
  EXPECT_FALSE(differ(out() / "a.png", out() / "b.png")) << "by name and by path gave different images";
}

// ---------------------------------------------------------------- presets, params, validate

using Listing = CliTest;

TEST_F(Listing, PresetsListsGlassesAndDrinks) {
  auto r = draught({"presets"});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  std::set<std::string> glasses, drinks;
  for (auto& line : lines_of(r.out)) {
    std::istringstream ls(line);
    std::string kind, name;
    ls >> kind >> name;
    if (kind == "glass") glasses.insert(name);
    if (kind == "drink") drinks.insert(name);
  }
  EXPECT_GE(glasses.size(), 5u) << r.out;
  EXPECT_GE(drinks.size(), 5u) << r.out;
  EXPECT_TRUE(glasses.count("pint")) << r.out;
  EXPECT_TRUE(drinks.count("lager")) << r.out;
}

TEST_F(Listing, ParamsPrintsEveryParameter) {
  auto r = draught({"params"});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  std::map<std::string, std::string> rows;
  for (auto& line : lines_of(r.out)) rows[line.substr(0, line.find(' '))] = line;
  // A few rows spelled out, so the test does not only mirror the code.
  ASSERT_TRUE(rows.count("liquid.fill")) << r.out;
  EXPECT_TRUE(matches(rows["liquid.fill"], R"(float\s+0\.85\s+\[0, 0\.98\])"))
      << rows["liquid.fill"];
  ASSERT_TRUE(rows.count("glass.ior")) << r.out;
  EXPECT_TRUE(matches(rows["glass.ior"], R"(float\s+1\.52\s+\[1, 2\.5\])")) << rows["glass.ior"];
  ASSERT_TRUE(rows.count("glass.profile")) << r.out;
  EXPECT_TRUE(matches(rows["glass.profile"], R"(curve\s+0\.0295,0;.*\s+m\s)"))
      << rows["glass.profile"];
  ASSERT_TRUE(rows.count("glass.wall_thickness")) << r.out;
  EXPECT_TRUE(matches(rows["glass.wall_thickness"], R"(float\s+0\.003\s+\[0\.0005, 0\.02\]\s+m\s)"))
      << rows["glass.wall_thickness"];
  ASSERT_TRUE(rows.count("render.tonemap")) << r.out;
  EXPECT_TRUE(contains(rows["render.tonemap"], "none|aces")) << rows["render.tonemap"];

  // Every row of the table, with type, default, range and unit.
  for (const auto& d : draught::param_table()) {
    ASSERT_TRUE(rows.count(d.path)) << "`draught params` lacks " << d.path;
    const std::string& row = rows[d.path];
    EXPECT_TRUE(contains(row, " " + std::string(draught::type_name(d.type)) + " ")) << row;
    std::string def = draught::format_param(d, d.def);
    if (def.size() > 28) def = def.substr(0, 25);
    EXPECT_TRUE(contains(row, def)) << "default " << def << " missing: " << row;
    if (d.type != draught::ParamType::Bool && d.type != draught::ParamType::Enum &&
        d.type != draught::ParamType::File) {
      char range[64];
      std::snprintf(range, sizeof range, "[%g, %g]", double(d.min), double(d.max));
      EXPECT_TRUE(contains(row, range)) << "range " << range << " missing: " << row;
    }
    if (!d.unit.empty()) {
      EXPECT_TRUE(contains(row, " " + d.unit + " ")) << "unit " << d.unit << " missing: " << row;
    }
  }
}

TEST_F(Listing, ParamsMarkdown) {
  auto r = draught({"params", "--markdown"});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_TRUE(contains(r.out, "| parameter | type | default | range | unit |")) << r.out;
  EXPECT_TRUE(contains(r.out, "| `liquid.fill` | float | `0.85` | [0, 0.98] |")) << r.out;
  EXPECT_EQ(lines_of(r.out).size(), draught::param_table().size() + 2);
}

TEST_F(Listing, ValidateLager) {
  auto r = draught({"validate", (kSourceDir / "presets/drinks/lager.json").string()});
  EXPECT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_TRUE(contains(r.out, "lager.json: ok")) << r.describe();
  EXPECT_EQ(r.err, "");
}

TEST_F(Listing, EveryShippedPresetValidates) {
  std::vector<std::string> args = {"validate"};
  for (auto& e : fs::recursive_directory_iterator(kSourceDir / "presets"))
    if (e.path().extension() == ".json") args.push_back(e.path().string());
  ASSERT_GE(args.size(), 11u);
  auto r = draught(args);
  EXPECT_EQ(r.exit_code, 0) << r.describe();
  for (size_t i = 1; i < args.size(); ++i)
    EXPECT_TRUE(contains(r.out, args[i] + ": ok")) << args[i] << "\n" << r.describe();
  EXPECT_EQ(r.err, "");
}

}  // namespace
}  // namespace draught_cli_test
