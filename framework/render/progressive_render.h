#pragma once
// Progressive rendering without pauses (./lab view, --stream): the samples of every pixel in
// batches, a frame of the film (film_frame.h) after each batch, and no thread waiting for the
// others in between.
//
// Work is (batch, tile) pairs taken in order; a tile starts its next batch as soon as it has
// finished this one, whatever the other tiles are doing, so that a thread never idles at the end
// of a batch (render_samples, called once per batch, has every thread wait there for the slowest:
// on a busy machine, for one that was descheduled). Whoever finishes a tile's batch copies the
// tile into that batch's frame; the frame is handed on once every tile has been copied. Each
// pixel's samples are still added in index order with render()'s generators, so frame after frame
// is bit for bit render()'s film with that many samples.
#include "film_frame.h"
#include "render.h"

#include <functional>

struct Progressive_Options {
	// threads, tile size, adaptive sampling (a frame's pixels then have up to frame.samples
	// samples); pass and progress are not used
	Render_Options render;
	uint32_t samples = 0;           // samples per pixel of the last frame
	double batch_seconds = 0.25;    // the time a batch should take, once the speed is known
	// Called with each frame in batch order (never two at once): the film with exactly
	// frame.samples samples in every pixel (with adaptive sampling, at most), frame.seconds after the render began. Returning false
	// stops the render.
	std::function<bool(const Film_Frame& frame)> frame;
};

// Renders options.samples samples of every pixel; the first batch has one sample per pixel (the
// first picture), later ones as many as batch_seconds allows at the speed measured so far (at
// most twice the last).
void render_progressively(const Pathtracer& pathtracer, const Progressive_Options& options);
