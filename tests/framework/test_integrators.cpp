// Every estimator of the renderer estimates the same image, on every shipped scene (image z-tests,
// framework/film/image_compare.h): next-event estimation with MIS (--integrator nee), lights chosen
// by power or by the light tree (--light-choice power|tree) and low-discrepancy samples (--sampler
// sobol) against the lab's estimator (task 4 with task 6's mixture, lights chosen uniformly,
// independent samples).
//
// The z-tests need each image's variance of the mean (compare_estimators: both estimators are the
// lab's own, so each image's variance counts, unlike a grader's comparison of a submission). With
// independent samples it is the film's per-sample variance s^2 over n. With low-discrepancy samples
// it is not: a pixel's samples are spread evenly on purpose, so s^2 / n overstates the error of
// their mean by an unknown factor (and for some integrands Owen-scrambled nets understate it, by up
// to e; Owen 1997). So the low-discrepancy image is the mean of R renders with independent seeds
// (independent scramblings), and its variance is that of the R render means: an honest estimate
// whatever the sampler does within a render. The graders and the stored references use independent
// samples for the same reason (Estimator_Choice's default).
#include "estimator.h"
#include "image_compare.h"
#include "render.h"
#include "scene_loader.h"

#include "lab_catch2.h"

#include <filesystem>
#include <vector>

namespace {

constexpr uint32_t WIDTH = 32, SPP = 256, REPLICATES = 16;

// Tested on its own (below): the lab's estimator finds its 120 small, bright lamps mostly by BSDF
// samples, rare and each worth up to 2 albedo x radiance (about 400 times a pixel's mean), a heavy
// tail whose variance 256 samples underestimate: a render of it made the light tree's image look
// 10 standard errors too dark in one pixel, where the lab's own render at 1024 samples was the one
// 15 % too bright.
const char* const MANY_LIGHTS = "many_lights.json";

std::vector<std::string> shipped_scenes() {
	std::vector<std::string> scenes;
	for (const auto& entry : std::filesystem::directory_iterator("scenes"))
		if (entry.path().extension() == ".json" && entry.path().filename() != MANY_LIGHTS)
			scenes.push_back(entry.path().string());
	std::sort(scenes.begin(), scenes.end());
	return scenes;
}

// A render: the scene's own settings (depth, roulette) on a small film of its aspect ratio, by an
// estimator.
struct Setup {
	Render_Settings settings;
	Estimator_Choice estimator;
};

Setup small(const Scene& scene, const char* integrator, Light_Choice choice, Sampler sampler) {
	Render_Settings settings = scene.settings;
	settings.width = WIDTH;
	settings.height = std::max(1u, uint32_t(std::lround(double(WIDTH) * scene.settings.height / scene.settings.width)));
	settings.samples = SPP;
	settings.seed = 1;
	return Setup{settings, Estimator_Choice{integrator, sampler, choice}};
}

Image_Estimate rendered(const Scene& scene, const Setup& setup) {
	return Image_Estimate::from(render(Pathtracer(scene, setup.settings, View::path, setup.estimator)));
}

// The mean of REPLICATES renders of SPP / REPLICATES samples with seeds of their own, as an image
// of REPLICATES "samples": each render's mean is one, with their variance per pixel.
Image_Estimate replicated(const Scene& scene, const Setup& setup) {
	Render_Settings settings = setup.settings;
	settings.samples = SPP / REPLICATES;
	std::vector<HDR_Image> means;
	for (uint32_t r = 0; r < REPLICATES; r++) {
		settings.seed = 100 + r;
		means.push_back(render(Pathtracer(scene, settings, View::path, setup.estimator)).mean());
	}
	HDR_Image mean(settings.width, settings.height), variance(settings.width, settings.height);
	for (size_t i = 0; i < mean.pixels.size(); i++) {
		glm::dvec3 sum{0.0}, sum2{0.0};
		for (const HDR_Image& m : means) {
			sum += glm::dvec3(m.pixels[i]);
			sum2 += glm::dvec3(m.pixels[i]) * glm::dvec3(m.pixels[i]);
		}
		glm::dvec3 mu = sum / double(REPLICATES);
		mean.pixels[i] = Spectrum(mu);
		variance.pixels[i] = Spectrum(glm::max((sum2 - double(REPLICATES) * mu * mu) / double(REPLICATES - 1), 0.0));
	}
	return Image_Estimate::uniform(std::move(mean), std::move(variance), HDR_Image{}, REPLICATES);
}

// The lab's image (the noisier, first: compare_estimators takes the larger per-sample variance for it)
// against another estimator's.
void check_agree(const Image_Estimate& lab, const Image_Estimate& other, const std::string& what) {
	Image_Comparison c = compare_estimators(lab, other);
	INFO(what << ": " << c.message);
	CHECK(c.pass);
}

} // namespace

TEST_CASE("every estimator renders the same image of every shipped scene", "[integrators]") {
	for (const std::string& file : shipped_scenes()) {
		Scene scene = load_scene(file);
		Image_Estimate lab = rendered(scene, small(scene, "mixture", Light_Choice::uniform, Sampler::independent));
		check_agree(lab, rendered(scene, small(scene, "nee", Light_Choice::power, Sampler::independent)),
		            file + ": next-event estimation with MIS, lights chosen by power");
		check_agree(lab, rendered(scene, small(scene, "mixture", Light_Choice::power, Sampler::independent)),
		            file + ": the mixture, lights chosen by power");
		check_agree(lab, rendered(scene, small(scene, "nee", Light_Choice::uniform, Sampler::independent)),
		            file + ": next-event estimation with MIS, lights chosen uniformly");
		check_agree(lab, rendered(scene, small(scene, "nee", Light_Choice::tree, Sampler::independent)),
		            file + ": next-event estimation with MIS, lights chosen by the light tree");
		check_agree(lab, rendered(scene, small(scene, "mixture", Light_Choice::tree, Sampler::independent)),
		            file + ": the mixture, lights chosen by the light tree");
		check_agree(lab, replicated(scene, small(scene, "nee", Light_Choice::power, Sampler::sobol)),
		            file + ": next-event estimation with MIS and low-discrepancy samples (16 renders)");
		check_agree(lab, replicated(scene, small(scene, "nee", Light_Choice::tree, Sampler::sobol)),
		            file + ": next-event estimation with MIS, the light tree and low-discrepancy samples (16 renders)");
		check_agree(lab, replicated(scene, small(scene, "mixture", Light_Choice::uniform, Sampler::sobol)),
		            file + ": the mixture with low-discrepancy samples (16 renders)");
	}
}

TEST_CASE("on 120 small lamps the light tree renders the image that choice by power renders", "[integrators]") {
	// The baseline is next-event estimation with lights chosen by power, whose light samples find
	// the lamps (the lab's estimator's tail, above, is too heavy for a z-test), with 4 x SPP samples.
	Scene scene = load_scene(std::string("scenes/") + MANY_LIGHTS);
	Setup baseline = small(scene, "nee", Light_Choice::power, Sampler::independent);
	baseline.settings.samples = 4 * SPP;
	Image_Estimate by_power = rendered(scene, baseline);
	Setup nee = small(scene, "nee", Light_Choice::tree, Sampler::independent);
	nee.settings.samples = 4 * SPP;
	check_agree(by_power, rendered(scene, nee), "next-event estimation with MIS, lights chosen by the light tree");
	Setup mixture = small(scene, "mixture", Light_Choice::tree, Sampler::independent);
	mixture.settings.samples = 4 * SPP;
	check_agree(rendered(scene, mixture), by_power, "the mixture, lights chosen by the light tree");
	check_agree(by_power, replicated(scene, small(scene, "nee", Light_Choice::tree, Sampler::sobol)),
	            "next-event estimation with MIS, the light tree and low-discrepancy samples (16 renders)");
}

TEST_CASE("the image comparison tells an estimator with a 5 % brighter light apart", "[integrators]") {
	// The test above can fail: renders of the Cornell box whose light is 5 % brighter are caught, by
	// either variance estimate.
	Scene scene = load_scene("scenes/cornell_box.json");
	Image_Estimate lab = rendered(scene, small(scene, "mixture", Light_Choice::uniform, Sampler::independent));
	for (Material& material : scene.materials) material.emission *= 1.05f;
	Image_Comparison independent =
		compare_estimators(lab, rendered(scene, small(scene, "nee", Light_Choice::power, Sampler::independent)));
	Image_Comparison low_discrepancy =
		compare_estimators(lab, replicated(scene, small(scene, "nee", Light_Choice::power, Sampler::sobol)));
	INFO("independent samples: " << independent.message << "\nlow-discrepancy samples: " << low_discrepancy.message);
	CHECK_FALSE(independent.pass);
	CHECK_FALSE(low_discrepancy.pass);
}
