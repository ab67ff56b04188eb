#pragma once
#include "math.h"

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
