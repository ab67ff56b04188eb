// A render split into passes (render.h: Render_Options::pass, framework/film/film_file.h): the passes
// draw every sample of the whole render exactly once, their film files keep each pixel's statistics
// exactly, and merging them gives the single render's film up to the order of its sums, within the
// bound below. Bad sets of passes are refused with the file named.
#include "error.h"
#include "estimator.h"
#include "film_file.h"
#include "image_io.h"
#include "render.h"
#include "scene_loader.h"
#include "temp_dir.h"

#include "lab_catch2.h"

#include <cmath>
#include <fstream>

namespace {

constexpr double EPSILON = 0x1p-53;  // the unit roundoff of a double
constexpr double RESIDUAL = 0x1p-48; // a double stored as two floats, hi + lo, is off by at most this, relative

// The Cornell box at 12 x 9 pixels, 11 samples each (not a multiple of the passes), sampled as renders
// are (low-discrepancy) and with next-event estimation, so that every kind of draw is split.
Render_Settings small(const Scene& scene) {
	Render_Settings settings = scene.settings;
	settings.width = 12, settings.height = 9, settings.samples = 11, settings.seed = 5, settings.max_depth = 6;
	return settings;
}
const Estimator_Choice SOBOL_NEE{"nee", Sampler::sobol};

Film render_pass(const Pathtracer& pt, uint32_t pass, uint32_t passes) {
	Render_Options options;
	options.threads = 2;
	options.pass = pass, options.passes = passes;
	return render(pt, options);
}

// How far two films of the same samples, summed in another order, may differ in a pixel channel.
// Welford's update (film.cpp) rounds three operations per sample, each by at most EPSILON relative to
// the largest of |x|, |mean|, which are at most M = |mean| + sqrt(m2) (no sample is further than
// sqrt(m2) from the mean): after n samples the mean is off by at most 3 n EPSILON M, and m2, a sum of n
// terms of size at most M^2, by at most 6 n^2 EPSILON M^2. A merge of P passes adds 3 EPSILON M per pass
// (Pixel_Stats::merge); storing the passes in film files adds RESIDUAL relative per pass. Two such
// results differ by at most twice the sum.
struct Bound {
	double mean, m2;
};
Bound summation_order_bound(const Pixel_Stats& p, int c, uint32_t passes) {
	double n = p.count, m = std::abs(p.mean[c]) + std::sqrt(p.m2[c]);
	return {2.0 * (3.0 * (n + passes) * EPSILON * m + passes * RESIDUAL * std::abs(p.mean[c])),
	        2.0 * (6.0 * n * (n + passes) * EPSILON * m * m + passes * RESIDUAL * p.m2[c])};
}

} // namespace

TEST_CASE("N passes draw every sample of the render once: their counts add up to the render's") {
	Scene scene = load_scene("scenes/cornell_box.json");
	Pathtracer pt(scene, small(scene), View::path, SOBOL_NEE);
	Film whole = render_pass(pt, 1, 1);
	std::vector<uint32_t> counts(whole.pixels.size(), 0);
	for (uint32_t pass = 1; pass <= 4; pass++) {
		Film part = render_pass(pt, pass, 4);
		for (size_t i = 0; i < counts.size(); i++) counts[i] += part.pixels[i].count + part.pixels[i].non_finite;
	}
	for (size_t i = 0; i < counts.size(); i++) {
		INFO("pixel " << i);
		CHECK(counts[i] == 11);
	}
}

TEST_CASE("a film file keeps each pixel's count exactly and its mean, m2, m3 and m4 to 2^-48") {
	Scene scene = load_scene("scenes/cornell_box.json");
	Film film = render_pass(Pathtracer(scene, small(scene), View::path, SOBOL_NEE), 2, 3);
	Temp_Dir dir;
	write_film(dir.file("pass.exr"), film, Film_Origin{"cornell", 5, 11, 2, 3});
	Film_File read = read_film(dir.file("pass.exr"));
	CHECK(read.origin.scene == "cornell");
	CHECK(read.origin.seed == 5);
	CHECK(read.origin.samples == 11);
	CHECK(read.origin.pass == 2);
	CHECK(read.origin.passes == 3);
	REQUIRE(read.film.w == film.w);
	REQUIRE(read.film.h == film.h);
	for (size_t i = 0; i < film.pixels.size(); i++) {
		const Pixel_Stats &a = film.pixels[i], &b = read.film.pixels[i];
		INFO("pixel " << i);
		CHECK(a.count == b.count);
		CHECK(a.non_finite == b.non_finite);
		for (int c = 0; c < 3; c++) {
			CHECK(std::abs(a.mean[c] - b.mean[c]) <= RESIDUAL * std::abs(a.mean[c]));
			CHECK(std::abs(a.m2[c] - b.m2[c]) <= RESIDUAL * a.m2[c]);
			CHECK(std::abs(a.m3[c] - b.m3[c]) <= RESIDUAL * std::abs(a.m3[c]));
			CHECK(std::abs(a.m4[c] - b.m4[c]) <= RESIDUAL * a.m4[c]);
		}
	}
}

TEST_CASE("merging the passes' film files, in any order, gives the single render up to summation order") {
	Scene scene = load_scene("scenes/cornell_box.json");
	Render_Settings settings = small(scene);
	Pathtracer pt(scene, settings, View::path, SOBOL_NEE);
	Film whole = render_pass(pt, 1, 1);
	const uint32_t PASSES = 4;
	Temp_Dir dir;
	std::vector<std::string> files;
	for (uint32_t pass : {3u, 1u, 4u, 2u}) {
		files.push_back(dir.file("pass" + std::to_string(pass) + ".exr"));
		write_film(files.back(), render_pass(pt, pass, PASSES), Film_Origin{"cornell", 5, 11, pass, PASSES});
	}
	Film_File merged = merge_films(files);
	CHECK(merged.origin.pass == 1);
	CHECK(merged.origin.passes == 1);
	for (size_t i = 0; i < whole.pixels.size(); i++) {
		const Pixel_Stats &single = whole.pixels[i], &joined = merged.film.pixels[i];
		INFO("pixel " << i);
		REQUIRE(joined.count == single.count);
		CHECK(joined.non_finite == single.non_finite);
		for (int c = 0; c < 3; c++) {
			Bound bound = summation_order_bound(single, c, PASSES);
			INFO("channel " << c << ": single render mean " << single.mean[c] << ", m2 " << single.m2[c]
			                << "; merged mean " << joined.mean[c] << ", m2 " << joined.m2[c]);
			CHECK(std::abs(joined.mean[c] - single.mean[c]) <= bound.mean);
			CHECK(std::abs(joined.m2[c] - single.m2[c]) <= bound.m2);
			// m4, a sum of fourth powers, on the same reasoning is off by a few n^2 EPSILON M^4; the
			// check only asks that the merge formula is the right one (10^-9 of M^4 n).
			double m = std::abs(single.mean[c]) + std::sqrt(single.m2[c]);
			CHECK(std::abs(joined.m4[c] - single.m4[c]) <= 1e-9 * m * m * m * m * double(single.count));
		}
	}
}

TEST_CASE("merging refuses a pass given twice, a missing pass, a pass of another render and a plain image") {
	Scene scene = load_scene("scenes/cornell_box.json");
	Pathtracer pt(scene, small(scene), View::path, SOBOL_NEE);
	Temp_Dir dir;
	std::string one = dir.file("one.exr"), two = dir.file("two.exr"), other = dir.file("other.exr");
	write_film(one, render_pass(pt, 1, 2), Film_Origin{"cornell", 5, 11, 1, 2});
	write_film(two, render_pass(pt, 2, 2), Film_Origin{"cornell", 5, 11, 2, 2});
	write_film(other, render_pass(pt, 2, 2), Film_Origin{"cornell", 6, 11, 2, 2});
	CHECK_THROWS_WITH(merge_films({one, one}), contains_text(one) && contains_text("pass 1 is already in"));
	CHECK_THROWS_WITH(merge_films({two}), contains_text("pass 1 of 2") && contains_text("missing"));
	CHECK_THROWS_WITH(merge_films({one, other}), contains_text(other) && contains_text("another render"));
	std::string image = dir.file("image.exr");
	write_exr(image, render_pass(pt, 1, 1).mean());
	CHECK_THROWS_WITH(merge_films({image}), contains_text(image) && contains_text("not a film file"));
	CHECK_THROWS_AS(merge_films({dir.file("none.exr")}), Input_Error);
}
