// Adaptive supersampling: the pixels of a supersampled picture whose samples disagree get
// more of them. A pixel whose samples' display codes differ by more than a threshold holds
// detail finer than its samples (a glass's silhouette, a rim's thin highlight, a bead's
// glint, the bar's bottles seen through a base): there a few samples catch or miss the
// detail, where a camera's pixel integrates all of it. gpu::Renderer::render draws those
// pixels again at more samples and resolves them here; the rest keep their samples.
#pragma once

#include "core/io/image.hpp"

#include <vector>

namespace draught {

// A run of pixels in one row: x .. x + length - 1 of row y (rows top-down).
struct PixelRun {
  int x = 0, y = 0, length = 0;
  bool operator==(const PixelRun&) const = default;
};

// The pixels of a width x height picture whose factor x factor samples (core/output/resolve's
// layout: linear light times the exposure) differ in some channel by more than
// `threshold` levels of 8-bit display code after the output transform `tonemap` (where
// the eye sees the difference), or in coverage by more than `threshold` / 255, and the
// pixels next to those; merged into runs along each row, rows in order.
std::vector<PixelRun> pixels_to_refine(const std::vector<float>& samples, int width, int height, int factor,
                                       int tonemap, double threshold);

// A picture of 8-bit display samples (premultiplied sRGB codes and coverage: a
// transparent picture's, which keeps the per-sample output transform) as samples for the
// functions here: sRGB decoded, alpha 0-1. With the output transform Tonemap::None their
// resolve is core/io/image's downsample (the mean of the decoded values, encoded again).
std::vector<float> samples_from_display(const Image&);

// How many pixels the runs hold.
long pixels_in(const std::vector<PixelRun>& runs);

// The fine samples of the runs' pixels, fine x fine each: for each run, `fine` rows of
// length * fine samples (RGBA, linear light), the run's rows top-down; runs in order.
struct RefinedSamples {
  int fine = 1;
  std::vector<PixelRun> runs;
  std::vector<float> rgba;
};

// resolve_linear, with each pixel of `refined.runs` the mean of its fine samples instead of
// its own. Throws std::invalid_argument when the sizes do not match or a run leaves the
// picture.
Image resolve_refined(const std::vector<float>& samples, int width, int height, int factor,
                      const RefinedSamples& refined, int tonemap);

}  // namespace draught
