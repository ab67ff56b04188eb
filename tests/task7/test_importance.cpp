// Task 7 grader, handout §7.4: importance sampling of an environment map (Samplers::Sphere::Image
// and Env_Map with importance_sampling on).
#include "env_test_support.h"
#include "sphere_chi2.h"
#include "student_overlapped.h"

#include "lab_catch2.h"

#include <future>
#include <iterator>
#include <vector>

using namespace env_test;

namespace {

struct Named_Map {
	std::string name;
	HDR_Image image;
};

// The points of integral_over_sphere: the midpoints of a 4 x 4 grid inside every texel of a w x h map.
std::vector<Vec2> quadrature_uvs(uint32_t w, uint32_t h) {
	const uint32_t nu = 4 * w, nv = 4 * h;
	std::vector<Vec2> uvs;
	for (uint32_t b = 0; b < nv; b++) {
		for (uint32_t a = 0; a < nu; a++) uvs.push_back(Vec2{float((a + 0.5) / nu), float((b + 0.5) / nv)});
	}
	return uvs;
}

// Integral over the sphere of a pdf given at quadrature_uvs(w, h), computed in uv where
// d omega = 2 pi^2 sin(theta) du dv. For a pdf that is a constant per texel divided by sin(theta)
// (handout §7.4) the rule is exact; a uniform-sphere Monte Carlo estimate would not do, its variance
// is infinite because of the 1 / sin(theta) at the poles.
double integral_over_sphere(const std::vector<float>& pdf, uint32_t w, uint32_t h) {
	std::vector<Vec2> uvs = quadrature_uvs(w, h);
	double sum = 0.0;
	for (size_t n = 0; n < uvs.size(); n++) sum += double(pdf[n]) * 2.0 * M_PI * M_PI * std::sin(M_PI * uvs[n].y);
	return sum / double(uvs.size());
}

std::vector<Vec3> directions_at(const std::vector<Vec2>& uvs) {
	std::vector<Vec3> dirs;
	for (Vec2 uv : uvs) dirs.push_back(uv_to_direction(uv));
	return dirs;
}

// One bright texel away from the seam and the poles.
HDR_Image inner_texel_map() {
	Texel t = inner_bright_texel();
	return one_texel_map(32, 16, t.i, t.j);
}

// Luminance (linear Rec. 709) of pure red and pure green: a test that the table uses luminance,
// not e.g. the mean of the channels (which would make them equal).
constexpr float Y_RED = 0.2126f, Y_GREEN = 0.7152f;

} // namespace

TEST_CASE("Image: pdf_texel and cdf describe a probability distribution over the texels", "[id:t7.importance.tables][task7][importance][fn:Image (tables)]") {
	const Named_Map maps[] = {{"a constant map", HDR_Image(32, 16, Spectrum{1.0f})},
	                          {"a gradient", gradient_map()},
	                          {"one bright texel", inner_texel_map()},
	                          {"a sky with a sun", sky_map()}};
	for (const Named_Map& m : maps) {
		protocol::Image_Sampler::Answer sampler = student_image_sampler(m.image, {}, {});
		size_t n = size_t(m.image.w) * m.image.h;
		INFO("Image built from " << m.name << " (" << m.image.w << " x " << m.image.h
		                         << "): w, h, pdf_texel and cdf as declared in env_light.h (handout §7.4)");
		REQUIRE(sampler.w == m.image.w);
		REQUIRE(sampler.h == m.image.h);
		REQUIRE(sampler.pdf_texel.size() == n);
		REQUIRE(sampler.cdf.size() == n);
		double sum = 0.0;
		size_t negative = 0, not_running_sum = 0;
		for (size_t k = 0; k < n; k++) {
			if (!(sampler.pdf_texel[k] >= 0.0f)) negative++;
			sum += sampler.pdf_texel[k];
			// The cdf is the running sum of pdf_texel (float rounding: 1e-5).
			if (!(std::abs(sampler.cdf[k] - sum) <= 1e-5)) not_running_sum++;
		}
		INFO("pdf_texel: " << negative << " negative or NaN entries; sum " << sum
		                   << " (must be 1: probabilities of choosing each texel); " << not_running_sum
		                   << " cdf entries that are not the running sum of pdf_texel; cdf.back() = "
		                   << sampler.cdf.back() << " (must be 1, or sampling can run past the last texel)");
		CHECK(negative == 0);
		CHECK(sum == Approx(1.0).epsilon(1e-5));
		CHECK(not_running_sum == 0);
		CHECK(sampler.cdf.back() == Approx(1.0f).epsilon(1e-6));
	}
}

TEST_CASE("Image: a texel's probability is proportional to luminance * sin(theta)", "[id:t7.importance.proportional][task7][importance][fn:Image (tables)]") {
	// Columns 0-15 red, 16-31 green. The bilinear lookup mixes only neighbouring columns, so away
	// from the colour boundaries (and the seam) a texel's probability is Y * sin(theta_row) / total.
	// sin(theta) at the row's centre and its mean over the row differ by less than 0.2 % at 16 rows,
	// so either is accepted within 1 %; leaving sin(theta) out is off by up to a factor 10.
	const uint32_t w = 32, h = 16;
	HDR_Image image(w, h);
	for (uint32_t j = 0; j < h; j++)
		for (uint32_t i = 0; i < w; i++) image.at(i, j) = i < w / 2 ? Spectrum{1, 0, 0} : Spectrum{0, 1, 0};
	std::vector<float> pdf_texel = student_image_sampler(image, {}, {}).pdf_texel;
	REQUIRE(pdf_texel.size() == size_t(w) * h);

	auto flux = [&](uint32_t i, uint32_t j) {
		return (i < w / 2 ? Y_RED : Y_GREEN) * std::sin(M_PI * (j + 0.5) / h);
	};
	const uint32_t ref_i = 24, ref_j = h / 2; // a green texel on the equator
	int bad = 0;
	std::string first;
	for (uint32_t j = 0; j < h; j++) {
		for (uint32_t i = 0; i < w; i++) {
			bool near_boundary = i <= 1 || i >= w - 2 || (i >= w / 2 - 2 && i <= w / 2 + 1);
			if (near_boundary) continue;
			double expected = flux(i, j) / flux(ref_i, ref_j);
			double got = double(pdf_texel[size_t(j) * w + i]) / pdf_texel[size_t(ref_j) * w + ref_i];
			if (!(std::abs(got / expected - 1.0) <= 0.01)) {
				if (bad++ == 0) {
					std::ostringstream s;
					s << "texel (" << i << ", " << j << "): pdf_texel relative to texel (" << ref_i << ", " << ref_j
					  << ") is " << got << ", expected " << expected;
					first = s.str();
				}
			}
		}
	}
	INFO("the probability of a texel must be proportional to its luminance (0.2126 r + 0.7152 g + 0.0722 b, "
	     "luminance() in vec_math.h) times sin(theta) of its row: the flux through it (handout §7.4). "
	     << bad << " texels off by more than 1 %; first: " << first);
	CHECK(bad == 0);
}

TEST_CASE("Image::pdf integrates to 1 over the sphere", "[id:t7.importance.pdf-integral][task7][importance][fn:Image::pdf][uses:Image (tables)][uses:direction_to_uv]") {
	const Named_Map maps[] = {{"a constant map", HDR_Image(32, 16, Spectrum{1.0f})},
	                          {"a gradient", gradient_map()},
	                          {"one bright texel", inner_texel_map()},
	                          {"one bright texel at the seam and the pole", one_texel_map(32, 16, 0, 0)},
	                          {"a sky with a sun", sky_map()},
	                          {"a black map", HDR_Image(16, 8)}};
	for (const Named_Map& m : maps) {
		std::vector<Vec3> dirs = directions_at(quadrature_uvs(m.image.w, m.image.h));
		std::vector<float> pdf = student_image_sampler(m.image, {}, dirs).queries.pdfs;
		double integral = integral_over_sphere(pdf, m.image.w, m.image.h);
		// Float rounding of the texel probabilities and of sin(theta): far below 1e-3.
		INFO("the integral of Image::pdf over all directions for " << m.name << " is " << integral
		                                                           << ", must be 1. The pdf over solid angle is "
		                                                              "pdf_texel * w * h / (2 pi^2 sin theta) (handout §7.4)");
		CHECK(integral == Approx(1.0).epsilon(1e-3));
	}
}

TEST_CASE("Image::sample draws directions with the density Image::pdf (chi-square)", "[id:t7.importance.sample-chi2][statistical:4][task7][importance][fn:Image::sample][uses:Image (tables)][uses:Image::pdf][uses:uv_to_direction]") {
	// Four of the grader's CHI2_TESTS. The cells refine the texel grid 2 x 2, so each cell lies in one
	// texel, where pdf * sin(theta) is constant and the expected counts are exact.
	const Named_Map maps[] = {{"one bright texel", inner_texel_map()},
	                          {"one bright texel at the seam and the pole", one_texel_map(32, 16, 0, 0)},
	                          {"a gradient", gradient_map()},
	                          {"a sky with a sun", sky_map()}};
	std::vector<stats::Sphere_Chi2_Settings> settings(std::size(maps));
	for (size_t i = 0; i < settings.size(); i++) {
		settings[i].theta_cells = 2 * maps[i].image.h;
		settings[i].phi_cells = 2 * maps[i].image.w;
		settings[i].integration_resolution = 2;
		settings[i].seed = judge::secret_seed_or(700 + i);
	}
	auto request = [&](size_t i) {
		return protocol::Image_Sampler{maps[i].image, unit_points(settings[i].seed, settings[i].samples),
		                               stats::sphere_chi2_pdf_directions(settings[i])};
	};
	std::vector<stats::Sphere_Chi2_Result> results(std::size(maps));
	auto count = [&](size_t i, const protocol::Image_Sampler::Answer& answer) {
		results[i] = stats::sphere_chi2(answer.queries.samples, answer.queries.pdfs, settings[i]);
	};
	ask_each_while_using_the_last(std::size(maps), request, count);
	for (size_t i = 0; i < results.size(); i++) {
		const double alpha = judge::significance(); // one chi-square test per map
		INFO("importance samples of " << maps[i].name << " must follow Image::pdf: choose a texel by the cdf, a "
		     "uniform point inside it in uv, and let pdf divide by 2 pi^2 sin(theta) (handout §7.4). "
		     << results[i].summary() << "; significance " << alpha);
		CHECK(results[i].pass(alpha));
	}
}

TEST_CASE("a constant map: the weights L / pdf average 4 pi L and stay below twice that", "[id:t7.importance.constant-map][statistical:4][estimate][task7][importance][uses:Image::sample][uses:Image::pdf]") {
	// E[L / pdf] = integral of L over the sphere = 4 pi L for any correct pdf (three of the grader's
	// z-tests). A weight is 4 pi L sin(theta) / sin(theta_row) up to the table's normalization;
	// sin(theta) / sin(theta_row) < 2 in the rows at the poles (sin(2x) / sin(x) = 2 cos(x) with the
	// row's centre, and Delta cot(Delta / 2) with its mean), about 1 elsewhere. With a grading seed
	// each channel of L is drawn in [0.2, 3].
	Spectrum L{0.5f, 1.0f, 2.0f};
	if (std::optional<RNG> secret = judge::secret_inputs()) {
		RNG& rng = *secret;
		L = Spectrum{0.2f + 2.8f * rng.unit(), 0.2f + 2.8f * rng.unit(), 0.2f + 2.8f * rng.unit()};
	}
	const size_t N = 200000;
	const HDR_Image map(32, 16, L);
	const uint64_t seed = judge::secret_seed_or(76);
	// The reference's weights are drawn while the subject samples.
	auto reference_drawn = std::async(std::launch::async, [&] { return reference_weights(map, seed, N); });
	Env_Samples samples = student_env_samples(map, true, unit_points(seed, N));
	std::array<std::vector<double>, 3> weights;
	size_t not_finite = 0, too_large = 0;
	std::string first_large;
	for (size_t n = 0; n < N; n++) {
		Vec3 d = samples.directions[n];
		float pdf = samples.pdfs[n];
		Spectrum weight = pdf > 0.0f ? samples.radiance[n] / pdf : Spectrum{0.0f}; // a renderer skips pdf = 0
		if (!is_finite(weight)) {
			not_finite++;
			continue;
		}
		if (!(weight.g <= 2.0f * 4.0f * PI_F * L.g * (1.0f + 1e-4f))) {
			if (too_large++ == 0) first_large = "direction " + str(d) + " with pdf " + std::to_string(pdf) + ", weight " + str(weight);
		}
		for (int c = 0; c < 3; c++) weights[c].push_back(double(weight[c]));
	}
	{
		INFO("L / pdf was not finite for " << not_finite << " importance samples of a constant map (handout §7.4)");
		CHECK(not_finite == 0);
	}
	{
		INFO(too_large << " weights L / pdf above 2 * 4 pi L = " << 8.0f * PI_F * L.g << "; first: " << first_large
		               << ". Weight the texels by sin(theta) of their row (handout §7.4)");
		CHECK(too_large == 0);
	}
	if (not_finite > 0) return; // the means and the noise would mislead
	std::array<std::vector<double>, 3> reference = reference_drawn.get();
	std::array<double, 3> rounding;
	for (int c = 0; c < 3; c++) {
		double mean = moments(weights[c]).mean, expected = 4.0 * M_PI * L[c];
		double error = standard_error(moments(reference[c]), N);
		rounding[c] = 1e-5 * expected;
		double critical = judge::z_critical();
		double allowed = critical * error + rounding[c]; // plus float rounding
		INFO("channel " << c << ": mean of L / pdf over " << N << " importance samples of a constant map is " << mean
		                << ", expected 4 pi L = " << expected << " (allowed difference " << allowed << ", "
		                << critical << " standard errors of the reference's estimate). sample, pdf and evaluate "
		                << "must agree (handout §7.4)");
		CHECK(std::abs(mean - expected) <= allowed);
	}
	Paired_Noise noise = compare_noise(weights, reference, judge::significance(), rounding);
	INFO("importance samples of a constant map: too noisy: " << describe(noise, "batch")
	     << ". The table must weight texels by luminance * sin(theta) and pdf must be what sample draws (handout §7.4)");
	CHECK(noise.pass);
}

TEST_CASE("a black map still gives valid samples and a normalized pdf", "[id:t7.importance.black-map][task7][importance][fn:Image (tables)][uses:Image::sample][uses:Image::pdf]") {
	// Nothing to importance-sample: the table must not divide by a zero total (handout §7.4).
	HDR_Image black(16, 8);
	std::vector<Vec2> us = unit_points(judge::secret_seed_or(77), 1000);
	std::vector<Vec3> samples = student_image_sampler(black, us, {}).queries.samples;
	std::vector<float> pdfs = student_image_sampler(black, {}, samples).queries.pdfs;
	for (size_t n = 0; n < samples.size(); n++) {
		Vec3 d = samples[n];
		float pdf = pdfs[n];
		INFO("black map: Image::sample = " << str(d) << ", pdf " << pdf
		                                   << "; must be a unit direction with a finite positive pdf: fall back to "
		                                      "choosing texels by solid angle when the total is 0 (handout §7.4)");
		REQUIRE(is_finite(d));
		REQUIRE(glm::length(d) == Approx(1.0f).epsilon(1e-4));
		REQUIRE(std::isfinite(pdf));
		REQUIRE(pdf > 0.0f);
	}
}
