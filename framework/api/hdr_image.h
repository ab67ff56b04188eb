#pragma once
#include "vec_math.h"

#include <string>
#include <vector>

// A linear-radiance RGB image. Pixel (0, 0) is the top-left; rows are stored top to bottom.
struct HDR_Image {
	HDR_Image() = default;
	HDR_Image(uint32_t w, uint32_t h, Spectrum fill = Spectrum{0.0f}) : w(w), h(h), pixels(size_t(w) * h, fill) {
	}

	Spectrum& at(uint32_t x, uint32_t y) {
		return pixels[size_t(y) * w + x];
	}
	const Spectrum& at(uint32_t x, uint32_t y) const {
		return pixels[size_t(y) * w + x];
	}

	uint32_t w = 0, h = 0;
	std::vector<Spectrum> pixels;
};

// The sum of the pixels' luminance, in double precision: 0 for a black image, which an environment
// cannot be importance-sampled from.
inline double total_luminance(const HDR_Image& image) {
	double total = 0.0;
	for (Spectrum pixel : image.pixels) total += double(luminance(pixel));
	return total;
}
