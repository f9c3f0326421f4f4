// Checks a draught-viewer screenshot:
//   check_screenshot FILE WIDTH HEIGHT glass         the size, not blank, a beer-coloured
//                                                    glass in the middle unlike the corners
//   check_screenshot FILE WIDTH HEIGHT panel OTHER   the size, and the left part (where the
//                                                    panel sits) clearly differs from OTHER,
//                                                    the same scene without the panel
//   check_screenshot FILE WIDTH HEIGHT scene PRESET  the size, not blank, and every object of
//                                                    the preset's scene drawn where the
//                                                    reference intersector sees it
//   check_screenshot FILE WIDTH HEIGHT uncovered PRESET LAYOUT
//                                                    the same, framed as the viewer's LAYOUT
//                                                    lines say (its stdout: where the panel,
//                                                    the overlay and the scene are), and no
//                                                    pixel of any glass under the panel or the
//                                                    overlay, which are really drawn there
// Prints what it measured; exits 1 naming the check that failed.
#include "core/io/image.hpp"
#include "core/params/preset.hpp"
#include "core/scene/frame.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using draught::Image;

namespace {

struct Region {
  int x0, y0, x1, y1;  // pixels, [x0, x1) x [y0, y1)
  bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
  bool overlaps(const Region& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

std::string str(const Region& r) {
  return "[" + std::to_string(r.x0) + ", " + std::to_string(r.x1) + ") x [" + std::to_string(r.y0) + ", " +
         std::to_string(r.y1) + ")";
}

// The viewer's "layout NAME X0 Y0 X1 Y1" lines (pixels, fractional).
struct Box {
  double x0, y0, x1, y1;
  Region pixels() const {  // every pixel it touches
    return {int(std::floor(x0)), int(std::floor(y0)), int(std::ceil(x1)), int(std::ceil(y1))};
  }
};

std::map<std::string, Box> read_layout(const std::string& file) {
  std::ifstream in(file);
  std::map<std::string, Box> out;
  std::string line, word, name;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    Box b;
    if (ls >> word >> name >> b.x0 >> b.y0 >> b.x1 >> b.y1 && word == "layout") out[name] = b;
  }
  return out;
}

Region fraction(const Image& img, double fx0, double fy0, double fx1, double fy1) {
  return {int(fx0 * img.width), int(fy0 * img.height), int(fx1 * img.width), int(fy1 * img.height)};
}

struct Mean {
  double r = 0, g = 0, b = 0;
};

Mean mean(const Image& img, Region r) {
  Mean m;
  double n = 0;
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x, ++n) {
      m.r += img.px(x, y)[0];
      m.g += img.px(x, y)[1];
      m.b += img.px(x, y)[2];
    }
  return {m.r / n, m.g / n, m.b / n};
}

double distance(Mean a, Mean b) { return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b); }

// Lager through glass: clearly more red than blue, green in between, not dark.
bool beer_coloured(const std::uint8_t* p) {
  const int r = p[0], g = p[1], b = p[2];
  return r >= 90 && r > b + 40 && g > b + 15 && r >= g;
}

int fail(const std::string& what) {
  std::fprintf(stderr, "check_screenshot: FAIL: %s\n", what.c_str());
  return 1;
}

// Every object of the scene drawn: where the reference intersector sees object i (its pixels
// in the lower half, below the overlay in the top right; or, given where the panel and the
// overlay are, the lower half of its silhouette), the picture's mean colour must stand apart
// from the floor and backdrop beside it. An object the renderer left out shows what lies
// behind it, like its neighbourhood. With `covers`, also no object's pixel lies under one.
int check_scene(const Image& img, const std::string& preset, draught::PictureRect view = {},
                const std::vector<Region>* covers = nullptr) {
  draught::SceneRequest req;
  req.preset = preset;
  const draught::Scene scene = draught::resolve_scene_objects(req);
  draught::FrameState frame = draught::make_frame(scene);
  frame.view = view;
  const int step = 2, top = covers ? 0 : img.height / 2;  // every other pixel: enough, and quick
  std::vector<int> object(std::size_t(img.width) * std::size_t(img.height), -2);
  for (int y = top; y < img.height; y += step)
    for (int x = 0; x < img.width; x += step)
      object[std::size_t(y) * img.width + x] = draught::pick_object(frame, x + 0.5, y + 0.5, img.width, img.height);
  if (covers) {
    // The whole silhouette of every glass, then none of it under the panel or the overlay.
    Region all{img.width, img.height, 0, 0};
    for (int y = 0; y < img.height; y += step)
      for (int x = 0; x < img.width; x += step)
        if (object[std::size_t(y) * img.width + x] >= 0)
          all = {std::min(all.x0, x), std::min(all.y0, y), std::max(all.x1, x + 1), std::max(all.y1, y + 1)};
    std::printf("the glasses lie in %s\n", str(all).c_str());
    if (all.x1 <= all.x0) return fail("no glass in the picture");
    for (int y = 0; y < img.height; y += step)
      for (int x = 0; x < img.width; x += step) {
        int& o = object[std::size_t(y) * img.width + x];
        for (const Region& c : *covers)
          if (c.contains(x, y)) {
            if (o >= 0)
              return fail("glass " + std::to_string(o) + " is under the panel or the overlay " + str(c) + " at " +
                          std::to_string(x) + ", " + std::to_string(y));
            o = -2;  // judged neither as floor nor as glass below
          }
      }
    // Each glass is judged by the lower half of its silhouette, where its drink is (the
    // rim, the head and the empty glass above look much like the studio behind them).
    for (int i = 0; i < int(frame.vessels.size()); ++i) {
      int y0 = img.height, y1 = 0;
      for (int y = 0; y < img.height; y += step)
        for (int x = 0; x < img.width; x += step)
          if (object[std::size_t(y) * img.width + x] == i) y0 = std::min(y0, y), y1 = std::max(y1, y);
      for (int y = 0; y < (y0 + y1) / 2; y += step)
        for (int x = 0; x < img.width; x += step)
          if (object[std::size_t(y) * img.width + x] == i) object[std::size_t(y) * img.width + x] = -2;
    }
  }
  std::printf("%s: %zu objects\n", preset.c_str(), frame.vessels.size());
  if (frame.vessels.size() != scene.objects.size()) return fail("the frame does not hold every object");
  for (int i = 0; i < int(frame.vessels.size()); ++i) {
    Region box{img.width, img.height, 0, 0};
    Mean in;
    int n = 0;
    for (int y = top; y < img.height; y += step)
      for (int x = 0; x < img.width; x += step)
        if (object[std::size_t(y) * img.width + x] == i) {
          box = {std::min(box.x0, x), std::min(box.y0, y), std::max(box.x1, x + 1), std::max(box.y1, y + 1)};
          in.r += img.px(x, y)[0], in.g += img.px(x, y)[1], in.b += img.px(x, y)[2];
          ++n;
        }
    const std::string name = "object " + std::to_string(i) + " (" + scene.objects[std::size_t(i)].name + ")";
    if (n < 20) return fail(name + " covers too few pixels below the overlay to judge");
    // Beside it: the floor and backdrop (no object) in its rows, within its own width.
    Mean out;
    int m = 0;
    const int w = box.x1 - box.x0;
    for (int y = box.y0; y < box.y1; y += step)
      for (int x = std::max(0, box.x0 - w) / step * step; x < std::min(img.width, box.x1 + w); x += step)
        if (object[std::size_t(y) * img.width + x] == -1) {
          out.r += img.px(x, y)[0], out.g += img.px(x, y)[1], out.b += img.px(x, y)[2];
          ++m;
        }
    if (m < 10) return fail(name + ": no floor or backdrop beside it to compare with");
    in = {in.r / n, in.g / n, in.b / n};
    out = {out.r / m, out.g / m, out.b / m};
    const double d = distance(in, out);
    std::printf("%s: %d pixels, mean (%.0f, %.0f, %.0f); beside it (%.0f, %.0f, %.0f); differs by %.0f\n",
                name.c_str(), n, in.r, in.g, in.b, out.r, out.g, out.b, d);
    if (d < 40) return fail(name + " looks like the floor beside it: not drawn");
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) return fail("usage: check_screenshot FILE WIDTH HEIGHT glass|panel|scene|uncovered|checkerboard [ARGS]");
  Image img;
  try {
    img = draught::read_png(argv[1]);
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  const int width = std::atoi(argv[2]), height = std::atoi(argv[3]);
  const std::string mode = argv[4];
  std::printf("%s: %d x %d\n", argv[1], img.width, img.height);
  if (img.width != width || img.height != height)
    return fail("size " + std::to_string(img.width) + "x" + std::to_string(img.height) + ", expected " +
                std::to_string(width) + "x" + std::to_string(height));

  // Not blank: a picture has many distinct grey levels, a cleared window one or two.
  int lo = 255, hi = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const int v = img.px(x, y)[1];
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  std::printf("green channel range: %d..%d\n", lo, hi);
  if (hi - lo < 60) return fail("the picture is (nearly) uniform: nothing was drawn");

  if (mode == "scene") {
    if (argc < 6) return fail("scene needs the preset the viewer showed");
    try {
      if (check_scene(img, argv[5])) return 1;
    } catch (const std::exception& e) {
      return fail(e.what());
    }
  } else if (mode == "uncovered") {
    if (argc < 7) return fail("uncovered needs the preset the viewer showed and its layout lines");
    const std::map<std::string, Box> layout = read_layout(argv[6]);
    if (!layout.count("overlay") || !layout.count("scene")) return fail("no layout lines in " + std::string(argv[6]));
    std::vector<Region> covers;
    std::vector<std::string> names;
    for (const char* name : {"panel", "overlay"})
      if (layout.count(name)) covers.push_back(layout.at(name).pixels()), names.push_back(name);
    for (size_t i = 0; i < covers.size(); ++i) {
      const Region r = covers[i];
      const std::string& name = names[i];
      std::printf("%s: %s\n", name.c_str(), str(r).c_str());
      // Really drawn there: ImGui's windows are dark (the panel 94 % opaque, the overlay
      // 60 %), so inside they are clearly darker than the studio just around them.
      std::vector<int> in, around;
      for (int y = std::max(0, r.y0 - 12); y < std::min(img.height, r.y1 + 12); ++y)
        for (int x = std::max(0, r.x0 - 12); x < std::min(img.width, r.x1 + 12); ++x) {
          const int v = std::max({img.px(x, y)[0], img.px(x, y)[1], img.px(x, y)[2]});
          if (x >= r.x0 + 4 && x < r.x1 - 4 && y >= r.y0 + 4 && y < r.y1 - 4) in.push_back(v);
          else if (!r.contains(x, y) && !std::any_of(covers.begin(), covers.end(), [&](const Region& c) {
                     return c.contains(x, y);
                   }))
            around.push_back(v);
        }
      if (in.empty() || around.empty()) return fail(name + ": nothing to judge it by");
      std::sort(in.begin(), in.end());
      std::sort(around.begin(), around.end());
      const int mid_in = in[in.size() / 2], mid_around = around[around.size() / 2];
      std::printf("%s: median brightness %d inside, %d around it\n", name.c_str(), mid_in, mid_around);
      if (mid_in > 0.75 * mid_around) return fail("no " + name + " drawn where the layout says");
    }
    const Box sb = layout.at("scene");
    const Region sr{int(std::ceil(sb.x0)), int(std::ceil(sb.y0)), int(std::floor(sb.x1)), int(std::floor(sb.y1))};
    std::printf("scene framed in %s\n", str(sr).c_str());
    for (const Region& c : covers)
      if (sr.overlaps(c)) return fail("the scene's part of the window overlaps " + str(c));
    const draught::PictureRect view{sb.x0 / img.width, sb.y0 / img.height, (sb.x1 - sb.x0) / img.width,
                                    (sb.y1 - sb.y0) / img.height};
    try {
      if (check_scene(img, argv[5], view, &covers)) return 1;
    } catch (const std::exception& e) {
      return fail(e.what());
    }
  } else if (mode == "glass") {
    const Region centre = fraction(img, 0.4, 0.35, 0.6, 0.75);
    const Mean c = mean(img, centre);
    const Region corners[] = {fraction(img, 0, 0, 0.12, 0.12), fraction(img, 0.88, 0, 1, 0.12),
                              fraction(img, 0, 0.88, 0.12, 1), fraction(img, 0.88, 0.88, 1, 1)};
    double nearest = 1e9;
    for (Region r : corners) nearest = std::min(nearest, distance(c, mean(img, r)));
    int beer = 0, n = 0;
    for (int y = centre.y0; y < centre.y1; ++y)
      for (int x = centre.x0; x < centre.x1; ++x, ++n) beer += beer_coloured(img.px(x, y));
    std::printf("centre mean (%.0f, %.0f, %.0f); nearest corner differs by %.0f; beer-coloured %.0f %% of the centre\n",
                c.r, c.g, c.b, nearest, 100.0 * beer / n);
    if (nearest < 40) return fail("the centre looks like the corners: no glass in the middle");
    if (beer < n / 4) return fail("less than a quarter of the centre is beer-coloured");
  } else if (mode == "panel") {
    if (argc < 6) return fail("panel needs the screenshot without the panel to compare with");
    Image other;
    try {
      other = draught::read_png(argv[5]);
    } catch (const std::exception& e) {
      return fail(e.what());
    }
    if (other.width != img.width || other.height != img.height) return fail("the two screenshots differ in size");
    const Region left = fraction(img, 0.05, 0.05, 0.35, 0.5);
    double diff = 0;
    int n = 0;
    for (int y = left.y0; y < left.y1; ++y)
      for (int x = left.x0; x < left.x1; ++x, ++n)
        for (int k = 0; k < 3; ++k) diff += std::abs(int(img.px(x, y)[k]) - int(other.px(x, y)[k]));
    std::printf("panel region differs from the panel-less shot by %.1f per pixel\n", diff / n);
    if (diff / n < 20) return fail("no panel drawn over the top left of the window");
  } else if (mode == "checkerboard") {
    // A transparent picture: the window's bottom corners show the checkerboard behind it
    // (12 px squares of 0x8c and 0xa8 grey, the dark ones at the upper right of each 24 px
    // tile from the top left), the drink in the middle covers it.
    int wrong = 0, n = 0;
    for (int y = img.height - 24; y < img.height; ++y)
      for (int x : {3, 7, 15, 19, img.width - 20, img.width - 16, img.width - 8, img.width - 4}) {
        if (x % 12 < 2 || x % 12 > 9 || y % 12 < 2 || y % 12 > 9) continue;  // (off the squares' edges)
        const int expected = (x / 12 + y / 12) % 2 ? 0x8c : 0xa8;
        const std::uint8_t* p = img.px(x, y);
        ++n;
        for (int k = 0; k < 3; ++k) wrong += std::abs(int(p[k]) - expected) > 6;
      }
    const Region centre = fraction(img, 0.4, 0.45, 0.6, 0.75);
    int beer = 0, m = 0;
    for (int y = centre.y0; y < centre.y1; ++y)
      for (int x = centre.x0; x < centre.x1; ++x, ++m) beer += beer_coloured(img.px(x, y));
    std::printf("checkerboard: %d of %d corner samples off their square's grey; beer-coloured %.0f %% of the centre\n",
                wrong, 3 * n, 100.0 * beer / m);
    if (n == 0 || wrong > 0) return fail("no checkerboard behind the transparent picture in the bottom corners");
    if (beer < m / 2) return fail("less than half of the centre is beer-coloured: the drink does not cover the checkerboard");
  } else {
    return fail("unknown mode '" + mode + "': expected glass, panel, scene, uncovered or checkerboard");
  }
  std::printf("ok\n");
  return 0;
}
