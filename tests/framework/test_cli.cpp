// The renderer's command line (framework/cli/cli.h) and its progress bar (framework/cli/terminal.h):
// --help explains everything, bad input gives one "error:" line and writes nothing, a render
// writes the images it reports.
#include "cli.h"
#include "cli_options.h"
#include "film_file.h"
#include "image_io.h"
#include "scene_loader.h"
#include "temp_dir.h"
#include "terminal.h"

#include "lab_catch2.h"
#include <stb/stb_image.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace fs = std::filesystem;

namespace {

// A small scene (format: scenes/README.md): a grey sphere in front of the camera under a white
// sky, film 16 x 12.
const char* const SPHERE_SCENE = R"({
	"camera": {"position": [0, 0, 3], "target": [0, 0, 0], "up": [0, 1, 0], "vertical_fov": 50},
	"film": {"width": 16, "height": 12, "samples": 2, "max_depth": 3, "seed": 1},
	"materials": {"grey": {"type": "lambertian", "albedo": [0.6, 0.6, 0.6]}},
	"objects": [{"type": "sphere", "radius": 1, "material": "grey"}],
	"environment": {"type": "constant", "radiance": [1, 1, 1]}
})";

// Runs the tests of this file inside a fresh directory, so that default outputs (out/...) land
// there and can be seen; restores the working directory afterwards.
class In_Temp_Dir {
public:
	In_Temp_Dir() : previous(fs::current_path()) {
		fs::current_path(dir.path());
		std::ofstream("sphere.json") << SPHERE_SCENE;
		std::ofstream("broken.json") << "{ \"camera\": ";
	}
	~In_Temp_Dir() {
		fs::current_path(previous);
	}

	// Every file below the directory, apart from the two scenes written above.
	std::vector<std::string> new_files() const {
		std::vector<std::string> files;
		for (const auto& entry : fs::recursive_directory_iterator(dir.path())) {
			std::string name = fs::relative(entry.path(), dir.path()).string();
			if (name != "sphere.json" && name != "broken.json") files.push_back(name);
		}
		return files;
	}

private:
	Temp_Dir dir;
	fs::path previous;
};

struct Run {
	int status = 0;
	std::string out, err;
};

// The program `program` with `args` after its name.
Run run_as(const std::string& program, std::vector<std::string> args, bool err_is_terminal = false) {
	args.insert(args.begin(), program);
	std::ostringstream out, err;
	Run result;
	result.status = run_cli(args, out, err, err_is_terminal);
	result.out = out.str();
	result.err = err.str();
	return result;
}

Run run(const std::vector<std::string>& args, bool err_is_terminal = false) {
	return run_as("pathtracer_reference", args, err_is_terminal);
}

std::string joined(const std::vector<std::string>& args) {
	std::string text;
	for (const std::string& a : args) text += (text.empty() ? "" : " ") + a;
	return text;
}

bool any_nonzero(const HDR_Image& image) {
	return std::any_of(image.pixels.begin(), image.pixels.end(), [](Spectrum p) { return p != Spectrum{0.0f}; });
}

// Decoded 8-bit RGB of a PNG.
std::vector<uint8_t> png_bytes(const std::string& path) {
	int w = 0, h = 0, channels = 0;
	uint8_t* data = stbi_load(path.c_str(), &w, &h, &channels, 3);
	REQUIRE(data != nullptr);
	std::vector<uint8_t> bytes(data, data + size_t(w) * h * 3);
	stbi_image_free(data);
	return bytes;
}

// Renders need a working scene loader; say so clearly if it fails.
Run require_render(const std::vector<std::string>& args) {
	Run result = run(args);
	INFO("pathtracer_reference " << joined(args) << "\nstdout:\n" << result.out << "stderr:\n" << result.err);
	REQUIRE(result.status == 0);
	return result;
}

} // namespace

TEST_CASE("cli: --help explains every option and every view, and succeeds") {
	In_Temp_Dir here;
	Run result = run({"--help"});
	CHECK(result.status == 0);
	CHECK(result.err.empty());
	for (const char* word : {"SCENE.json", "--out", "--exr", "--variance", "--nan-map", "--spp", "--width", "--height",
	                         "--max-depth", "--seed", "--threads", "--view", "--exposure", "--no-light-sampling",
	                         "--no-roulette", "--env-sampling", "uniform", "importance", "--quiet", "--help", "path",
	                         "eye", "normals", "bvh", "direction"}) {
		INFO("--help does not mention " << word);
		CHECK(result.out.find(word) != std::string::npos);
	}
	CHECK(here.new_files().empty());
	// --help wins over everything else on the line.
	CHECK(run({"sphere.json", "--spp", "0", "--help"}).status == 0);
}

TEST_CASE("cli: -h is --help, and every line of the help fits 80 columns") {
	In_Temp_Dir here;
	Run help = run({"--help"});
	Run h = run({"-h"});
	CHECK(h.status == 0);
	CHECK(h.out == help.out);
	std::istringstream lines(help.out);
	int number = 1;
	for (std::string line; std::getline(lines, line); number++) {
		INFO("line " << number << " of --help is " << line.size() << " characters long:\n" << line);
		CHECK(line.size() <= 80);
	}
}

TEST_CASE("cli: --version prints the program and the lab's version, and succeeds") {
	In_Temp_Dir here;
	Run result = run({"--version"});
	CHECK(result.status == 0);
	CHECK(result.err.empty());
	CHECK(result.out.rfind("pathtracer_reference (PathTracer Lab) ", 0) == 0);
	CHECK(result.out.find("unknown") == std::string::npos); // CMake gave the project's VERSION
	CHECK(here.new_files().empty());
}

TEST_CASE("cli: a bad command line exits with status 2 (as ./lab's usage errors), a bad scene with 1") {
	In_Temp_Dir here;
	for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
	         {}, {"sphere.json", "--bogus"}, {"sphere.json", "--spp", "0"}, {"sphere.json", "other.json"}}) {
		INFO("pathtracer_reference " << joined(args));
		CHECK(run(args).status == 2);
	}
	CHECK(run({"missing.json"}).status == 1);
	CHECK(run({"broken.json"}).status == 1);
}

TEST_CASE("cli: bad input gives one 'error:' line naming the problem, a non-zero status and no file") {
	In_Temp_Dir here;
	struct Case {
		std::vector<std::string> args;
		std::vector<std::string> message_names; // what the message must mention
	};
	const std::vector<Case> cases{
		{{}, {"scene"}},
		{{"--spp", "4"}, {"scene"}},
		{{"sphere.json", "--bogus"}, {"--bogus"}},
		{{"sphere.json", "-x"}, {"-x"}},
		{{"sphere.json", "--spp"}, {"--spp", "missing"}},
		{{"sphere.json", "--spp", "--quiet"}, {"--spp", "missing"}},
		{{"sphere.json", "--spp", "many"}, {"--spp", "many"}},
		{{"sphere.json", "--spp", "0"}, {"--spp", "'0'"}},
		{{"sphere.json", "--spp", "2.5"}, {"--spp", "2.5"}},
		{{"sphere.json", "--spp=-4"}, {"--spp", "-4"}},
		{{"sphere.json", "--width", "0"}, {"--width", "'0'"}},
		{{"sphere.json", "--width", "99999999999"}, {"--width", "99999999999"}},
		{{"sphere.json", "--height", "-3"}, {"--height", "-3"}},
		{{"sphere.json", "--width", "16384", "--height", "16384"}, {"--width/--height", "16384 x 16384"}},
		{{"sphere.json", "--follow-pixel", "3"}, {"--follow-pixel", "X,Y"}},
		{{"sphere.json", "--follow-pixel", "500,2"}, {"--follow-pixel", "outside"}},
		{{"sphere.json", "--max-depth", "deep"}, {"--max-depth", "deep"}},
		{{"sphere.json", "--seed", "-1"}, {"--seed", "-1"}},
		{{"sphere.json", "--threads", "-2"}, {"--threads", "-2"}},
		{{"sphere.json", "--exposure", "bright"}, {"--exposure", "bright"}},
		{{"sphere.json", "--exposure", "inf"}, {"--exposure", "inf"}},
		{{"sphere.json", "--view", "depth"}, {"--view", "depth", "albedo"}}, // the message lists the views
		{{"sphere.json", "--out", "image.jpg"}, {"--out", ".png"}},
		{{"sphere.json", "--exr", "image.png"}, {"--exr", ".exr"}},
		{{"sphere.json", "--pass", "2/4"}, {"--pass 2/4", "--film"}},
		{{"sphere.json", "--pass", "5/4", "--film", "f.exr"}, {"--pass P", "5"}},
		{{"sphere.json", "--pass", "0/4", "--film", "f.exr"}, {"--pass P", "0"}},
		{{"sphere.json", "--pass", "3", "--film", "f.exr"}, {"--pass", "P/N"}},
		{{"sphere.json", "--film", "f.png"}, {"--film", ".exr"}},
		{{"sphere.json", "--variance", "variance.png"}, {"--variance", ".exr"}},
		{{"sphere.json", "--nan-map", "nan.exr"}, {"--nan-map", ".png"}},
		{{"sphere.json", "--exr", "same.exr", "--variance", "same.exr"}, {"same.exr"}},
		{{"sphere.json", "--quiet=yes"}, {"--quiet"}},
		{{"sphere.json", "--no-roulette=yes"}, {"--no-roulette"}},
		{{"sphere.json", "--env-sampling", "sometimes"}, {"--env-sampling", "sometimes"}},
		{{"sphere.json", "--env-sampling", "uniform"}, {"--env-sampling", "no environment image"}},
		{{"sphere.json", "other.json"}, {"other.json"}},
		{{"missing.json"}, {"missing.json"}},
		{{"broken.json"}, {"broken.json"}},
	};
	for (const Case& c : cases) {
		// Ask for every output first (the case's own options come later and win), so a partial
		// render would leave files behind.
		std::vector<std::string> args{"--exr", "a.exr", "--variance", "v.exr", "--nan-map", "n.png"};
		args.insert(args.end(), c.args.begin(), c.args.end());
		if (c.args.empty()) args.clear(); // no arguments at all
		Run result = run(args);
		INFO("pathtracer_reference " << joined(args) << "\nstdout: " << result.out << "\nstderr: " << result.err);
		CHECK(result.status != 0);
		CHECK(result.err.rfind("error: ", 0) == 0);
		CHECK(std::count(result.err.begin(), result.err.end(), '\n') == 1);
		for (const std::string& name : c.message_names) {
			INFO("the message should mention " << name);
			CHECK(result.err.find(name) != std::string::npos);
		}
		CHECK(result.out.empty());
		std::vector<std::string> files = here.new_files();
		INFO("files written: " << joined(files));
		CHECK(files.empty());
	}
}

TEST_CASE("cli: a render writes the PNG (default out/<scene>.png), the EXRs and reports them") {
	In_Temp_Dir here;
	Run result = require_render({"sphere.json", "--exr", "mean.exr", "--variance", "var/variance.exr", "--nan-map",
	                             "nan.png", "--threads", "2"});
	for (const char* file : {"out/sphere.png", "mean.exr", "var/variance.exr", "nan.png"}) {
		INFO(file);
		CHECK(fs::exists(file));
		CHECK(result.out.find(std::string("wrote ") + file + "\n") != std::string::npos);
	}
	HDR_Image mean = read_image("mean.exr");
	CHECK(mean.w == 16u);
	CHECK(mean.h == 12u);
	HDR_Image variance = read_image("var/variance.exr");
	CHECK(variance.w == 16u);
	CHECK(variance.h == 12u);
	CHECK(result.out.find("samples/s") != std::string::npos);
	CHECK(result.out.find("non-finite samples: 0\n") != std::string::npos);
	CHECK(result.err.empty()); // no progress bar: err is not a terminal in this test
}

TEST_CASE("cli: --pass P/N --film renders one share of the samples, and the films of all N merge into the whole") {
	In_Temp_Dir here;
	require_render({"sphere.json", "--spp", "5", "--film", "whole.exr", "--threads", "2"});
	std::vector<std::string> passes;
	for (const char* pass : {"1/2", "2/2"}) {
		passes.push_back(std::string("pass") + pass[0] + ".exr");
		Run result = require_render({"sphere.json", "--spp", "5", "--pass", pass, "--film", passes.back()});
		CHECK(result.out.find(std::string("(pass ") + pass[0] + " of 2 of 5 samples)") != std::string::npos);
	}
	Film_File whole = read_film("whole.exr"), merged = merge_films(passes);
	CHECK(read_film(passes[0]).film.pixels[0].count == 3); // samples 0, 2, 4
	CHECK(read_film(passes[1]).film.pixels[0].count == 2); // samples 1, 3
	CHECK(merged.origin.scene == "sphere.json");
	for (size_t i = 0; i < whole.film.pixels.size(); i++) {
		INFO("pixel " << i);
		CHECK(merged.film.pixels[i].count == whole.film.pixels[i].count);
		CHECK(glm::length(merged.film.pixels[i].mean - whole.film.pixels[i].mean) <= 1e-12);
	}
}

TEST_CASE("cli: --width, --height, --spp and --exposure override the scene for this run") {
	In_Temp_Dir here;
	Run result = require_render({"sphere.json", "--out", "small.png", "--exr", "small.exr", "--width", "8", "--height",
	                             "6", "--spp", "3", "--exposure", "1.5"});
	HDR_Image image = read_image("small.exr");
	CHECK(image.w == 8u);
	CHECK(image.h == 6u);
	CHECK(result.out.find("8 x 6 pixels, 3 samples") != std::string::npos);
	// The PNG is the EXR through write_png with the same exposure.
	write_png("expected.png", image, 1.5f);
	CHECK(png_bytes("small.png") == png_bytes("expected.png"));
}

TEST_CASE("cli: pathtracer_student's default output is out/<scene>_student.png, so it never replaces the reference's") {
	In_Temp_Dir here;
	Run reference = run({"sphere.json"});
	Run student = run_as("pathtracer_student", {"sphere.json"});
	CHECK(reference.out.find("wrote out/sphere.png\n") != std::string::npos);
	CHECK(student.out.find("wrote out/sphere_student.png\n") != std::string::npos);
	std::vector<std::string> files = here.new_files();
	std::sort(files.begin(), files.end());
	CHECK(files == std::vector<std::string>{"out", "out/sphere.png", "out/sphere_student.png"});
	CHECK(run_as("pathtracer_student", {"--help"}).out.find("out/<scene name>_student.png") != std::string::npos);
	CHECK(run_as("pathtracer_student", {"sphere.json", "--quiet", "--out", "mine.png"}).status == 0);
	CHECK(fs::exists("mine.png")); // --out still chooses
}

TEST_CASE("cli: --width and --height give the camera the film's aspect ratio, keeping the vertical field of view") {
	In_Temp_Dir here; // sphere.json: film 16 x 12, vertical_fov 50
	Scene scene = load_scene("sphere.json");
	Scene wide = load_scene("sphere.json");
	override_scene(wide, parse_cli_options({"pathtracer", "sphere.json", "--width", "32"}));
	CHECK(wide.settings.width == 32u);
	CHECK(wide.camera.aspect_ratio == 32.0f / 12.0f);
	CHECK(wide.camera.v_fov == scene.camera.v_fov);
	CHECK(wide.camera.camera_to_world == scene.camera.camera_to_world);
	Scene same = load_scene("sphere.json");
	override_scene(same, parse_cli_options({"pathtracer", "sphere.json", "--spp", "3"}));
	CHECK(same.camera.aspect_ratio == scene.camera.aspect_ratio);

	// The picture is the one of a scene whose film has that size: the sphere stays round.
	auto scene_with_film = [](const std::string& size) {
		const std::string film = R"("width": 16, "height": 12)";
		std::string text = SPHERE_SCENE;
		return text.replace(text.find(film), film.size(), size);
	};
	std::ofstream("wide.json") << scene_with_film(R"("width": 32, "height": 12)");
	std::ofstream("tall.json") << scene_with_film(R"("width": 16, "height": 30)");
	require_render({"sphere.json", "--quiet", "--width", "32", "--exr", "cli_wide.exr"});
	require_render({"wide.json", "--quiet", "--exr", "scene_wide.exr"});
	require_render({"sphere.json", "--quiet", "--height", "30", "--exr", "cli_tall.exr"});
	require_render({"tall.json", "--quiet", "--exr", "scene_tall.exr"});
	INFO("--width/--height must set Camera::aspect_ratio (framework/cli/cli_options.cpp, override_scene)");
	CHECK(read_image("cli_wide.exr").pixels == read_image("scene_wide.exr").pixels);
	CHECK(read_image("cli_tall.exr").pixels == read_image("scene_tall.exr").pixels);
}

TEST_CASE("cli: --seed chooses the random numbers: same seed same image, another seed another image") {
	In_Temp_Dir here;
	require_render({"sphere.json", "--quiet", "--exr", "a.exr", "--seed", "5", "--threads", "1"});
	require_render({"sphere.json", "--quiet", "--exr", "b.exr", "--seed", "5", "--threads", "2"});
	require_render({"sphere.json", "--quiet", "--exr", "c.exr", "--seed", "6"});
	CHECK(read_image("a.exr").pixels == read_image("b.exr").pixels);
	CHECK(read_image("a.exr").pixels != read_image("c.exr").pixels);
}

TEST_CASE("cli: --no-light-sampling and --no-roulette turn the strategies off for this run; both are on by default") {
	In_Temp_Dir here;
	Scene scene = load_scene("sphere.json"); // a constant sky: a light that task 6 may sample
	Render_Settings plain = override_settings(scene.settings, parse_cli_options({"pathtracer", "sphere.json"}));
	CHECK(plain.light_sampling);
	CHECK(plain.russian_roulette);
	CHECK(Pathtracer(scene, plain).has_lights());

	Render_Settings off = override_settings(
		scene.settings, parse_cli_options({"pathtracer", "sphere.json", "--no-light-sampling", "--no-roulette"}));
	CHECK_FALSE(off.russian_roulette);
	CHECK_FALSE(off.light_sampling);
	INFO("--no-light-sampling must hide the lights from task 6: has_lights() false (framework/render/pathtracer.cpp)");
	CHECK_FALSE(Pathtracer(scene, off).has_lights());
	require_render({"sphere.json", "--quiet", "--no-light-sampling", "--no-roulette"});
}

TEST_CASE("cli: --light-choice tree|power|uniform; next-event estimation defaults to the light tree, the mixture to power") {
	auto chosen = [&](std::vector<std::string> args) {
		args.insert(args.begin(), {"pathtracer", "sphere.json"});
		return estimator_choice(parse_cli_options(args)).light_choice;
	};
	CHECK(chosen({"--integrator", "nee"}) == Light_Choice::tree);
	CHECK(chosen({"--integrator", "mixture"}) == Light_Choice::power);
	CHECK(chosen({"--integrator", "nee", "--light-choice", "power"}) == Light_Choice::power);
	CHECK(chosen({"--integrator", "mixture", "--light-choice", "tree"}) == Light_Choice::tree);
	CHECK(chosen({"--light-choice", "uniform"}) == Light_Choice::uniform);
	CHECK_THROWS_WITH(chosen({"--light-choice", "bvh"}), contains_text("expected tree, power or uniform, got 'bvh'"));
}

TEST_CASE("cli: --env-sampling rebuilds the environment image as uniformly or importance-sampled") {
	In_Temp_Dir here;
	// A 4 x 2 sky, dim but for one bright texel, and the same sky black everywhere.
	HDR_Image sky(4, 2, Spectrum{0.1f});
	sky.at(1, 0) = Spectrum{100.0f};
	write_exr("sky.exr", sky);
	write_exr("black.exr", HDR_Image(4, 2));
	auto scene_with = [](const std::string& file, bool importance) {
		return std::string(R"({"camera": {"position": [0, 0, 3], "target": [0, 0, 0], "vertical_fov": 50},
			"film": {"width": 8, "height": 6, "samples": 2, "max_depth": 2},
			"materials": {"grey": {"type": "lambertian", "albedo": [0.6, 0.6, 0.6]}},
			"objects": [{"type": "sphere", "radius": 1, "material": "grey"}],
			"environment": {"type": "image", "file": ")") + file + R"(", "importance_sampling": )" +
		       (importance ? "true" : "false") + "}}";
	};
	std::ofstream("importance.json") << scene_with("sky.exr", true);
	std::ofstream("uniform.json") << scene_with("sky.exr", false);
	std::ofstream("black.json") << scene_with("black.exr", false);
	const float uniform_pdf = 1.0f / (4.0f * PI_F);
	const Vec3 towards_bright = uv_to_direction(Vec2{1.5f / 4.0f, 0.5f / 2.0f}); // texel centres
	const Vec3 towards_dim = uv_to_direction(Vec2{3.5f / 4.0f, 1.5f / 2.0f});

	auto environment = [](const std::string& path, const std::string& how) {
		Scene scene = load_scene(path);
		override_environment(scene, parse_cli_options({"pathtracer", path, "--env-sampling", how}));
		return std::get<Env_Map>(*scene.environment);
	};
	Env_Map uniform = environment("importance.json", "uniform");
	CHECK_FALSE(uniform.importance_sampling);
	CHECK(uniform.pdf(towards_bright) == Approx(uniform_pdf));
	CHECK(uniform.image.pixels == sky.pixels); // the radiance is unchanged

	Env_Map importance = environment("uniform.json", "importance");
	CHECK(importance.importance_sampling);
	REQUIRE(importance.sampler.pdf_texel.size() == 8u);
	// Importance sampling favours the bright texel and avoids the dim ones (uniform would not).
	CHECK(importance.pdf(towards_bright) > 2.0f * uniform_pdf);
	CHECK(importance.pdf(towards_dim) < 0.5f * uniform_pdf);

	// Without the option the scene's own choice stands.
	Scene as_loaded = load_scene("uniform.json");
	override_environment(as_loaded, parse_cli_options({"pathtracer", "uniform.json"}));
	CHECK_FALSE(std::get<Env_Map>(*as_loaded.environment).importance_sampling);

	// A black sky has nothing to importance-sample: an error, and no image.
	Run black = run({"black.json", "--env-sampling", "importance"});
	INFO("stderr: " << black.err);
	CHECK(black.status != 0);
	CHECK(black.err.find("--env-sampling importance") != std::string::npos);
	CHECK_FALSE(fs::exists("out/black.png"));
	require_render({"black.json", "--quiet", "--env-sampling", "uniform"});
	require_render({"uniform.json", "--quiet", "--env-sampling", "importance"});
}

TEST_CASE("cli: --quiet prints nothing, and the progress bar appears only on a terminal") {
	In_Temp_Dir here;
	Run quiet = run({"sphere.json", "--quiet"}, true);
	CHECK(quiet.status == 0);
	CHECK(quiet.out.empty());
	CHECK(quiet.err.empty());
	CHECK(fs::exists("out/sphere.png"));

	Run terminal = run({"sphere.json"}, true);
	CHECK(terminal.status == 0);
	CHECK(terminal.err.find("100%") != std::string::npos);
}

TEST_CASE("cli: scene loading is shown, reported with its time, and counted in the total") {
	In_Temp_Dir here;
	Run terminal = run({"sphere.json"}, true);
	CHECK(terminal.status == 0);
	INFO("stdout:\n" << terminal.out << "stderr:\n" << terminal.err);
	CHECK(terminal.err.rfind("loading sphere.json ...", 0) == 0); // shown while it loads
	CHECK(terminal.err.find("  0%") != std::string::npos);        // then the bar, at once
	CHECK(terminal.out.rfind("loaded sphere.json in ", 0) == 0);
	CHECK(terminal.out.find("total: ") != std::string::npos);
	CHECK(terminal.out.find("(loading ") != std::string::npos);
	Run quiet = run({"sphere.json", "--quiet"}, true);
	CHECK(quiet.out.empty());
	CHECK(quiet.err.empty());
}

TEST_CASE("cli: non-finite samples are counted, reported with a warning, and marked in the NaN map") {
	In_Temp_Dir here;
	// Emission and sky near the float maximum: emitted plus reflected radiance overflows to +inf.
	std::ofstream("overflow.json") << R"({
		"camera": {"position": [0, 0, 3], "target": [0, 0, 0], "vertical_fov": 50},
		"film": {"width": 16, "height": 12, "samples": 2, "max_depth": 3, "seed": 1},
		"materials": {"hot": {"type": "lambertian", "albedo": [0.9, 0.9, 0.9], "emission": [3e38, 3e38, 3e38]}},
		"objects": [{"type": "sphere", "radius": 1, "material": "hot"}],
		"environment": {"type": "constant", "radiance": [3e38, 3e38, 3e38]}
	})";
	Run result = require_render({"overflow.json", "--nan-map", "nan.png"});
	CHECK(result.out.find("non-finite samples: 0\n") == std::string::npos);
	CHECK(result.err.rfind("warning: ", 0) == 0);
	CHECK(result.err.find("NaN or infinite") != std::string::npos);
	CHECK(result.err.find("nan.png") != std::string::npos);
	std::vector<uint8_t> map = png_bytes("nan.png");
	CHECK(std::count(map.begin(), map.end(), uint8_t(255)) > 0);
	CHECK(std::count(map.begin(), map.end(), uint8_t(0)) > 0); // the sky pixels are fine
}

TEST_CASE("cli: an image that cannot be written gives an error naming it") {
	In_Temp_Dir here;
	std::ofstream("blocker") << "a file where a directory is needed";
	Run result = run({"sphere.json", "--quiet", "--out", "blocker/image.png"});
	CHECK(result.status != 0);
	CHECK(result.err.rfind("error: ", 0) == 0);
	CHECK(result.err.find("blocker/image.png") != std::string::npos);
}

TEST_CASE("cli: every output path is checked before rendering: a bad one fails and no file is written") {
	In_Temp_Dir here;
	std::ofstream("blocker") << "a file where a directory is needed";
	fs::create_directory("folder.exr");
	for (std::string bad : {"/proc/x.exr", "blocker/x.exr", "folder.exr"}) {
		Run result = run({"sphere.json", "--out", "ok.png", "--variance", "new/v.exr", "--exr", bad});
		INFO("--exr " << bad << "\nstdout: " << result.out << "\nstderr: " << result.err);
		CHECK(result.status != 0);
		CHECK(result.err.rfind("error: " + bad + ": ", 0) == 0);
		CHECK(result.out.empty()); // nothing rendered
		std::vector<std::string> files = here.new_files();
		std::sort(files.begin(), files.end());
		INFO("files: " << joined(files));
		CHECK(files == std::vector<std::string>{"blocker", "folder.exr"});
	}
}

TEST_CASE("cli: an image written to a full device is an error with the system's reason, never 'wrote'") {
	In_Temp_Dir here;
	fs::create_symlink("/dev/full", "full.png");
	Run result = run({"sphere.json", "--out", "full.png"});
	INFO("stdout: " << result.out << "\nstderr: " << result.err);
	CHECK(result.status != 0);
	CHECK(result.err.find("full.png: ") != std::string::npos);
	CHECK(result.err.find(std::strerror(ENOSPC)) != std::string::npos);
	CHECK(result.out.find("wrote") == std::string::npos);
}

TEST_CASE("cli: the debug views eye, normals, bvh and direction show the scene (not a black image)") {
	In_Temp_Dir here;
	for (const char* view : {"eye", "normals", "bvh", "direction"}) {
		INFO("--view " << view << " rendered a black image: check the reference tasks 1-3 and "
		     "framework/render/pathtracer.cpp");
		require_render({"sphere.json", "--quiet", "--view", view, "--exr", "view.exr"});
		CHECK(any_nonzero(read_image("view.exr")));
	}
}

TEST_CASE("Progress_Bar: percentage and ETA on one line when enabled, nothing when disabled") {
	std::ostringstream silent;
	{
		Progress_Bar bar(silent, false);
		bar.update(1, 4);
		bar.update(4, 4);
	}
	CHECK(silent.str().empty());

	std::ostringstream out;
	Progress_Bar bar(out, true);
	bar.update(1, 4);
	CHECK(out.str().find(" 25%") != std::string::npos);
	CHECK(out.str().find("ETA") != std::string::npos);
	CHECK(out.str().find('\n') == std::string::npos); // redrawn with '\r', never a new line
	bar.update(3, 4);
	std::string before_late_report = out.str();
	bar.update(2, 4); // a slower thread reporting late: the bar must not move backwards
	CHECK(out.str() == before_late_report);
	bar.update(4, 4);
	CHECK(out.str().find("100%") != std::string::npos);
	bar.finish();
	CHECK(out.str().back() == '\r'); // the line is erased for the next output
	CHECK(out.str().find('\n') == std::string::npos);
}

TEST_CASE("Progress_Bar: appears at once, before any work is done") {
	std::ostringstream out;
	Progress_Bar bar(out, true);
	bar.update(0, 1000);
	CHECK(out.str().find("  0%") != std::string::npos);
	CHECK(out.str().find("ETA -:--") != std::string::npos);
}

// The lines a bar drew, each one after a '\r'.
std::vector<std::string> drawn_lines(const std::string& text) {
	std::vector<std::string> lines;
	std::istringstream in(text);
	for (std::string line; std::getline(in, line, '\r');) {
		if (line.find_first_not_of(' ') != std::string::npos) lines.push_back(line);
	}
	return lines;
}

TEST_CASE("Progress_Bar: every line is narrower than the terminal, down to 10 columns") {
	for (size_t columns : {80, 40, 30, 24, 10}) {
		std::ostringstream out;
		{
			Progress_Bar bar(out, true, columns);
			for (size_t done = 0; done <= 100; done += 7) bar.update(done, 100);
		}
		std::vector<std::string> lines = drawn_lines(out.str());
		REQUIRE_FALSE(lines.empty());
		for (const std::string& line : lines) {
			INFO(columns << " columns: '" << line << "'");
			CHECK(line.size() < std::max<size_t>(columns, 16)); // below 16 only the percentage and ETA remain
		}
		if (columns >= 40) CHECK(lines.back().find('[') != std::string::npos); // the bar itself
	}
}

TEST_CASE("terminal_columns: the terminal's width, else $COLUMNS, else 80") {
	if (stderr_is_terminal()) return; // the real terminal's width wins; ctest runs without one
	const char* saved = std::getenv("COLUMNS");
	std::string previous = saved ? saved : "";
	setenv("COLUMNS", "57", 1);
	CHECK(terminal_columns() == 57);
	unsetenv("COLUMNS");
	CHECK(terminal_columns() == 80);
	if (saved) setenv("COLUMNS", previous.c_str(), 1);
}
