// Checks a draught-viewer screenshot:
//   check_screenshot FILE WIDTH HEIGHT glass         the size, not blank, a beer-coloured
//                                                    glass in the middle unlike the corners
//   check_screenshot FILE WIDTH HEIGHT panel OTHER   the size, and the left part (where the
//                                                    panel sits) clearly differs from OTHER,
//                                                    the same scene without the panel
// Prints what it measured; exits 1 naming the check that failed.
#include "core/io/image.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

using draught::Image;

namespace {

struct Region {
  int x0, y0, x1, y1;  // pixels, [x0, x1) x [y0, y1)
};

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

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) return fail("usage: check_screenshot FILE WIDTH HEIGHT glass|panel [OTHER]");
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

  if (mode == "glass") {
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
  } else {
    return fail("unknown mode '" + mode + "': expected glass or panel");
  }
  std::printf("ok\n");
  return 0;
}
