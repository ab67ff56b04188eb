#include "render.h"
#include "render_tiles.h"
#include "estimator.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

std::vector<Tile> make_tiles(uint32_t w, uint32_t h, uint32_t size) {
	std::vector<Tile> tiles;
	for (uint32_t y = 0; y < h; y += size) {
		for (uint32_t x = 0; x < w; x += size) tiles.push_back({x, y, std::min(x + size, w), std::min(y + size, h)});
	}
	return tiles;
}

namespace {
// The first sample index at or after `first` in the pass's share (s % passes == pass - 1).
uint32_t first_of_pass(uint32_t first, const Render_Options& options) {
	uint32_t offset = options.pass - 1;
	if (first <= offset) return offset;
	return first + (options.passes - (first - offset) % options.passes) % options.passes;
}

// Task 8's loop over a pixel's samples (api/adaptive_sampling.h), held to its contract: samples 0, 1,
// 2, ... each once, at most `samples` of them, and the count it returns the count it took.
void sample_adaptively(const Adaptive_Sampling& adaptive, uint32_t samples,
                       const std::function<Spectrum(uint32_t)>& take_sample) {
	uint32_t taken = 0;
	auto counted = [&](uint32_t s) {
		if (s != taken || s >= samples) {
			throw std::logic_error("Adaptive_Sampling::sample_pixel (task 8) asked for sample " + std::to_string(s) +
			                       " of a pixel; expected sample " + std::to_string(taken) + " of at most " +
			                       std::to_string(samples) + " (handout §8.3)");
		}
		taken++;
		return take_sample(s);
	};
	uint32_t returned = adaptive.sample_pixel(samples, counted);
	if (returned != taken) {
		throw std::logic_error("Adaptive_Sampling::sample_pixel (task 8) took " + std::to_string(taken) +
		                       " samples of a pixel but returned " + std::to_string(returned) + " (handout §8.3)");
	}
}
} // namespace

void render_tile(const Pathtracer& pt, const Render_Settings& settings, const Render_Options& options, const Tile& tile,
                 uint32_t first, uint32_t end, Film& film, Adaptive_Progress* progress) {
	const Adaptive_Sampling& adaptive = options.adaptive;
	Sampler sampler = pt.estimator().choice.sampler;
	for (uint32_t y = tile.y0; y < tile.y1; y++) {
		for (uint32_t x = tile.x0; x < tile.x1; x++) {
			size_t index = size_t(y) * film.w + x;
			Pixel_Stats& pixel = film.pixels[index];
			auto take_sample = [&](uint32_t s) {
				RNG rng = generator_for_sample(settings.seed, index, s, sampler);
				Spectrum sample = pt.trace_pixel(x, y, rng);
				pixel.add(sample);
				return sample;
			};
			if (adaptive.threshold > 0.0f && progress) {
				Luminance_Sums& sums = progress->sums[index];
				for (uint32_t s = first; s < end && !progress->stopped[index]; s++) {
					sums.add(take_sample(s));
					progress->stopped[index] = (s + 1) % adaptive.batch == 0 && adaptive.pixel_converged(sums);
				}
				continue;
			}
			if (adaptive.threshold > 0.0f) {
				sample_adaptively(adaptive, end, take_sample);
				continue;
			}
			for (uint32_t s = first_of_pass(first, options); s < end; s += options.passes) take_sample(s);
		}
	}
}

uint32_t tile_size(const Render_Settings& settings, const Render_Options& options, uint32_t threads) {
	constexpr uint64_t TILES_PER_THREAD = 16;
	constexpr uint32_t SMALLEST = 4;
	uint32_t size = std::max(1u, options.tile_size);
	auto tiles = [&](uint32_t s) { return uint64_t((settings.width + s - 1) / s) * ((settings.height + s - 1) / s); };
	while (size / 2 >= SMALLEST && tiles(size) < TILES_PER_THREAD * threads) size /= 2;
	return size;
}

Film render(const Pathtracer& pathtracer, const Render_Options& options) {
	Film film(pathtracer.settings.width, pathtracer.settings.height);
	render_samples(pathtracer, film, 0, pathtracer.settings.samples, options);
	return film;
}

void render_samples(const Pathtracer& pathtracer, Film& film, uint32_t first, uint32_t end,
                    const Render_Options& options) {
	if (options.passes == 0 || options.pass < 1 || options.pass > options.passes) {
		throw std::invalid_argument("render: pass " + std::to_string(options.pass) + " of " +
		                            std::to_string(options.passes) + " (expected 1 <= pass <= passes)");
	}
	if (options.adaptive.threshold > 0.0f && (first != 0 || options.passes != 1 || options.adaptive.batch == 0)) {
		throw std::invalid_argument("render: adaptive sampling renders every sample of a film at once, in batches of "
		                            "at least one (not in passes, nor progressively)");
	}
	const Render_Settings& settings = pathtracer.settings;
	if (film.w != settings.width || film.h != settings.height) {
		throw std::invalid_argument("render_samples: the film is " + std::to_string(film.w) + " x " +
		                            std::to_string(film.h) + ", the settings " + std::to_string(settings.width) +
		                            " x " + std::to_string(settings.height));
	}
	uint32_t threads = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
	std::vector<Tile> tiles = make_tiles(settings.width, settings.height, tile_size(settings, options, threads));
	if (options.shuffle_tiles) std::shuffle(tiles.begin(), tiles.end(), std::mt19937(12345));
	threads = std::min<uint32_t>(threads, uint32_t(tiles.size()));
	std::atomic<size_t> next{0}, done{0};
	if (options.progress) options.progress(0, tiles.size()); // the bar appears at once
	auto worker = [&]() {
		for (size_t i; (i = next.fetch_add(1)) < tiles.size();) {
			render_tile(pathtracer, settings, options, tiles[i], first, end, film);
			size_t finished = done.fetch_add(1) + 1;
			if (options.progress) options.progress(finished, tiles.size());
		}
	};
	run_on_threads(threads, worker, [&] { next = tiles.size(); });
}

void run_on_threads(uint32_t threads, const std::function<void()>& work, const std::function<void()>& stop) {
	std::exception_ptr thrown;
	std::mutex mutex;
	auto guarded = [&] {
		try {
			work();
		} catch (...) {
			std::lock_guard<std::mutex> lock(mutex);
			if (!thrown) thrown = std::current_exception(), stop();
		}
	};
	std::vector<std::thread> pool;
	for (uint32_t t = 1; t < threads; t++) pool.emplace_back(guarded);
	guarded();
	for (auto& thread : pool) thread.join();
	if (thrown) std::rethrow_exception(thrown);
}
