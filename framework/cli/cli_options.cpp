#include "cli_options.h"
#include "decimal.h"
#include "error.h"
#include "integrators.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <functional>
#include <tuple>

// The lab's version (the project's VERSION in CMakeLists.txt), for --version.
#ifndef LAB_VERSION
#define LAB_VERSION "unknown"
#endif

namespace {

// The help fits an 80-column terminal.
constexpr size_t HELP_WIDTH = 80;

// ---- Values -------------------------------------------------------------------------------------

template<typename T> T whole_number(const std::string& option, const std::string& text, T min, T max) {
	T value{};
	const char* end = text.data() + text.size();
	auto [stop, status] = std::from_chars(text.data(), end, value);
	if (status != std::errc() || stop != end || value < min || value > max) {
		throw Input_Error(option + ": expected a whole number from " + std::to_string(min) + " to " +
		                  std::to_string(max) + ", got '" + text + "'");
	}
	return value;
}

float stops(const std::string& option, const std::string& text) {
	constexpr float LIMIT = 64.0f; // 2^64 is far beyond any useful exposure
	float value = 0.0f;
	if (!parse_decimal(text, value) || !(std::abs(value) <= LIMIT)) {
		throw Input_Error(option + ": expected a number of stops from -64 to 64, got '" + text + "'");
	}
	return value;
}

float adaptive_threshold(const std::string& option, const std::string& text) {
	float value = 0.0f;
	if (!parse_decimal(text, value) || !(value >= 0.001f && value <= 1.0f)) {
		throw Input_Error(option + ": expected a relative precision from 0.001 to 1 (e.g. 0.0625), got '" + text + "'");
	}
	return value;
}

std::string lowercase(std::string text) {
	std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
	return text;
}

// An output file name with the extension its format needs.
std::string output_file(const std::string& option, const std::string& path, const std::string& extension) {
	if (lowercase(std::filesystem::path(path).extension().string()) != extension) {
		throw Input_Error(option + ": the file name must end in " + extension + ", got '" + path + "'");
	}
	return path;
}

// "X,Y" as two whole numbers.
std::pair<uint32_t, uint32_t> pixel(const std::string& option, const std::string& text) {
	size_t comma = text.find(',');
	if (comma == std::string::npos) throw Input_Error(option + ": expected a pixel X,Y (e.g. 128,40), got '" + text + "'");
	return {whole_number<uint32_t>(option + " X", text.substr(0, comma), 0, 16383),
	        whole_number<uint32_t>(option + " Y", text.substr(comma + 1), 0, 16383)};
}

// "P/N" with 1 <= P <= N.
std::pair<uint32_t, uint32_t> pass_of(const std::string& option, const std::string& text) {
	size_t slash = text.find('/');
	if (slash == std::string::npos) throw Input_Error(option + ": expected a pass P/N (e.g. 2/8), got '" + text + "'");
	uint32_t passes = whole_number<uint32_t>(option + " N", text.substr(slash + 1), 1, 1000000);
	return {whole_number<uint32_t>(option + " P", text.substr(0, slash), 1, passes), passes};
}

// "uniform" or "importance": whether to importance-sample the environment image.
bool env_sampling_named(const std::string& option, const std::string& name) {
	if (name != "uniform" && name != "importance") {
		throw Input_Error(option + ": expected uniform or importance, got '" + name + "'");
	}
	return name == "importance";
}

Sampler sampler_named(const std::string& option, const std::string& name) {
	Sampler sampler;
	if (!parse_sampler(name, sampler)) throw Input_Error(option + ": expected sobol or independent, got '" + name + "'");
	return sampler;
}

Light_Choice light_choice_named(const std::string& option, const std::string& name) {
	if (name == "tree") return Light_Choice::tree;
	if (name == "power") return Light_Choice::power;
	if (name == "uniform") return Light_Choice::uniform;
	throw Input_Error(option + ": expected tree, power or uniform, got '" + name + "'");
}

bool follow_format_json(const std::string& option, const std::string& name) {
	if (name != "text" && name != "json") throw Input_Error(option + ": expected text or json, got '" + name + "'");
	return name == "json";
}

View view_named(const std::string& option, const std::string& name) {
	View view;
	if (!parse_view(name, view)) {
		throw Input_Error(option + ": unknown view '" + name +
		                  "' (expected path, samples, eye, normals, albedo, bvh or direction)");
	}
	return view;
}

// ---- The options: one table for parsing and for --help ------------------------------------------

struct Option {
	const char* name;
	const char* value; // placeholder shown in --help; nullptr for a flag without value
	const char* help;
	// Stores the value; `name` is the option's name, for error messages.
	std::function<void(Cli_Options& o, const std::string& name, const std::string& value)> set;
};

const std::vector<Option>& option_table() {
	static const std::vector<Option> table{
		{"--out", "FILE.png",
		 "the image to look at: exposure, sRGB, 8 bits (default out/<scene name>.png; from pathtracer_student "
		 "out/<scene name>_student.png)",
		 [](auto& o, auto& name, auto& v) { o.png = output_file(name, v, ".png"); }},
		{"--exr", "FILE.exr", "also write the linear image (the per-pixel mean) as 32-bit floats",
		 [](auto& o, auto& name, auto& v) { o.exr = output_file(name, v, ".exr"); }},
		{"--variance", "FILE.exr", "also write the per-pixel sample variance s^2 (the mean's is s^2 / spp)",
		 [](auto& o, auto& name, auto& v) { o.variance = output_file(name, v, ".exr"); }},
		{"--film", "FILE.exr",
		 "also write the film: each pixel's mean, variance and sample count, exactly; the passes of a split "
		 "render are merged from these (merge_films, ./lab merge)",
		 [](auto& o, auto& name, auto& v) { o.film = output_file(name, v, ".exr"); }},
		{"--pass", "P/N",
		 "render pass P of N: only the samples s with s % N = P - 1, so that N machines share a render; "
		 "needs --film",
		 [](auto& o, auto& name, auto& v) { std::tie(o.pass, o.passes) = pass_of(name, v); }},
		{"--nan-map", "FILE.png", "also write a map of the pixels that had NaN or infinite samples (white)",
		 [](auto& o, auto& name, auto& v) { o.nan_map = output_file(name, v, ".png"); }},
		{"--spp", "N", "samples per pixel, 1 to 1000000",
		 [](auto& o, auto& name, auto& v) { o.samples = whole_number<uint32_t>(name, v, 1, 1000000); }},
		{"--width", "W", "image width in pixels, 1 to 16384; the view widens, never stretches",
		 [](auto& o, auto& name, auto& v) { o.width = whole_number<uint32_t>(name, v, 1, 16384); }},
		{"--height", "H", "image height in pixels, 1 to 16384",
		 [](auto& o, auto& name, auto& v) { o.height = whole_number<uint32_t>(name, v, 1, 16384); }},
		{"--max-depth", "D", "maximum number of bounces, 0 to 1000 (0: emitters only, 1: direct light)",
		 [](auto& o, auto& name, auto& v) { o.max_depth = whole_number<uint32_t>(name, v, 0, 1000); }},
		{"--seed", "S", "random seed, a whole number >= 0; the same seed gives the same image",
		 [](auto& o, auto& name, auto& v) { o.seed = whole_number<uint64_t>(name, v, 0, UINT64_MAX); }},
		{"--threads", "T", "render threads, 0 to 1024 (0 = all cores; the image does not depend on it)",
		 [](auto& o, auto& name, auto& v) { o.threads = whole_number<uint32_t>(name, v, 0, 1024); }},
		{"--view", "VIEW", "what to show (see views below; default path)",
		 [](auto& o, auto& name, auto& v) {
			 o.samples_view = v == "samples";
			 o.view = o.samples_view ? View::path : view_named(name, v);
		 }},
		{"--adaptive", "THRESHOLD",
		 "adaptive sampling: each pixel stops once the 95 % confidence interval of its mean is within THRESHOLD "
		 "of it (relative, 0.001 to 1; e.g. 0.0625, where its bias stays within a tenth of the noise on the lab's "
		 "scenes), checked every 16 samples from 32 on; --spp is then the most a pixel takes (see --view samples)",
		 [](auto& o, auto& name, auto& v) { o.adaptive = adaptive_threshold(name, v); }},
		{"--exposure", "STOPS", "brighten (> 0) or darken (< 0) the PNG by 2^STOPS (default 0)",
		 [](auto& o, auto& name, auto& v) { o.exposure = stops(name, v); }},
		{"--follow-pixel", "X,Y",
		 "instead of an image, print the life of every ray of pixel (X, Y)'s samples: what each ray hit, the "
		 "BSDF and light samples, the weights and the radiance (pixel (0, 0) is the top-left)",
		 [](auto& o, auto& name, auto& v) { o.follow_pixel = pixel(name, v); }},
		{"--follow-samples", "N",
		 "how many of that pixel's samples --follow-pixel follows, 1 to 1000000 (default 1)",
		 [](auto& o, auto& name, auto& v) { o.follow_samples = whole_number<uint32_t>(name, v, 1, 1000000); }},
		{"--follow-format", "FORMAT", "text (default) or json: how --follow-pixel prints (json: for ./lab view)",
		 [](auto& o, auto& name, auto& v) { o.follow_json = follow_format_json(name, v); }},
		{"--follow-brightest", "K",
		 "with --follow-format json: of the --follow-samples samples, only the K brightest, 1 to 1000 (where "
		 "a firefly comes from)",
		 [](auto& o, auto& name, auto& v) { o.follow_brightest = whole_number<uint32_t>(name, v, 1, 1000); }},
		{"--stream", nullptr,
		 "for ./lab view: render progressively up to --spp samples, writing the film to standard output "
		 "after each batch of samples (binary: framework/film/film_stream.h); writes no image",
		 [](auto& o, auto&, auto&) { o.stream = true; }},
		{"--no-light-sampling", nullptr,
		 "sample the BSDF only: task 6 sees no lights (has_lights() is false); same image, other noise",
		 [](auto& o, auto&, auto&) { o.light_sampling = false; }},
		{"--no-roulette", nullptr, "no Russian roulette (task 4): every path runs to max-depth; same image",
		 [](auto& o, auto&, auto&) { o.russian_roulette = false; }},
		{"--env-sampling", "HOW",
		 "uniform or importance: how task 7 samples the scene's environment image (default: the scene's "
		 "\"importance_sampling\", true if absent)",
		 [](auto& o, auto& name, auto& v) { o.env_importance_sampling = env_sampling_named(name, v); }},
		{"--sampler", "NAME",
		 "sobol (default: low-discrepancy, Owen-scrambled Sobol' points) or independent (PCG32): the random "
		 "numbers of every sample; same image, other noise",
		 [](auto& o, auto& name, auto& v) { o.sampler = sampler_named(name, v); }},
		{"--integrator", "NAME",
		 "how the light along a path is estimated (see integrators below; default nee in pathtracer_reference, "
		 "mixture in pathtracer_student); same image, other noise",
		 [](auto& o, auto& name, auto& v) { o.integrator = integrator_row(name, v).name; }},
		{"--light-choice", "HOW",
		 "tree (by the light each may send to the point), power (in proportion to the power each emits) or "
		 "uniform: how light sampling chooses a light (default: the integrator's, below); same image, other "
		 "noise",
		 [](auto& o, auto& name, auto& v) { o.light_choice = light_choice_named(name, v); }},
		{"--quiet", nullptr, "no progress bar and no summary (errors and warnings are still printed)",
		 [](auto& o, auto&, auto&) { o.quiet = true; }},
		{"--help", nullptr, "print this help and exit (also -h)", [](auto&, auto&, auto&) {}},
		{"--version", nullptr, "print the lab's version and exit", [](auto&, auto&, auto&) {}},
	};
	return table;
}

const Option* find_option(const std::string& name) {
	for (const Option& option : option_table()) {
		if (name == option.name) return &option;
	}
	return nullptr;
}

std::string program_name(const std::vector<std::string>& args) {
	return args.empty() ? "pathtracer" : std::filesystem::path(args[0]).filename().string();
}

// out/<scene name>.png, or out/<scene name>_student.png from the student's renderer, so that its
// render never replaces the reference renderer's (./lab render-student beside ./lab render).
std::string default_png(const std::string& program, const std::string& scene) {
	std::string suffix = program == "pathtracer_student" ? "_student" : "";
	return "out/" + std::filesystem::path(scene).stem().string() + suffix + ".png";
}

// The end of the word that starts at `start`: the next space outside <...> (a placeholder such as
// <scene name> stays on one line), or the end of the text.
size_t word_end(const std::string& text, size_t start) {
	bool in_placeholder = false;
	for (size_t i = start; i < text.size(); i++) {
		if (text[i] == '<') in_placeholder = true;
		if (text[i] == '>') in_placeholder = false;
		if (text[i] == ' ' && !in_placeholder) return i;
	}
	return text.size();
}

// `text` broken into lines of at most `width` characters at spaces; every line after the first is
// indented by `indent` spaces (the first one's indent is the caller's).
std::string wrapped(const std::string& text, size_t indent, size_t first_column, size_t width) {
	std::string out, line;
	size_t column = first_column;
	size_t start = 0;
	while (start < text.size()) {
		size_t end = word_end(text, start);
		std::string word = text.substr(start, end - start);
		start = end + 1;
		if (!line.empty() && column + line.size() + 1 + word.size() > width) {
			out += line + "\n" + std::string(indent, ' ');
			line.clear();
			column = indent;
		}
		line += (line.empty() ? "" : " ") + word;
	}
	return out + line;
}

std::string usage(const std::string& program) {
	constexpr size_t HEAD_WIDTH = 22; // "  --option VALUE" and spaces up to the help
	std::string text = "usage: " + program + " SCENE.json [options]\n\n"
	                   "Renders a scene (format: scenes/README.md) and writes a PNG image. The options\n"
	                   "override the scene's settings for this run only. Values follow the option,\n"
	                   "as in --spp 64 or --spp=64.\n\noptions:\n";
	for (const Option& option : option_table()) {
		std::string head = std::string(option.name) + (option.value ? std::string(" ") + option.value : "");
		if (head.size() + 2 > HEAD_WIDTH) {
			text += "  " + head + "\n" + std::string(HEAD_WIDTH + 2, ' ');
		} else {
			head.resize(HEAD_WIDTH, ' ');
			text += "  " + head;
		}
		text += wrapped(option.help, HEAD_WIDTH + 2, HEAD_WIDTH + 2, HELP_WIDTH) + "\n";
	}
	text += "\nviews (--view):\n"
	        "  path       the Monte Carlo path tracer (tasks 4 to 7)\n"
	        "  samples    the path tracer's render, shown as the samples each pixel took\n"
	        "             (with --adaptive) as a heat map: black none, white --spp\n"
	        "  eye        light from the eye: albedo * |cos| at the first hit, plus emission\n"
	        "  normals    the first hit's normal n as colour (n + 1) / 2\n"
	        "  albedo     the first hit's albedo (the BSDF's reflectance)\n"
	        "  bvh        BVH nodes whose boxes the camera ray overlaps before its hit\n"
	        "             (what a front-to-back traversal visits), as a heat map: black 0,\n"
	        "             blue, purple, orange, yellow, white 64 or more\n"
	        "  direction  the camera ray's direction d as colour (d + 1) / 2\n"
	        "The debug views need tasks 1 to 3 only.\n\n"
	        "integrators (--integrator, with the light choice each takes by default):\n";
	constexpr size_t NAME_WIDTH = 13; // "  name" and spaces up to the summary
	for (const Integrator_Row* row : integrator_rows()) {
		std::string head = "  " + std::string(row->name);
		head = head.size() < NAME_WIDTH ? head + std::string(NAME_WIDTH - head.size(), ' ')
		                                : head + "\n" + std::string(NAME_WIDTH, ' ');
		std::string help = std::string(row->summary) + "; lights by " + light_choice_name(row->light_choice);
		text += head + wrapped(help, NAME_WIDTH, NAME_WIDTH, HELP_WIDTH) + "\n";
	}
	text += "\nExit status 0 on success, 2 for a usage error (an unknown option, a bad value,\n"
	        "no scene), 1 for any other error; bad input writes no file.\n";
	return text;
}

// ---- Parsing ------------------------------------------------------------------------------------

// "--name value" or "--name=value".
void apply_option(const std::vector<std::string>& args, size_t& i, Cli_Options& options) {
	const std::string& arg = args[i];
	size_t equals = arg.find('=');
	std::string name = arg.substr(0, equals);
	const Option* option = find_option(name);
	if (!option) throw Input_Error("unknown option '" + name + "' (see --help)");
	if (!option->value) {
		if (equals != std::string::npos) throw Input_Error(name + " takes no value, got '" + arg + "'");
		option->set(options, name, "");
		return;
	}
	if (equals != std::string::npos) {
		option->set(options, name, arg.substr(equals + 1));
		return;
	}
	bool has_value = i + 1 < args.size() && args[i + 1].rfind("--", 0) != 0;
	if (!has_value) throw Input_Error(name + ": missing value (" + name + " " + option->value + ")");
	option->set(options, name, args[++i]);
}

// Two outputs in one file would silently overwrite each other.
void require_distinct_outputs(const Cli_Options& options) {
	std::vector<std::string> outputs{options.png, options.exr, options.variance, options.nan_map, options.film};
	std::sort(outputs.begin(), outputs.end());
	for (size_t i = 1; i < outputs.size(); i++) {
		if (!outputs[i].empty() && outputs[i] == outputs[i - 1]) {
			throw Input_Error(outputs[i] + ": the same file is given for two outputs");
		}
	}
}

} // namespace

Cli_Options parse_cli_options(const std::vector<std::string>& args) {
	Cli_Options options;
	for (size_t i = 1; i < args.size(); i++) {
		const std::string& arg = args[i];
		if (arg.size() > 1 && arg[0] == '-') {
			apply_option(args, i, options);
		} else if (options.scene.empty()) {
			options.scene = arg;
		} else {
			throw Input_Error("unexpected argument '" + arg + "': give one scene file (see --help)");
		}
	}
	if (options.scene.empty()) {
		throw Input_Error("no scene file given (usage: " + program_name(args) + " SCENE.json [options])");
	}
	if (options.png.empty()) options.png = default_png(program_name(args), options.scene);
	if (options.stream && (options.passes > 1 || options.follow_pixel)) {
		throw Input_Error("--stream renders the whole film progressively: it goes with neither --pass nor --follow-pixel");
	}
	if (options.adaptive > 0.0f && (options.passes > 1 || options.follow_pixel)) {
		throw Input_Error("--adaptive decides each pixel's samples over the whole render: it goes with neither "
		                  "--pass nor --follow-pixel");
	}
	if (options.passes > 1 && options.film.empty()) {
		throw Input_Error("--pass " + std::to_string(options.pass) + "/" + std::to_string(options.passes) +
		                  ": a pass is one share of a render: write its film with --film FILE.exr, to merge");
	}

	require_distinct_outputs(options);
	return options;
}

Render_Settings override_settings(Render_Settings settings, const Cli_Options& options) {
	settings.samples = options.samples.value_or(settings.samples);
	settings.width = options.width.value_or(settings.width);
	settings.height = options.height.value_or(settings.height);
	settings.max_depth = options.max_depth.value_or(settings.max_depth);
	settings.seed = options.seed.value_or(settings.seed);
	settings.light_sampling = settings.light_sampling && options.light_sampling;
	settings.russian_roulette = settings.russian_roulette && options.russian_roulette;
	if (uint64_t(settings.width) * settings.height > Render_Settings::MAX_PIXELS) {
		throw Input_Error("--width/--height: expected at most " + std::to_string(Render_Settings::MAX_PIXELS) +
		                  " pixels (e.g. 4096 x 4096), got " + std::to_string(settings.width) + " x " +
		                  std::to_string(settings.height));
	}
	return settings;
}

Estimator_Choice estimator_choice(const Cli_Options& options) {
	Estimator_Choice choice;
	choice.integrator = options.integrator.value_or(choice.integrator);
	choice.sampler = options.sampler;
	choice.light_choice = options.light_choice.value_or(integrator_row("--integrator", choice.integrator).light_choice);
	return choice;
}

void override_environment(Scene& scene, const Cli_Options& options) {
	if (!options.env_importance_sampling) return;
	Env_Map* map = scene.environment ? std::get_if<Env_Map>(&*scene.environment) : nullptr;
	if (!map) throw Input_Error("--env-sampling: " + scene.path + " has no environment image to sample");
	bool importance = *options.env_importance_sampling;
	if (importance && !(total_luminance(map->image) > 0.0)) {
		throw Input_Error("--env-sampling importance: the environment image of " + scene.path +
		                  " is black everywhere, so it cannot be importance-sampled");
	}
	*map = Env_Map(std::move(map->image), importance); // builds the sampler only for importance
}

void override_scene(Scene& scene, const Cli_Options& options) {
	scene.settings = override_settings(scene.settings, options);
	if (options.width || options.height) {
		scene.camera.aspect_ratio = float(scene.settings.width) / float(scene.settings.height);
	}
	override_environment(scene, options);
}

bool wants_help(const std::vector<std::string>& args) {
	auto first = args.begin() + std::min<size_t>(1, args.size());
	return std::find(first, args.end(), "--help") != args.end() || std::find(first, args.end(), "-h") != args.end();
}

bool wants_version(const std::vector<std::string>& args) {
	return std::find(args.begin() + std::min<size_t>(1, args.size()), args.end(), "--version") != args.end();
}

std::string cli_usage(const std::vector<std::string>& args) {
	return usage(program_name(args));
}

std::string cli_version(const std::vector<std::string>& args) {
	return program_name(args) + " (PathTracer Lab) " + LAB_VERSION + "\n";
}
