#pragma once
// The film as a stream of frames, for ./lab view: a renderer started with --stream renders
// progressively and writes a frame to its standard output after each batch of samples; the
// viewer reads them from a pipe. A frame is what the graders' image comparison needs of a film
// (image_compare.h: per pixel the mean, the per-sample variance and the sample count, as floats,
// as Image_Estimate::from makes them) and each pixel's count of non-finite samples.
//
// Layout (native byte order: writer and reader are programs of one build on one machine):
//   "LABF", version (uint32), width, height, samples per pixel so far (uint32 each),
//   seconds of rendering so far (double),
//   then per pixel, row by row from the top-left: mean RGB, variance RGB (float32 each),
//   finite samples, non-finite samples (uint32 each).
#include "image_compare.h"

#include <cstdint>
#include <iosfwd>
#include <vector>

struct Film;

struct Film_Frame {
	uint32_t samples = 0; // samples per pixel rendered so far
	double seconds = 0.0; // time spent rendering them
	Image_Estimate estimate;
	std::vector<uint32_t> non_finite; // per pixel

	uint32_t width() const {
		return estimate.mean.w;
	}
	uint32_t height() const {
		return estimate.mean.h;
	}
	uint64_t non_finite_total() const;
};

constexpr uint32_t FILM_STREAM_VERSION = 1;
// The largest frame a reader accepts: Render_Settings::MAX_PIXELS pixels.
constexpr uint64_t FILM_STREAM_MAX_PIXELS = 4096 * 4096;

// Writes the film as one frame, `samples` per pixel rendered in `seconds`, and flushes. (Straight
// from the film, in one pass: the renderer writes a frame after every batch.)
void write_frame(std::ostream& out, const Film& film, uint32_t samples, double seconds);

// Reads the next frame into `frame`: false at the end of the stream (before a frame starts);
// throws Input_Error for a stream that is cut inside a frame or is not a film stream.
bool read_frame(std::istream& in, Film_Frame& frame);
