// The ray lifecycle (--follow-pixel): it shows the paths the renderer really takes.
#include "follow_pixel.h"
#include "furnace_scenes.h"
#include "lifecycle.h"

#include "lab_catch2.h"

#include <sstream>

namespace {
// A diffuse sphere lit by a uniform environment, seen from outside: every path that hits the
// sphere bounces and escapes.
Scene lit_sphere() {
	Furnace_Options options;
	options.environment = Spectrum{1.0f};
	return sphere_seen_from_outside(diffuse_material(Spectrum{0.5f}), options, 4.0f, 30.0f);
}

Render_Settings small_settings() {
	Render_Settings settings;
	settings.width = settings.height = 9;
	settings.samples = 4;
	settings.max_depth = 3;
	settings.seed = 7;
	return settings;
}
} // namespace

TEST_CASE("follow_pixel prints the value the renderer computes for each sample", "[lifecycle]") {
	Scene scene = lit_sphere();
	Pathtracer pathtracer(scene, small_settings());
	std::ostringstream out;
	follow_pixel(pathtracer, 4, 4, 4, out);
	std::string text = out.str();

	for (uint32_t s = 0; s < 4; s++) {
		RNG rng = RNG::for_sample(7, 4 * 9 + 4, s); // the generator render() uses for this sample
		Spectrum value = pathtracer.trace_pixel(4, 4, rng);
		std::ostringstream expected;
		expected << "sample " << s << ": value " << format_vec(value);
		INFO("expected the line '" << expected.str() << "' in:\n" << text);
		CHECK(text.find(expected.str()) != std::string::npos);
	}
}

TEST_CASE("follow_pixel shows each ray's hit, the BSDF sample and the weights", "[lifecycle]") {
	Scene scene = lit_sphere();
	Pathtracer pathtracer(scene, small_settings());
	std::ostringstream out;
	follow_pixel(pathtracer, 4, 4, 4, out); // the centre pixel sees the sphere
	std::string text = out.str();
	INFO(text);
	CHECK(text.find("ray depth 0: origin") != std::string::npos);
	CHECK(text.find("dist_bounds [0, inf]") != std::string::npos);
	CHECK(text.find("hit object 0") != std::string::npos);
	// Task 6 samples either the BSDF or the lights (here the environment), and evaluates both pdfs.
	bool sampled = text.find("BSDF sample (lambertian, continuous)") != std::string::npos ||
	               text.find("light sample (environment)") != std::string::npos;
	CHECK(sampled);
	CHECK(text.find("BSDF pdf(out, in") != std::string::npos);
	CHECK(text.find("ray depth 1: origin") != std::string::npos);
	CHECK(text.find("missed the scene (environment)") != std::string::npos);
	// Under a uniform environment of radiance 1 the light returned by the bounce is 1, so the
	// weight the estimator applied is exactly the sample's value, and the throughput shows it.
	CHECK(text.find("weight applied to the next ray's light") != std::string::npos);
	CHECK(text.find("(? in a weight or throughput: no light came back") != std::string::npos); // what '?' means
}

TEST_CASE("Nothing is recorded unless a pixel is followed", "[lifecycle]") {
	CHECK(Render_Observer::active() == nullptr);
	{
		Lifecycle_Recorder recorder;
		CHECK(Render_Observer::active() == &recorder);
	}
	CHECK(Render_Observer::active() == nullptr);
}
