// Rendering (framework/render/render.h) and the film (framework/film/film.h): a render is a pure function of
// (scene, settings, seed), whatever the threads and tile order; pixels keep an exact mean and
// variance; non-finite samples are counted, never averaged.
#include "estimator.h"
#include "progressive_render.h"
#include "render.h"
#include "scene_loader.h"

#include "lab_catch2.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <vector>

namespace {

// A grey diffuse sphere under a white sky, seen from the front: every pixel depends on random
// numbers (the jittered camera ray of task 1, and in the path view the bounces of task 4).
Scene sphere_scene() {
	Scene scene;
	scene.camera = Camera::look_at(Vec3{0.0f, 0.0f, 3.0f}, Vec3{0.0f}, Vec3{0.0f, 1.0f, 0.0f}, 50.0f, 4.0f / 3.0f);
	scene.settings.width = 24;
	scene.settings.height = 18;
	scene.settings.samples = 4;
	scene.settings.max_depth = 3;
	scene.settings.seed = 7;
	scene.materials.push_back(Material{BSDF(BSDF_Lambertian{Spectrum{0.6f}}), Spectrum{0.0f}});
	scene.material_names.push_back("grey");
	scene.objects.emplace_back(Sphere{1.0f}, Mat4{1.0f}, 0, 0);
	scene.environment = Env_Constant{Spectrum{1.0f}};
	scene.commit();
	return scene;
}

Film render_with(const Scene& scene, View view, Render_Options options, uint64_t seed = 7,
                 Sampler sampler = Sampler::independent, const std::string& integrator = "mixture") {
	Render_Settings settings = scene.settings;
	settings.seed = seed;
	Estimator_Choice estimator;
	estimator.sampler = sampler;
	estimator.integrator = integrator;
	return render(Pathtracer(scene, settings, view, estimator), options);
}

Render_Options threads_and_tiles(uint32_t threads, uint32_t tile_size, bool shuffle = false) {
	Render_Options options;
	options.threads = threads;
	options.tile_size = tile_size;
	options.shuffle_tiles = shuffle;
	return options;
}

bool same_bits(const Pixel_Stats& a, const Pixel_Stats& b) {
	return a.count == b.count && a.non_finite == b.non_finite && std::memcmp(&a.mean, &b.mean, sizeof a.mean) == 0 &&
	       std::memcmp(&a.m2, &b.m2, sizeof a.m2) == 0 && std::memcmp(&a.m3, &b.m3, sizeof a.m3) == 0 &&
	       std::memcmp(&a.m4, &b.m4, sizeof a.m4) == 0;
}

// Index of the first pixel whose statistics differ in any bit, or -1 if the films are identical.
long first_difference(const Film& a, const Film& b) {
	REQUIRE(a.w == b.w);
	REQUIRE(a.h == b.h);
	for (size_t i = 0; i < a.pixels.size(); i++) {
		if (!same_bits(a.pixels[i], b.pixels[i])) return long(i);
	}
	return -1;
}

// The determinism checks below prove nothing unless the pixels depend on the random numbers: a
// pixel whose samples differ from each other (sum of squared deviations m2 > 0) does.
void require_random_pixels(const Film& film) {
	size_t random = 0;
	for (const Pixel_Stats& p : film.pixels) random += p.m2 != glm::dvec3{0.0};
	INFO(random << " of " << film.pixels.size() << " pixels have differing samples; the test scene needs the reference "
	     "tasks (task 1 for the direction view, tasks 1-4 for the path view) to work");
	REQUIRE(random >= film.pixels.size() / 4);
}

} // namespace

TEST_CASE("render is bit-identical for any number of threads, tile size and tile order") {
	Scene scene = sphere_scene();
	View view = GENERATE(View::direction, View::path);
	Sampler sampler = GENERATE(Sampler::independent, Sampler::sobol);
	std::string integrator = GENERATE("mixture", "nee");
	CAPTURE(view_name(view), sampler_name(sampler), integrator);
	Film reference = render_with(scene, view, threads_and_tiles(1, 16), 7, sampler, integrator);
	require_random_pixels(reference);

	// (threads, tile size, shuffled tiles); 0 threads = all hardware threads.
	for (Render_Options options : {threads_and_tiles(2, 16), threads_and_tiles(1, 1), threads_and_tiles(2, 5),
	                               threads_and_tiles(2, 64), threads_and_tiles(1, 16, true),
	                               threads_and_tiles(2, 3, true), threads_and_tiles(0, 7, true)}) {
		INFO("threads " << options.threads << ", tile size " << options.tile_size
		     << (options.shuffle_tiles ? ", shuffled tiles" : ""));
		long pixel = first_difference(reference, render_with(scene, view, options, 7, sampler, integrator));
		INFO("first differing pixel: " << pixel << " (a pixel's samples must not depend on which thread or "
		     "tile draws them: seed each with RNG::for_sample)");
		CHECK(pixel == -1);
	}
}

TEST_CASE("a render whose lights the light tree chooses is bit-identical for any number of threads") {
	// The tree chooses by the shading point: still a pure function of each sample's random numbers.
	Scene scene = load_scene("scenes/many_lights.json");
	Render_Settings& settings = scene.settings;
	settings.width = 24, settings.height = 15, settings.samples = 4, settings.seed = 3;
	Estimator_Choice estimator{"nee"};
	estimator.light_choice = Light_Choice::tree;
	estimator.sampler = GENERATE(Sampler::independent, Sampler::sobol);
	CAPTURE(sampler_name(estimator.sampler));
	Film reference = render(Pathtracer(scene, settings, View::path, estimator), threads_and_tiles(1, 16));
	require_random_pixels(reference);
	for (Render_Options options : {threads_and_tiles(2, 5), threads_and_tiles(0, 3, true)}) {
		INFO("threads " << options.threads << ", tile size " << options.tile_size);
		CHECK(first_difference(reference, render(Pathtracer(scene, settings, View::path, estimator), options)) == -1);
	}
}

TEST_CASE("render: the same seed gives the same image, another seed another image") {
	Scene scene = sphere_scene();
	View view = GENERATE(View::direction, View::path);
	CAPTURE(view_name(view));
	Film a = render_with(scene, view, threads_and_tiles(2, 8), 7);
	require_random_pixels(a);
	CHECK(first_difference(a, render_with(scene, view, threads_and_tiles(2, 8), 7)) == -1);

	// Every pixel whose samples vary has 4 of them: with new random numbers its statistics change.
	Film b = render_with(scene, view, threads_and_tiles(2, 8), 8);
	size_t random = 0, unchanged = 0;
	for (size_t i = 0; i < a.pixels.size(); i++) {
		if (a.pixels[i].m2 == glm::dvec3{0.0}) continue;
		random++;
		unchanged += same_bits(a.pixels[i], b.pixels[i]);
	}
	INFO(unchanged << " of " << random << " pixels with random samples are the same for seeds 7 and 8: "
	     "RNG::for_sample must use the render seed");
	CHECK(unchanged == 0);
}

TEST_CASE("render draws settings.samples samples of every pixel and reports progress from 0 up to all tiles") {
	Scene scene = sphere_scene();
	Render_Options options = threads_and_tiles(2, 5);
	std::mutex mutex;
	std::vector<size_t> reports;
	size_t total = 0;
	options.progress = [&](size_t done, size_t all) {
		std::lock_guard<std::mutex> lock(mutex);
		reports.push_back(done);
		total = all;
	};
	Film film = render_with(scene, View::direction, options);
	for (const Pixel_Stats& p : film.pixels) REQUIRE(p.count + p.non_finite == scene.settings.samples);

	const size_t tiles = ((24 + 4) / 5) * ((18 + 4) / 5); // ceil(24 / 5) * ceil(18 / 5)
	CHECK(total == tiles);
	std::sort(reports.begin(), reports.end());
	std::vector<size_t> expected(tiles + 1);
	for (size_t i = 0; i <= tiles; i++) expected[i] = i;
	CHECK(reports == expected); // 0 before the first tile (the bar appears at once), then each tile once
}

TEST_CASE("Pixel_Stats: mean and unbiased variance equal the two-pass formulas") {
	// Samples far from 0 with a small spread: a one-pass sum of squares would lose the variance.
	std::vector<Spectrum> samples;
	for (int i = 0; i < 50; i++) {
		float k = float(i % 7) - 3.0f;
		samples.push_back(Spectrum{0.25f * float(i), 1e4f + 0.01f * k, (i % 2) ? 3.0f : -1.0f});
	}
	Pixel_Stats stats;
	for (Spectrum s : samples) stats.add(s);
	REQUIRE(stats.count == samples.size());
	CHECK(stats.non_finite == 0u);

	// Two-pass: mean = sum x / n, then s^2 = sum (x - mean)^2 / (n - 1).
	const double n = double(samples.size());
	Film film(1, 1);
	film.pixels[0] = stats;
	for (int c = 0; c < 3; c++) {
		double sum = 0.0, squares = 0.0;
		for (Spectrum s : samples) sum += double(s[c]);
		double mean = sum / n;
		for (Spectrum s : samples) squares += (double(s[c]) - mean) * (double(s[c]) - mean);
		double variance = squares / (n - 1.0);
		CAPTURE(c, mean, variance, stats.mean[c], stats.m2[c]);
		CHECK(stats.mean[c] == Approx(mean).epsilon(1e-12));
		CHECK(stats.m2[c] / (n - 1.0) == Approx(variance).epsilon(1e-9));
		// The film's images are the same numbers in float.
		CHECK(film.mean().pixels[0][c] == Approx(float(mean)).epsilon(1e-6));
		CHECK(film.variance().pixels[0][c] == Approx(float(variance)).epsilon(1e-6));
	}
}

namespace {
// Sums of the third and fourth powers of the deviations from the mean, in two passes.
glm::dvec2 two_pass_m3_m4(const std::vector<Spectrum>& samples, int c) {
	double mean = 0.0;
	for (Spectrum s : samples) mean += double(s[c]) / double(samples.size());
	glm::dvec2 m{0.0};
	for (Spectrum s : samples) {
		double d = double(s[c]) - mean;
		m += glm::dvec2(d * d * d, d * d * d * d);
	}
	return m;
}
} // namespace

TEST_CASE("Pixel_Stats: third and fourth central moments equal the two-pass sums, added or merged") {
	// Skewed, heavy-tailed samples (a rare bright one, as a firefly), far from 0 in one channel.
	std::vector<Spectrum> samples;
	for (int i = 0; i < 101; i++) {
		float k = float(i % 7) - 3.0f;
		samples.push_back(Spectrum{(i % 37 == 5) ? 500.0f : 0.25f * float(i % 11), 1e3f + 0.5f * k * k * k,
		                           (i % 3) ? 3.0f : -1.0f});
	}
	Pixel_Stats all, first, second;
	for (size_t i = 0; i < samples.size(); i++) {
		all.add(samples[i]);
		(i < 40 ? first : second).add(samples[i]);
	}
	Pixel_Stats merged = first;
	merged.merge(second);
	Film film(1, 1);
	film.pixels[0] = all;
	for (int c = 0; c < 3; c++) {
		glm::dvec2 expected = two_pass_m3_m4(samples, c);
		CAPTURE(c, expected.x, expected.y, all.m3[c], all.m4[c], merged.m3[c], merged.m4[c]);
		// m3 may be near 0: compare it on the scale of n sigma^3.
		double m3_scale = std::pow(all.m2[c] / all.count, 1.5) * all.count;
		CHECK(std::abs(all.m3[c] - expected.x) <= 1e-9 * m3_scale);
		CHECK(std::abs(merged.m3[c] - expected.x) <= 1e-9 * m3_scale);
		CHECK(all.m4[c] == Approx(expected.y).epsilon(1e-9));
		CHECK(merged.m4[c] == Approx(expected.y).epsilon(1e-9));
		CHECK(film.fourth_moment().pixels[0][c] == Approx(float(expected.y / double(samples.size()))).epsilon(1e-6));
	}
}

TEST_CASE("Pixel_Stats: NaN and infinite samples are counted and left out of the mean") {
	const float nan = std::numeric_limits<float>::quiet_NaN();
	Pixel_Stats stats;
	stats.add(Spectrum{1.0f, 2.0f, 3.0f});
	stats.add(Spectrum{nan, 0.0f, 0.0f});
	stats.add(Spectrum{0.0f, INF_F, 0.0f});
	stats.add(Spectrum{0.0f, 0.0f, -INF_F});
	stats.add(Spectrum{3.0f, 4.0f, 5.0f});
	CHECK(stats.count == 2u);
	CHECK(stats.non_finite == 3u);
	CHECK(stats.mean == glm::dvec3{2.0, 3.0, 4.0});
	CHECK(stats.m2 == glm::dvec3{2.0, 2.0, 2.0}); // (1 - 2)^2 + (3 - 2)^2 per channel
}

TEST_CASE("Film: non_finite() sums the pixels, non_finite_map() marks them, variance of one sample is 0") {
	Film film(3, 2);
	film.pixels[1].add(Spectrum{std::numeric_limits<float>::quiet_NaN()});
	film.pixels[1].add(Spectrum{INF_F});
	film.pixels[4].add(Spectrum{-INF_F});
	film.pixels[5].add(Spectrum{0.5f});
	CHECK(film.non_finite() == 3u);

	HDR_Image map = film.non_finite_map();
	REQUIRE(map.w == 3u);
	REQUIRE(map.h == 2u);
	for (size_t i = 0; i < map.pixels.size(); i++) {
		CAPTURE(i);
		CHECK(map.pixels[i] == Spectrum{(i == 1 || i == 4) ? 1.0f : 0.0f});
	}
	CHECK(film.mean().pixels[5] == Spectrum{0.5f});
	CHECK(film.variance().pixels[5] == Spectrum{0.0f}); // s^2 needs two samples; 0 with fewer
}

TEST_CASE("A film grown sample range by sample range equals the render of all its samples, bit for bit", "[render]") {
	// ./lab view renders progressively (render_samples, in batches of any size) and promises the
	// picture after N samples is the one `--spp N` renders.
	Scene scene = sphere_scene();
	for (Sampler sampler : {Sampler::independent, Sampler::sobol}) {
		Render_Settings settings = scene.settings;
		settings.samples = 7;
		Estimator_Choice estimator;
		estimator.sampler = sampler;
		Pathtracer pathtracer(scene, settings, View::path, estimator);
		Film whole = render(pathtracer);
		Film grown(settings.width, settings.height);
		uint32_t first = 0;
		for (uint32_t end : {1u, 2u, 4u, 7u}) { // batches of 1, 1, 2 and 3 samples
			Render_Options options;
			options.threads = end; // any threads
			render_samples(pathtracer, grown, first, end, options);
			first = end;
		}
		for (size_t i = 0; i < whole.pixels.size(); i++) {
			INFO("pixel " << i << ", sampler " << sampler_name(sampler));
			REQUIRE(grown.pixels[i].count == whole.pixels[i].count);
			REQUIRE(std::memcmp(&grown.pixels[i].mean, &whole.pixels[i].mean, sizeof(glm::dvec3)) == 0);
			REQUIRE(std::memcmp(&grown.pixels[i].m2, &whole.pixels[i].m2, sizeof(glm::dvec3)) == 0);
		}
	}
}

TEST_CASE("render_samples refuses a film of another size than the settings'", "[render]") {
	Scene scene = sphere_scene();
	Pathtracer pathtracer(scene, scene.settings, View::path);
	Film wrong(scene.settings.width + 1, scene.settings.height);
	CHECK_THROWS_WITH(render_samples(pathtracer, wrong, 0, 1), contains_text("the film is 25 x 18"));
}

TEST_CASE("A progressive render hands on, batch after batch, render()'s film with that many samples", "[render]") {
	// ./lab view's renderer (--stream): no thread waits for the others between batches, yet every
	// frame must be exactly the film of render() with the frame's samples.
	Scene scene = sphere_scene();
	Render_Settings settings = scene.settings;
	settings.samples = 9;
	Estimator_Choice estimator;
	estimator.sampler = Sampler::sobol;
	Pathtracer pathtracer(scene, settings, View::path, estimator);
	for (uint32_t threads : {1u, 3u}) {
		Progressive_Options options;
		options.render.threads = threads;
		options.render.tile_size = 4; // many tiles: tiles of one batch finish while others start the next
		options.samples = settings.samples;
		options.batch_seconds = 1e-9; // one sample per batch: the most frames
		std::vector<uint32_t> counts;
		options.frame = [&](const Film_Frame& frame) {
			counts.push_back(frame.samples);
			Render_Settings partial = settings;
			partial.samples = frame.samples;
			Film_Frame expected =
				Film_Frame::from(render(Pathtracer(scene, partial, View::path, estimator)), frame.samples, 0.0);
			for (size_t i = 0; i < expected.non_finite.size(); i++) {
				INFO("frame of " << frame.samples << " samples, pixel " << i << ", " << threads << " threads");
				REQUIRE(frame.estimate.samples[i] == frame.samples);
				REQUIRE(std::memcmp(&frame.estimate.mean.pixels[i], &expected.estimate.mean.pixels[i], sizeof(Spectrum)) == 0);
				REQUIRE(std::memcmp(&frame.estimate.variance.pixels[i], &expected.estimate.variance.pixels[i],
				                    sizeof(Spectrum)) == 0);
				REQUIRE(frame.non_finite[i] == expected.non_finite[i]);
			}
			CHECK(frame.seconds >= 0.0);
			return true;
		};
		render_progressively(pathtracer, options);
		CHECK(counts == std::vector<uint32_t>{1, 2, 3, 4, 5, 6, 7, 8, 9}); // in order, each once
	}
}

TEST_CASE("A progressive render stops when its frame handler says so", "[render]") {
	Scene scene = sphere_scene();
	Render_Settings settings = scene.settings;
	settings.samples = 50;
	Pathtracer pathtracer(scene, settings, View::path);
	Progressive_Options options;
	options.render.threads = 2;
	options.samples = settings.samples;
	options.batch_seconds = 1e-9;
	std::vector<uint32_t> counts;
	options.frame = [&](const Film_Frame& frame) {
		counts.push_back(frame.samples);
		return frame.samples < 3; // the viewer went away after the third frame
	};
	render_progressively(pathtracer, options);
	CHECK(counts == std::vector<uint32_t>{1, 2, 3});
}

TEST_CASE("An exception thrown on any of a render's threads reaches its caller, after every thread ended", "[render]") {
	// Task code may throw (the subject reports the exception to the judge): a thread that ends by an
	// exception must not end the program. Here the work of a thread throws after a few tiles.
	Scene scene = sphere_scene();
	Pathtracer pathtracer(scene, scene.settings, View::path);
	for (uint32_t threads : {1u, 3u}) {
		INFO(threads << " threads");
		Render_Options options = threads_and_tiles(threads, 4);
		options.progress = [](size_t done, size_t) {
			if (done == 3) throw std::runtime_error("thrown while rendering");
		};
		CHECK_THROWS_WITH(render(pathtracer, options), "thrown while rendering");

		Progressive_Options progressive;
		progressive.render = threads_and_tiles(threads, 4);
		progressive.samples = 20;
		progressive.batch_seconds = 1e-9;
		progressive.frame = [](const Film_Frame& frame) {
			if (frame.samples == 2) throw std::runtime_error("thrown with a frame");
			return true;
		};
		CHECK_THROWS_WITH(render_progressively(pathtracer, progressive), "thrown with a frame");
	}
}
