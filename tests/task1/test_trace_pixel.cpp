// Task 1, handout §1.3: Pathtracer::trace_pixel, one supersampling sample per call. In the
// View::direction debug view, trace() returns the colour 0.5 (d + 1) of the camera ray's
// direction d (framework/render/pathtracer.cpp), so the grader can recover the film point of every
// sample from the reference camera's film plane (camera_check.h) and look at where in the pixel it
// fell.
#include "camera_check.h"
#include "judge.h"
#include "pathtracer.h"
#include "statistics.h"

#include "lab_catch2.h"

#include <algorithm>
#include <sstream>

using namespace task1;
using protocol::Trace_Pixels;

namespace {

constexpr uint32_t WIDTH = 64, HEIGHT = 48;

// The render seed: public, or drawn from the grading seed.
uint64_t render_seed() {
	return judge::secret_seed_or(20240917);
}

// The pixels whose samples are tested for uniformity.
const std::vector<std::pair<uint32_t, uint32_t>> STAT_PIXELS{{0, 0}, {37, 22}, {WIDTH - 1, HEIGHT - 1}};

// Recovering d from the float colour loses ~1e-7 per component, about 1e-5 of a pixel here; a
// sample more than 1e-3 pixel outside its pixel is a real error.
constexpr double PIXEL_TOLERANCE = 1e-3;

Scene direction_scene() {
	Scene scene;
	Vec3 position{1.0f, 2.0f, 3.0f};
	float v_fov = 50.0f;
	if (std::optional<RNG> secret = judge::secret_inputs()) {
		position = 5.0f * (Vec3(secret->unit(), secret->unit(), secret->unit()) + 0.2f);
		v_fov = 20.0f + 100.0f * secret->unit();
	}
	scene.camera = Camera::look_at(position, Vec3{0.0f}, Vec3{0.0f, 1.0f, 0.0f}, v_fov, float(WIDTH) / float(HEIGHT));
	scene.settings.width = WIDTH;
	scene.settings.height = HEIGHT;
	return scene;
}

Render_Settings film_settings() {
	Render_Settings settings;
	settings.width = WIDTH;
	settings.height = HEIGHT;
	settings.seed = render_seed();
	return settings;
}

struct Sample {
	DVec3 dir;   // the camera ray's direction, recovered from the colour
	DVec2 pixel; // where it crosses the film, in pixel units (x in [0, WIDTH), y in [0, HEIGHT))
	bool valid;  // the colour decodes to a unit direction
};

using Pixel = std::pair<uint32_t, uint32_t>;

// Samples 0 .. n - 1 of each pixel, seeded as the renderer seeds them (framework/render/render.cpp), from
// the student's trace_pixel in one request.
std::vector<std::vector<Sample>> sample_pixels(const Scene& scene, const std::vector<Pixel>& pixels, uint32_t n) {
	Trace_Pixels request{scene, film_settings(), Estimator_Choice{}, View::direction, {}};
	uint64_t seed = request.settings.seed;
	for (auto [x, y] : pixels) {
		for (uint32_t s = 0; s < n; s++) {
			request.samples.push_back({x, y, RNG_State::of(RNG::for_sample(seed, size_t(y) * WIDTH + x, s))});
		}
	}
	std::vector<Spectrum> colours = judge::ask(request);
	Film_Plane plane(scene.camera);
	std::vector<std::vector<Sample>> samples(pixels.size());
	for (size_t i = 0; i < colours.size(); i++) {
		Sample sample;
		sample.dir = 2.0 * DVec3(colours[i]) - 1.0;
		sample.valid = std::abs(glm::length(sample.dir) - 1.0) < 1e-5;
		DVec2 uv = plane.film_uv(sample.dir);
		sample.pixel = DVec2(uv.x * WIDTH, uv.y * HEIGHT);
		samples[i / n].push_back(sample);
	}
	return samples;
}

bool inside(DVec2 offset, double lo, double hi) {
	return offset.x >= lo - PIXEL_TOLERANCE && offset.x <= hi + PIXEL_TOLERANCE && offset.y >= lo - PIXEL_TOLERANCE &&
	       offset.y <= hi + PIXEL_TOLERANCE;
}

constexpr int CELLS = 8; // histogram cells per axis of a pixel

// Where n samples of pixel (x, y) fall, as offsets from its corner (x, y): inside the pixel they
// are in [0, 1)^2.
struct Offsets {
	std::vector<double> histogram = std::vector<double>(CELLS * CELLS, 0.0); // of those inside, row-major
	DVec2 sum{0.0};                    // of the offsets inside
	DVec2 lo{INFINITY}, hi{-INFINITY}; // range of all decodable offsets, inside or not
	size_t outside = 0;                // decodable samples outside the pixel
	size_t in_mirrored_row = 0;        // ... of which inside pixel (x, HEIGHT - 1 - y)
	size_t undecodable = 0;            // colours that are not 0.5 (d + 1) of a unit d
	Spectrum bad_colour{0.0f};         // the first of those
};

Offsets collect_offsets(const std::vector<Sample>& samples, uint32_t x, uint32_t y) {
	Offsets result;
	for (const Sample& sample : samples) {
		if (!sample.valid) {
			if (result.undecodable++ == 0) result.bad_colour = Spectrum(0.5 * (sample.dir + 1.0));
			continue;
		}
		DVec2 offset = sample.pixel - DVec2(x, y);
		result.lo = glm::min(result.lo, offset);
		result.hi = glm::max(result.hi, offset);
		if (!inside(offset, 0.0, 1.0)) {
			result.outside++;
			result.in_mirrored_row += inside(sample.pixel - DVec2(x, HEIGHT - 1 - y), 0.0, 1.0);
			continue;
		}
		result.sum += offset;
		int cx = std::clamp(int(offset.x * CELLS), 0, CELLS - 1), cy = std::clamp(int(offset.y * CELLS), 0, CELLS - 1);
		result.histogram[size_t(cy * CELLS + cx)] += 1.0;
	}
	return result;
}

// Why samples of pixel (x, y) are not all inside it ("" if they are), in the handout's terms.
std::string outside_problem(const Offsets& o, uint32_t x, uint32_t y, uint32_t n) {
	std::ostringstream why;
	if (o.undecodable > 0) {
		why << o.undecodable << " of " << n << " calls trace_pixel(" << x << ", " << y << ") returned colours such as "
		    << show(DVec3(o.bad_colour)) << ". It must return trace(rng, ray) of the camera ray through the sample, "
		       "which in this debug view is the colour 0.5 (d + 1) of the ray's unit direction d (handout §1.3)";
		return why.str();
	}
	if (o.outside == 0) return "";
	why << o.outside << " of " << n << " samples of pixel (" << x << ", " << y << ") fell outside [" << x << ", "
	    << x + 1 << ") x [" << y << ", " << y + 1 << "); their offsets from the corner (x, y) ranged over [" << o.lo.x
	    << ", " << o.hi.x << "] x [" << o.lo.y << ", " << o.hi.y << "]: ";
	if (o.in_mirrored_row == o.outside) {
		why << "they landed in row " << HEIGHT - 1 - y << " instead. Row y = 0 is the TOP of the image, film v grows "
		       "downwards like the rows (handout §1.1)";
	} else if (inside(o.lo, 0.5, 1.5) && inside(o.hi, 0.5, 1.5)) {
		why << "the random offset was added to the pixel centre. Pixel (x, y) covers [x, x + 1) x [y, y + 1): the "
		       "sample is (x + u1, y + u2) with (u1, u2) = rng.unit2() in [0, 1)^2 (handout §1.3)";
	} else if (inside(o.lo, -0.5, 0.5) && inside(o.hi, -0.5, 0.5)) {
		why << "the samples are centred on the pixel's corner (x, y). Pixel (x, y) covers [x, x + 1) x [y, y + 1): "
		       "its centre is (x + 0.5, y + 0.5) (handout §1.3)";
	} else {
		why << "film_uv must be ((x + u1) / width, (y + u2) / height) with settings.width and settings.height "
		       "(handout §1.3). If generate_ray's test cases fail too, fix those first";
	}
	return why.str();
}

} // namespace

TEST_CASE("trace_pixel: every sample of pixel (x, y) falls inside that pixel, in any corner of the film", "[id:t1.pixel.inside][fn:trace_pixel][uses:generate_ray]") {
	const std::vector<Pixel> pixels{{0, 0}, {WIDTH - 1, 0}, {0, HEIGHT - 1}, {WIDTH - 1, HEIGHT - 1}, {17, 29}, {40, 3}};
	std::vector<std::vector<Sample>> samples = sample_pixels(direction_scene(), pixels, 2000);
	for (size_t i = 0; i < pixels.size(); i++) {
		auto [x, y] = pixels[i];
		std::string problem = outside_problem(collect_offsets(samples[i], x, y), x, y, 2000);
		INFO(problem);
		CHECK(problem.empty());
		if (!problem.empty()) return;
	}
}

TEST_CASE("trace_pixel: samples are uniform over the pixel around its centre (x + 0.5, y + 0.5)", "[id:t1.pixel.uniform][statistical:9][estimate][fn:trace_pixel][uses:generate_ray]") {
	// 10^5 samples per pixel in 8 x 8 cells (expected 1562.5 per cell): a chi-square test of
	// uniformity, and z-tests that the mean offset is the pixel centre 0.5 (variance 1/12 per axis):
	// three statistical checks per pixel.
	constexpr uint32_t N = 100000;
	std::vector<std::vector<Sample>> samples = sample_pixels(direction_scene(), STAT_PIXELS, N);
	for (size_t i = 0; i < STAT_PIXELS.size(); i++) {
		auto [x, y] = STAT_PIXELS[i];
		CAPTURE(x, y);
		Offsets offsets = collect_offsets(samples[i], x, y);
		{
			std::string problem = outside_problem(offsets, x, y, N);
			INFO(problem);
			REQUIRE(problem.empty());
		}
		DVec2 lo = offsets.lo, hi = offsets.hi;
		bool no_jitter = hi.x - lo.x < 1e-2 && hi.y - lo.y < 1e-2;
		std::vector<double> expected(CELLS * CELLS, double(N) / (CELLS * CELLS));
		stats::Chi2_Result chi2 = stats::chi2_test(offsets.histogram, expected);
		{
			const double alpha = judge::significance();
			INFO((no_jitter ? "no jitter: supersampling needs a uniformly random point in the pixel (handout §1.3)"
			                : "the points chosen in the pixel are not uniform: take (x + u1, y + u2) with (u1, u2) = "
			                  "rng.unit2(), two independent numbers, one per axis (handout §1.3)")
			     << ". Offsets within the pixel ranged over [" << lo.x << ", " << hi.x << "] x [" << lo.y << ", "
			     << hi.y << "]; chi-square = " << chi2.statistic << " with " << chi2.dof << " degrees of freedom, p = "
			     << chi2.p_value << ", alpha = " << alpha);
			CHECK(chi2.p_value >= alpha);
		}
		DVec2 mean = offsets.sum / double(N);
		double sigma = std::sqrt(1.0 / 12.0 / N);
		const double z_max = judge::z_critical(2); // the two axes' z-tests
		INFO("the mean offset within the pixel is (" << mean.x << ", " << mean.y << "); uniform points in the pixel "
		     "average to its centre (0.5, 0.5) +- " << z_max * sigma << ". Pixel (x, y) covers [x, x + 1) x [y, y + 1) "
		     "(handout §1.3)");
		CHECK(std::abs(mean.x - 0.5) / sigma <= z_max);
		CHECK(std::abs(mean.y - 0.5) / sigma <= z_max);
	}
}
