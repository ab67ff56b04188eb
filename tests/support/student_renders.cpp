#include "student_renders.h"

#include "graded_images.h"
#include "graded_variation.h"
#include "image_io.h"
#include "judge.h"
#include "report_record.h"
#include "scene_loader.h"
#include "z_heat_map.h"

#include "lab_catch2.h"

#include <optional>
#include <sstream>

namespace {

// The grade report's picture of a reference-image test: the render and the reference as `./lab
// render` shows them (exposure 0), and where they differ; written as <task>_<scene>_*.png.
void report_images(const std::string& name, const Reference_Check& check) {
	const Image_Comparison& c = check.comparison;
	std::string prefix = report::task_name() + "_" + name;
	std::string render = prefix + "_render.png", reference = prefix + "_reference.png", z_map = prefix + "_z.png";
	write_png(report::file(render), check.render.mean);
	write_png(report::file(reference), check.reference.mean);
	write_png(report::file(z_map), z_heat_map(z_scores(check.render, check.reference), c.z_critical));
	report::attach({{"type", "image_test"}, {"scene", graded_scene_file(name)}, {"render", render},
	                {"reference", reference}, {"z_map", z_map}, {"pass", c.pass && check.non_finite == 0},
	                {"message", c.message + (c.noise.pass ? "" : "; too noisy: " + c.noise_message)},
	                {"non_finite", check.non_finite}, {"failed", c.failed},
	                {"tests", c.tests}, {"z_critical", c.z_critical}, {"rel_mse", c.rel_mse}});
}

// The hints of the functions whose own test cases failed, or else the general one.
std::string chosen_hint(const std::string& hint, const std::vector<Image_Hint>& if_failed) {
	std::string chosen;
	for (const Image_Hint& h : if_failed) {
		if (judge::unit_tests_failed(h.function)) chosen += h.function + " decides " + h.hint + " ";
	}
	return chosen.empty() ? hint : chosen;
}

} // namespace

void check_renders_like_reference(const Image_Test& test) {
	const Graded_Scene& graded = graded_scene(test.name);
	// Under a grading seed, the scene as the seed varies it and the judge's own reference of it
	// (graded_variation.h); in public, the scene file and its stored reference.
	std::optional<nlohmann::ordered_json> varied;
	if (std::optional<RNG> variation = judge::secret_inputs(judge::Secret::graded_scene)) {
		varied = vary_graded_scene(graded, *variation);
	}
	Scene scene = varied ? load_scene(*varied, graded_scene_file(graded.name)) : load_graded(graded);
	Render_Settings settings = scene.settings;
	settings.seed = judge::secret_seed_or(settings.seed);
	Film film = judge::ask(protocol::Render{scene, settings, Estimator_Choice{test.integrator}, graded.view, 2});
	const double alpha = judge::significance(2); // the means' and the noise's checks (image_compare.h)
	Reference_Check check = [&] {
		if (!varied) return compare_with_reference(graded, film, settings, test.integrator, alpha);
		Judge_Reference reference = judge_reference(graded, *varied, settings, test.integrator);
		return compare_with(film, settings, std::move(reference.reference), reference.calibration, alpha);
	}();
	if (report::enabled()) report_images(test.name, check);
	std::ostringstream render_it;
	render_it << " Render it: ./lab render-student scenes/graded/" << test.name << ".json"
	          << (graded.view == View::eye_light ? " --view eye" : "")
	          << (test.integrator == "mixture" ? "" : " --integrator " + test.integrator)
	          << (varied ? " (the grading seed varied this scene: its camera, materials, lights and the places of its "
	                       "objects)"
	                     : "");
	{
		INFO("scenes/graded/" << test.name << ".json: " << check.non_finite
		                      << " samples were NaN or infinite (render with --nan-map to see where)."
		                      << render_it.str());
		CHECK(check.non_finite == 0);
	}
	{
		INFO("scenes/graded/" << test.name << ".json: " << check.comparison.message);
		INFO(chosen_hint(test.hint, test.if_failed) << render_it.str());
		CHECK(check.comparison.means_pass);
	}
	{
		INFO("scenes/graded/" << test.name << ".json: too noisy: " << check.comparison.noise_message << ". "
		                      << test.if_noisy << render_it.str() << " and compare its noise with the reference's "
		                      << "(--variance FILE.exr writes the per-pixel variance).");
		CHECK(check.comparison.noise.pass);
	}
}
