#include "viewer_options.h"
#include "error.h"

#include <charconv>
#include <filesystem>

namespace {
template<typename T> T whole_number(const std::string& option, const std::string& text, T min, T max) {
	T value{};
	auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), value);
	if (status != std::errc() || end != text.data() + text.size() || value < min || value > max) {
		throw Input_Error(option + ": expected a whole number from " + std::to_string(min) + " to " +
		                  std::to_string(max) + ", got '" + text + "'");
	}
	return value;
}

std::string existing_file(const std::string& option, const std::string& path) {
	if (!std::filesystem::is_regular_file(path)) throw Input_Error(option + ": no such file: " + path);
	return path;
}
} // namespace

std::string viewer_usage() {
	return "usage: lab_viewer SCENE.json --reference-renderer PATH\n"
	       "                  [--student-renderer PATH | --reference-only] [--port N]\n"
	       "                  [--out-dir DIR] [--student-dir DIR --lab PATH --build-dir DIR\n"
	       "                  [--rebuild-target T]] [--max-spp N] [--threads T] [--seed S]\n"
	       "(./lab view runs it: ./lab help view)\n"
	       "  --port N            127.0.0.1:N, 0 to 65535 (0: any free port; default 8024)\n"
	       "  --reference-only    the reference's render alone (./lab view --reference)\n"
	       "  --student-dir DIR   rebuild the student's renderer when a file of DIR changes:\n"
	       "                      LAB_BUILD_DIR=DIR LAB build T (default T pathtracer_student);\n"
	       "                      the page runs a grader as LAB_BUILD_DIR=DIR LAB grade N\n"
	       "  --max-spp N         samples per pixel a render stops at (default 4096)\n"
	       "  --threads T         threads per renderer (default 0: all cores)\n"
	       "  --seed S            the student's seed (the reference's is S + 1; default 0)\n";
}

Viewer_Options parse_viewer_options(const std::vector<std::string>& args) {
	Viewer_Options options;
	Viewer_Config& c = options.session;
	c.out_dir = "out";
	std::string lab, build_dir, rebuild_target = "pathtracer_student";
	bool reference_only = false;
	for (size_t i = 1; i < args.size(); i++) {
		const std::string& arg = args[i];
		auto value = [&]() -> const std::string& {
			if (i + 1 >= args.size()) throw Input_Error(arg + ": missing value");
			return args[++i];
		};
		if (arg == "--reference-renderer") c.reference_renderer = existing_file(arg, value());
		else if (arg == "--student-renderer") c.student_renderer = value();
		else if (arg == "--reference-only") reference_only = true;
		else if (arg == "--port") options.port = whole_number<int>(arg, value(), 0, 65535);
		else if (arg == "--out-dir") c.out_dir = value();
		else if (arg == "--student-dir") c.student_dir = value();
		else if (arg == "--lab") lab = existing_file(arg, value());
		else if (arg == "--build-dir") build_dir = value();
		else if (arg == "--rebuild-target") rebuild_target = value();
		else if (arg == "--max-spp") c.max_samples = whole_number<uint32_t>(arg, value(), 1, 1000000);
		else if (arg == "--threads") c.threads = whole_number<uint32_t>(arg, value(), 0, 1024);
		else if (arg == "--seed") c.seed = whole_number<uint64_t>(arg, value(), 0, UINT64_MAX - 1);
		else if (arg.rfind("-", 0) == 0) throw Input_Error("unknown option '" + arg + "'");
		else if (c.scene.empty()) c.scene = existing_file("SCENE", arg);
		else throw Input_Error("unexpected argument '" + arg + "': give one scene file");
	}
	if (c.scene.empty()) throw Input_Error("no scene file given");
	if (c.reference_renderer.empty()) throw Input_Error("--reference-renderer is required");
	c.compare = !reference_only;
	if (c.compare && c.student_renderer.empty()) throw Input_Error("--student-renderer is required (or --reference-only)");
	if (!lab.empty()) {
		if (build_dir.empty()) throw Input_Error("--lab needs --build-dir");
		std::string build_env = "LAB_BUILD_DIR=" + build_dir;
		c.grade_command = {"/usr/bin/env", build_env, lab, "grade"};
		if (!c.student_dir.empty()) c.rebuild_command = {"/usr/bin/env", build_env, lab, "build", rebuild_target};
	}
	if (!c.student_dir.empty() && !std::filesystem::is_directory(c.student_dir)) {
		throw Input_Error("--student-dir: no such folder: " + c.student_dir);
	}
	return options;
}
