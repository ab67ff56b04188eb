// Stress (handout §4.5): the Cornell box moved 10^4 away from the origin renders the same as the
// original. Far from the origin a float coordinate is only good to ~1e-3, so every spawned ray
// needs an offset that grows with the coordinates; with a fixed 1e-4, ~40 % of the bounces there
// hit the surface they leave and the picture darkens (testing-anchors §3.3).
//
// Both renders (32 x 32, 64 samples per pixel, same seed) are compared in 4 x 4 blocks of 8 x 8
// pixels, per colour channel: z = (mean_a - mean_b) / sqrt(var_a + var_b), the variances of the
// block means from the per-pixel sample variances. The renders use the same random numbers, which
// correlates them positively and only makes the test more conservative. 48 tests at an overall
// significance of 1e-3 (Šidák).
#include "pathtracer.h"
#include "render.h"
#include "scene_loader.h"
#include "statistics.h"
#include "temp_dir.h"

#include "lab_catch2.h"
#include <nlohmann/json.hpp>

#include <fstream>

namespace {

constexpr uint32_t SIZE = 32, BLOCK = 8;
constexpr float OFFSET = 1e4f;

// scenes/cornell_box.json at SIZE x SIZE pixels, every vertex and the camera moved by `offset`.
std::string translated_cornell_box(const Temp_Dir& dir, const std::string& name, Vec3 offset) {
	std::ifstream in("scenes/cornell_box.json");
	INFO("cannot read scenes/cornell_box.json: run the suite from the repository's root, as ctest does");
	REQUIRE(in.good());
	nlohmann::json scene = nlohmann::json::parse(in);
	auto move = [&](nlohmann::json& p) {
		for (int i = 0; i < 3; i++) p[i] = p[i].get<double>() + double(offset[i]);
	};
	move(scene["camera"]["position"]);
	move(scene["camera"]["target"]);
	for (auto& object : scene["objects"]) {
		REQUIRE(object.contains("vertices")); // the moved scene must really have moved coordinates
		for (auto& vertex : object["vertices"]) move(vertex);
	}
	scene["film"] = {{"width", SIZE}, {"height", SIZE}, {"samples", 64}, {"max_depth", 8}, {"seed", 1}};
	std::string file = dir.file(name);
	std::ofstream(file) << scene.dump();
	return file;
}

struct Block {
	glm::dvec3 mean{0.0}, variance{0.0}; // of the block's mean
};

Block block_of(const Film& film, uint32_t bx, uint32_t by) {
	Block b;
	double n = double(BLOCK * BLOCK);
	for (uint32_t y = by * BLOCK; y < (by + 1) * BLOCK; y++) {
		for (uint32_t x = bx * BLOCK; x < (bx + 1) * BLOCK; x++) {
			const Pixel_Stats& p = film.pixels[size_t(y) * film.w + x];
			b.mean += p.mean / n;
			b.variance += p.m2 / double(p.count - 1) / double(p.count) / (n * n);
		}
	}
	return b;
}

} // namespace

TEST_CASE("Stress: the Cornell box translated by 10^4 renders the same as the original (z-test per block)",
          "[stress][task4]") {
	Temp_Dir dir;
	Scene original = load_scene(translated_cornell_box(dir, "original.json", Vec3{0.0f}));
	Scene moved = load_scene(translated_cornell_box(dir, "moved.json", Vec3{OFFSET, -OFFSET, OFFSET}));
	Film a = render(Pathtracer(original, original.settings));
	Film b = render(Pathtracer(moved, moved.settings));
	REQUIRE(a.non_finite() == 0);
	REQUIRE(b.non_finite() == 0);

	const size_t tests = 3 * (SIZE / BLOCK) * (SIZE / BLOCK);
	const double z_max = stats::two_sided_z(stats::sidak(1e-3, tests));
	size_t rejected = 0;
	double worst = 0.0;
	for (uint32_t by = 0; by < SIZE / BLOCK; by++) {
		for (uint32_t bx = 0; bx < SIZE / BLOCK; bx++) {
			Block ba = block_of(a, bx, by), bb = block_of(b, bx, by);
			for (int c = 0; c < 3; c++) {
				double z = (ba.mean[c] - bb.mean[c]) / std::sqrt(ba.variance[c] + bb.variance[c]);
				worst = std::max(worst, std::abs(z));
				if (!(std::abs(z) <= z_max)) {
					rejected++;
					UNSCOPED_INFO("block (" << bx << ", " << by << ") channel " << c << ": original " << ba.mean[c]
					                        << ", moved " << bb.mean[c] << ", z = " << z);
				}
			}
		}
	}
	INFO(rejected << " of " << tests << " block means differ (|z| > " << z_max << ") between the Cornell box and "
	              << "the same box moved by 10^4. Far from the origin, spawned rays must start at an offset that "
	                 "grows with the hit point's coordinates (handout §4.2).");
	CHECK(rejected == 0);
	std::printf("stress count: translated Cornell box: %zu of %zu block means differ (max |z| %.2f, limit %.2f)\n",
	            rejected, tests, worst, z_max);
}
