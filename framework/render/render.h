#pragma once
// Rendering: square tiles of pixels rendered in parallel on a thread pool. Every sample of a pixel
// is drawn in the same tile, in order, with its own generator (generator_for_sample, sampler.h), so
// the result is bit-identical for any number of threads and any tile order.
#include "adaptive_sampling.h"
#include "film.h"
#include "pathtracer.h"

#include <functional>

struct Render_Options {
	uint32_t threads = 0;   // 0 = all hardware threads
	uint32_t tile_size = 16; // edge in pixels; smaller on small films, so every thread has many tiles
	bool shuffle_tiles = false; // render tiles in a random order (tests determinism)
	// Called with (0, total tiles) before the first tile, then from worker threads with (finished
	// tiles, total tiles); may be empty.
	std::function<void(size_t, size_t)> progress;
	// A share of the samples, for a render split over machines (--pass, film_file.h): pass P of N
	// draws the samples with index s % N == P - 1 of the settings' samples. The N passes draw every
	// sample of the whole render exactly once, each with the generator it has there.
	uint32_t pass = 1, passes = 1;
	// With a threshold, each pixel stops once its estimate is that precise (adaptive_sampling.h):
	// the settings' samples are then the most a pixel takes. render() takes each pixel's samples at
	// once (task 8's sample_pixel), render_progressively in batches (progressive_render.h); not in
	// passes, nor by render_samples.
	Adaptive_Sampling adaptive;
};

// Renders pathtracer.settings.samples samples of every pixel (of them, options' pass's share).
Film render(const Pathtracer& pathtracer, const Render_Options& options = {});

// Progressive rendering (./lab view): adds the samples with index in [first, end) of every pixel
// (of them, options' pass's share) to `film`, a film of the settings' size that holds samples
// [0, first). Each pixel's samples are added in index order with the generators render() gives
// them, so a film grown by any sequence of ranges that covers [0, N) equals render() with N
// samples, bit for bit.
void render_samples(const Pathtracer& pathtracer, Film& film, uint32_t first, uint32_t end,
                    const Render_Options& options = {});
