#pragma once
// A frame of a progressive render (progressive_render.h, ./lab view): what the graders' image
// comparison needs of a film (image_compare.h: per pixel the mean, the per-sample variance and the
// sample count, as Image_Estimate::from makes them) and each pixel's count of non-finite samples.
#include "image_compare.h"

#include <cstdint>
#include <vector>

struct Film;

struct Film_Frame {
	uint32_t samples = 0; // samples per pixel rendered so far
	double seconds = 0.0; // time spent rendering them
	Image_Estimate estimate;  // (without the fourth moment)
	std::vector<uint32_t> non_finite; // per pixel

	Film_Frame() = default;
	Film_Frame(uint32_t width, uint32_t height);
	// The whole film as a frame.
	static Film_Frame from(const Film& film, uint32_t samples, double seconds);

	// Sets pixel i from the film's pixel i.
	void set_pixel(size_t i, const Film& film);

	uint32_t width() const {
		return estimate.mean.w;
	}
	uint32_t height() const {
		return estimate.mean.h;
	}
	uint64_t non_finite_total() const;
};
