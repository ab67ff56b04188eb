#pragma once
// The tiles a render is cut into (render.cpp), shared by render() and the progressive render
// (progressive_render.h).
#include "film.h"
#include "render.h"

#include <cstdint>
#include <functional>
#include <vector>

struct Tile {
	uint32_t x0, y0, x1, y1; // pixels [x0, x1) x [y0, y1)
};

// The film cut into tiles of `size` pixels square (smaller at the right and bottom edges), row by
// row.
std::vector<Tile> make_tiles(uint32_t w, uint32_t h, uint32_t size);

// options.tile_size, or smaller for a small film: at least TILES_PER_THREAD tiles for each thread,
// so that the threads finish within a small tile of each other, and none is left working alone
// at the end. The image does not depend on it.
uint32_t tile_size(const Render_Settings& settings, const Render_Options& options, uint32_t threads);

// Runs `work` on `threads` threads, this one among them, and returns when all have ended. The first
// exception a thread throws (task code may throw: an Input_Error, a bad_alloc) is thrown on here
// once they have; `stop` is called when it is thrown, so that the others end soon.
void run_on_threads(uint32_t threads, const std::function<void()>& work, const std::function<void()>& stop);

// Adaptive sampling over several calls (the progressive render, --stream): each pixel's luminance
// sums so far, and whether it has stopped.
struct Adaptive_Progress {
	std::vector<Luminance_Sums> sums;
	std::vector<uint8_t> stopped;
	explicit Adaptive_Progress(size_t pixels) : sums(pixels), stopped(pixels, 0) {
	}
};

// Adds samples [first, end) (of them, options' pass's share) of every pixel of the tile to the
// film, each pixel's in index order with the generators render() gives them. With adaptive
// sampling (options.adaptive), a pixel takes them until it stops: in one call, samples [0, end) by
// task 8's sample_pixel; over several (`progress`), by task 8's pixel_converged after each batch,
// as sample_pixel checks it, so that the film grows into the one render() makes.
void render_tile(const Pathtracer& pt, const Render_Settings& settings, const Render_Options& options, const Tile& tile,
                 uint32_t first, uint32_t end, Film& film, Adaptive_Progress* progress = nullptr);
