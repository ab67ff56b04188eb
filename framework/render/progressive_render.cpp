#include "progressive_render.h"
#include "render_tiles.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

namespace {
using Clock = std::chrono::steady_clock;

// The batches' sample ranges, decided as they are first needed, and the frames being filled.
class Batches {
public:
	Batches(const Progressive_Options& options, uint32_t width, uint32_t height, size_t tiles)
		: options(options), width(width), height(height), tiles(tiles), start(Clock::now()) {
	}

	// The end of batch b's samples (its first is the end of batch b - 1), or 0 past the last batch.
	uint32_t end_of(size_t b) {
		std::lock_guard<std::mutex> lock(mutex);
		while (ends.size() <= b) {
			uint32_t first = ends.empty() ? 0 : ends.back();
			if (first >= options.samples) return 0;
			ends.push_back(first + std::min(options.samples - first, next_size()));
		}
		return ends[b];
	}
	uint32_t first_of(size_t b) {
		return b == 0 ? 0 : end_of(b - 1);
	}

	// Copies the tile's pixels, which have just finished batch b, into batch b's frame (before the
	// tile may start its next batch). Frames that have been handed on are reused.
	void copy_tile(size_t b, const Tile& tile, const Film& film) {
		Film_Frame* frame;
		{
			std::lock_guard<std::mutex> lock(mutex);
			auto& slot = frames[b];
			if (!slot.frame && !spare.empty()) {
				slot.frame = std::move(spare.back());
				spare.pop_back();
			}
			if (!slot.frame) slot.frame = std::make_unique<Film_Frame>(width, height);
			frame = slot.frame.get();
		}
		for (uint32_t y = tile.y0; y < tile.y1; y++) {
			for (uint32_t x = tile.x0; x < tile.x1; x++) frame->set_pixel(size_t(y) * film.w + x, film);
		}
	}

	// Counts a tile of batch b in. Frames are handed on in batch order by one thread at a time:
	// whoever finds the next frame complete while no one is handing one on hands it on, and the
	// frames after it that are complete by then. False once the render is to stop.
	bool tile_in(size_t b) {
		std::unique_lock<std::mutex> lock(mutex);
		frames[b].tiles_in++;
		while (!stopped && !handing) {
			auto next = frames.find(next_to_hand);
			if (next == frames.end() || next->second.tiles_in < tiles) break;
			std::unique_ptr<Film_Frame> done = std::move(next->second.frame);
			frames.erase(next);
			done->samples = ends[next_to_hand];
			done->seconds = std::chrono::duration<double>(Clock::now() - start).count();
			measured_samples = done->samples, measured_seconds = done->seconds;
			handing = true;
			lock.unlock();
			bool go_on = options.frame(*done);
			lock.lock();
			spare.push_back(std::move(done));
			handing = false;
			next_to_hand++;
			if (!go_on) stopped = true;
		}
		return !stopped;
	}

	bool stop_requested() {
		std::lock_guard<std::mutex> lock(mutex);
		return stopped;
	}
	void stop() {
		std::lock_guard<std::mutex> lock(mutex);
		stopped = true;
	}

private:
	// Samples per pixel for the next batch: 1 until a frame has told the speed, then what
	// batch_seconds allows at it, at most twice the last batch.
	uint32_t next_size() const {
		uint32_t last = ends.size() < 2 ? 1 : ends[ends.size() - 1] - ends[ends.size() - 2];
		if (measured_seconds <= 0.0) return 1;
		double per_second = measured_samples / measured_seconds;
		double wanted = std::floor(per_second * options.batch_seconds);
		return uint32_t(std::clamp(wanted, 1.0, 2.0 * last));
	}

	struct Frame_Slot {
		std::unique_ptr<Film_Frame> frame;
		size_t tiles_in = 0;
	};

	const Progressive_Options& options;
	const uint32_t width, height;
	const size_t tiles;
	const Clock::time_point start;
	std::mutex mutex;
	std::vector<uint32_t> ends;
	std::map<size_t, Frame_Slot> frames;
	std::vector<std::unique_ptr<Film_Frame>> spare; // handed on, to be reused
	double measured_samples = 0.0, measured_seconds = 0.0;
	size_t next_to_hand = 0; // the batch whose frame is handed on next
	bool stopped = false, handing = false;
};
} // namespace

void render_progressively(const Pathtracer& pathtracer, const Progressive_Options& options) {
	const Render_Settings& settings = pathtracer.settings;
	if (options.render.adaptive.threshold > 0.0f && options.render.adaptive.batch == 0) {
		throw std::invalid_argument("render_progressively: adaptive sampling in batches of at least one sample");
	}
	Film film(settings.width, settings.height);
	uint32_t threads = options.render.threads ? options.render.threads : std::max(1u, std::thread::hardware_concurrency());
	std::vector<Tile> tiles = make_tiles(settings.width, settings.height, tile_size(settings, options.render, threads));
	threads = std::min<uint32_t>(threads, uint32_t(tiles.size()));
	Batches batches(options, settings.width, settings.height, tiles.size());
	// Adaptive sampling (render.h): the pixels' sums and stops, carried from batch to batch.
	std::unique_ptr<Adaptive_Progress> adaptive;
	if (options.render.adaptive.threshold > 0.0f) adaptive = std::make_unique<Adaptive_Progress>(film.pixels.size());
	// The batches each tile has finished; a tile's next batch waits for its last (rarely: only when
	// the thread that had it was descheduled for as long as all the other tiles took).
	std::vector<std::atomic<size_t>> finished(tiles.size());
	std::atomic<size_t> next{0};
	auto worker = [&]() {
		for (;;) {
			size_t item = next.fetch_add(1);
			size_t b = item / tiles.size(), t = item % tiles.size();
			uint32_t end = batches.end_of(b);
			if (end == 0 || batches.stop_requested()) return;
			while (finished[t].load(std::memory_order_acquire) < b) {
				if (batches.stop_requested()) return; // (the thread that had it threw)
				std::this_thread::yield();
			}
			render_tile(pathtracer, settings, options.render, tiles[t], batches.first_of(b), end, film, adaptive.get());
			batches.copy_tile(b, tiles[t], film);
			finished[t].store(b + 1, std::memory_order_release);
			if (!batches.tile_in(b)) return;
		}
	};
	run_on_threads(threads, worker, [&] { batches.stop(); });
}
