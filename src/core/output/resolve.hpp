// Supersampling's resolve in scene-linear light: each pixel the mean of its samples'
// light, then the output transform once (a camera's pixel integrates light before its
// response is applied; the reference resolves its paths the same way). The GPU's passes
// leave such samples when Frame::output_linear is set (gpu::Renderer::render).
#pragma once

#include "core/io/image.hpp"

#include <vector>

namespace draught {

// samples: (width * factor) x (height * factor) RGBA samples, rows top-down: linear light
// already times the exposure, and coverage. Each output pixel is the mean of its factor x
// factor block, through display_code (the tone map `tonemap`, then sRGB) and alpha 0-255.
// Throws std::invalid_argument when the sizes do not match.
Image resolve_linear(const std::vector<float>& samples, int width, int height, int factor, int tonemap);

// Throws std::invalid_argument (naming `who`) unless `samples` holds width x height pixels
// of factor x factor RGBA samples.
void check_sample_count(const char* who, const std::vector<float>& samples, int width, int height, int factor);
// The mean RGBA of one pixel's factor x factor samples, its first at `first`, rows of the
// samples `row` floats apart (a non-finite value, a half float's overflow, counts as none).
void block_mean(const float* first, size_t row, int factor, double mean[4]);

// Its two steps. Each pixel's mean of its factor x factor samples (RGBA; a sample's
// non-finite value, a half float's overflow, counts as none), with the same checks.
std::vector<double> sample_means(const std::vector<float>& samples, int width, int height, int factor);
// Pixel means (RGBA, linear light) through display_code, alpha 0-255.
Image display_means(const std::vector<double>& means, int width, int height, int tonemap);

}  // namespace draught
