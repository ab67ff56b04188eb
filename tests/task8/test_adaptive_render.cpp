// Task 8, handout §8.4: an adaptive render with the student's stopping rule and batch loop (tasks 1-7
// the reference's). The grader draws every pixel's samples itself, as the framework draws them (the
// same generators, in the same order), so it knows where the rule stops each pixel; and it compares
// the image with the reference's adaptive render at another seed, by z-tests whose standard errors
// come from the stored reference of the graded scene.
#include "adaptive_spec.h"
#include "estimator.h"
#include "graded_images.h"
#include "image_io.h"
#include "judge.h"
#include "report_record.h"
#include "sample_rate_map.h"
#include "sampler.h"

#include "lab_catch2.h"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using namespace task8;

namespace {

const char* SCENE = "cornell_diffuse";
constexpr uint32_t MAX_SAMPLES = 128; // a pixel's most: twice the graders' 64
constexpr float THRESHOLD = 0.3f;

struct Adaptive_Case {
	Scene scene;
	Render_Settings settings;
	Adaptive_Sampling rule;
	Film film{0, 0};      // the student's render
	Film reference{0, 0}; // the reference's, at another seed
	// Where the rule stops each pixel, from the samples the grader drew itself (0: too close to call).
	std::vector<uint32_t> expected;
};

std::vector<uint32_t> expected_stops(const Scene& scene, const Render_Settings& settings, const Adaptive_Sampling& rule) {
	Pathtracer pathtracer(scene, settings);
	Sampler sampler = pathtracer.estimator().choice.sampler;
	std::vector<uint32_t> stops(size_t(settings.width) * settings.height);
	for (uint32_t y = 0; y < settings.height; y++) {
		for (uint32_t x = 0; x < settings.width; x++) {
			size_t index = size_t(y) * settings.width + x;
			// The pixel's samples as the framework draws them, until the rule stops it.
			Sample_Stream samples = [&](uint32_t s) {
				RNG rng = generator_for_sample(settings.seed, index, s, sampler);
				Spectrum sample = pathtracer.trace_pixel(x, y, rng);
				return is_finite(sample) ? double(::luminance(sample)) : NAN;
			};
			stops[index] = expected_stop_of(rule, settings.samples, samples).value_or(0);
		}
	}
	return stops;
}

// The student's adaptive render of the graded scene, at a seed of the grader's (public, or drawn
// from the grading seed), and where the rule stops each of its pixels.
const Adaptive_Case& adaptive_case() {
	static Adaptive_Case c = [] {
		Adaptive_Case c;
		c.scene = load_graded(graded_scene(SCENE));
		c.settings = c.scene.settings;
		c.settings.samples = MAX_SAMPLES;
		c.settings.seed = judge::secret_seed_or(c.settings.seed);
		c.rule.threshold = THRESHOLD;
		protocol::Adaptive_Render request{c.scene, c.settings, on_wire(c.rule), 2};
		c.film = judge::ask(request);
		c.expected = expected_stops(c.scene, c.settings, c.rule);
		Render_Settings other = c.settings;
		other.seed = c.settings.seed + 1;
		Render_Options options;
		options.adaptive = c.rule;
		c.reference = render(Pathtracer(c.scene, other), options);
		return c;
	}();
	return c;
}

uint32_t taken(const Pixel_Stats& pixel) {
	return pixel.count + pixel.non_finite;
}

// For the grade report: the render's rate map beside the one the rule gives (where a pixel's
// decision was too close to call, the render's own count).
void report_rate_maps(const Adaptive_Case& c) {
	Film expected = c.film;
	for (size_t i = 0; i < expected.pixels.size(); i++) {
		if (c.expected[i] == 0) continue;
		expected.pixels[i].count = c.expected[i];
		expected.pixels[i].non_finite = 0;
	}
	std::string render = report::task_name() + "_rate_map.png", rule = report::task_name() + "_rate_map_rule.png";
	write_png(report::file(render), sample_rate_map(c.film, MAX_SAMPLES));
	write_png(report::file(rule), sample_rate_map(expected, MAX_SAMPLES));
	std::ostringstream most;
	most << MAX_SAMPLES;
	report::attach({{"type", "figures"},
	                {"figures",
	                 {{{"file", render}, {"caption", "The samples each pixel of your render took (black none, white " + most.str() + ")"}},
	                  {{"file", rule}, {"caption", "The samples the rule gives each pixel"}}}}});
}

} // namespace

TEST_CASE("adaptive render: each pixel takes the samples the rule gives it",
          "[id:t8.render.rate-map][task8][uses:Adaptive_Sampling::sample_pixel][uses:Adaptive_Sampling::pixel_converged]") {
	const Adaptive_Case& c = adaptive_case();
	if (report::enabled()) report_rate_maps(c);
	size_t compared = 0, wrong = 0;
	std::string first;
	for (uint32_t y = 0; y < c.settings.height; y++) {
		for (uint32_t x = 0; x < c.settings.width; x++) {
			size_t index = size_t(y) * c.settings.width + x;
			if (c.expected[index] == 0) continue;
			compared++;
			uint32_t got = taken(c.film.pixels[index]);
			if (got == c.expected[index]) continue;
			if (wrong++ == 0) {
				std::ostringstream out;
				out << "pixel (" << x << ", " << y << ") took " << got << " samples; its samples stop the rule at "
				    << c.expected[index];
				first = out.str();
			}
		}
	}
	INFO("The adaptive render of " << SCENE << " (threshold " << THRESHOLD << ", at most " << MAX_SAMPLES
	     << " samples, ./lab render " << graded_scene_file(SCENE) << " --adaptive " << THRESHOLD << " --spp "
	     << MAX_SAMPLES << " --view samples shows the rate map): " << first << "; " << wrong << " of " << compared
	     << " pixels took another number of samples than the rule gives them (handout §8.4)");
	CHECK(wrong == 0);
	CHECK(compared >= c.expected.size() * 9 / 10);
	double mean = 0.0;
	for (const Pixel_Stats& pixel : c.film.pixels) mean += taken(pixel);
	std::ostringstream figure;
	figure << mean / double(c.film.pixels.size()) << " of at most " << MAX_SAMPLES;
	judge::key_figure("samples per pixel", figure.str());
}

TEST_CASE("adaptive render: the image matches the reference's within the z-tests of its blocks",
          "[id:t8.render.image][task8][statistical:192][uses:Adaptive_Sampling::sample_pixel][uses:Adaptive_Sampling::pixel_converged]") {
	// The render against the reference's adaptive render at another seed, which has the same bias
	// (handout §8.1). Per block of 8 x 8 pixels and channel, the mean of the pixel means: with n_i
	// and m_i the samples pixel i takes in the render (as the rule gives them) and in the
	// reference's, and s_i^2 the per-sample variance of the stored reference image (a uniform render
	// of 4096 samples), the difference has variance sum_i s_i^2 (1 / n_i + 1 / m_i) / 64^2: the
	// reference's variance, never the render's. It errs on the safe side: the reference against
	// itself over 100 grading seeds gave 19 200 z with mean 0.004 and standard deviation 0.87.
	const Adaptive_Case& c = adaptive_case();
	const uint32_t BLOCK = 8;
	Image_Estimate variance = read_reference(graded_scene(SCENE), c.scene.settings);
	size_t blocks = size_t(c.settings.width / BLOCK) * (c.settings.height / BLOCK);
	double z_critical = judge::z_critical(3 * blocks);
	double worst = 0.0;
	std::string where;
	for (uint32_t by = 0; by + BLOCK <= c.settings.height; by += BLOCK) {
		for (uint32_t bx = 0; bx + BLOCK <= c.settings.width; bx += BLOCK) {
			for (int channel = 0; channel < 3; channel++) {
				double difference = 0.0, sum_of_variances = 0.0;
				for (uint32_t y = by; y < by + BLOCK; y++) {
					for (uint32_t x = bx; x < bx + BLOCK; x++) {
						size_t i = size_t(y) * c.settings.width + x;
						const Pixel_Stats& pixel = c.film.pixels[i];
						uint32_t n = c.expected[i] ? c.expected[i] : std::max(1u, taken(pixel));
						uint32_t m = std::max(1u, taken(c.reference.pixels[i]));
						difference += pixel.mean[channel] - c.reference.pixels[i].mean[channel];
						sum_of_variances += variance.variance.pixels[i][channel] * (1.0 / n + 1.0 / m);
					}
				}
				double z = sum_of_variances > 0.0 ? difference / std::sqrt(sum_of_variances)
				                                  : (difference == 0.0 ? 0.0 : INFINITY);
				if (std::abs(z) > std::abs(worst) || std::isnan(z)) {
					worst = z;
					std::ostringstream out;
					out << "the block of pixels (" << bx << ", " << by << ") to (" << bx + BLOCK - 1 << ", "
					    << by + BLOCK - 1 << "), channel " << "RGB"[channel];
					where = out.str();
				}
			}
		}
	}
	INFO("The adaptive render of " << SCENE << " (threshold " << THRESHOLD << ", at most " << MAX_SAMPLES
	     << " samples) against the reference's: " << where << " is off by z = " << worst << ", beyond "
	     << z_critical << ". Which samples a pixel takes decides nothing but when it stops (handout §8.4)");
	CHECK(std::abs(worst) <= z_critical);
	std::ostringstream figure;
	figure << std::abs(worst) << " (at most " << z_critical << ")";
	judge::key_figure("largest |z| of a block", figure.str());
}
