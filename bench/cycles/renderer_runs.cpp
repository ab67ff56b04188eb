#include "renderer_runs.h"

#include "convergence_metrics.h"
#include "image_io.h"
#include "text_file.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <fstream>
#include <spawn.h>
#include <stdexcept>
#include <sys/wait.h>

extern char** environ;

const char* renderer_name(Renderer renderer) {
	return renderer == Renderer::lab ? "ours" : "Cycles 3.4";
}

namespace {

std::vector<std::string> command(Renderer renderer, const Render_Request& r, const std::string& image) {
	std::vector<std::string> args;
	if (renderer == Renderer::lab) {
		args = {LAB_RENDERER, r.scene, "--spp", std::to_string(r.spp), "--seed", std::to_string(r.seed), "--threads",
		        std::to_string(r.threads), "--exr", image, "--out", image + ".png"};
		args.insert(args.end(), r.lab_options.begin(), r.lab_options.end());
	} else {
		args = {"blender", "-b", "--factory-startup", "--python-exit-code", "1", "-P", LAB_CYCLES_SCRIPT, "--", r.scene,
		        "--out", image, "--spp", std::to_string(r.spp), "--seed", std::to_string(r.seed), "--threads",
		        std::to_string(r.threads)};
		for (const std::string& name : r.cycles_defaults) {
			args.push_back("--cycles-default");
			args.push_back(name);
		}
		args.insert(args.end(), r.cycles_options.begin(), r.cycles_options.end());
	}
	if (r.max_depth > 0) {
		args.push_back("--max-depth");
		args.push_back(std::to_string(r.max_depth));
	}
	return args;
}

// The number after `key` on the log's last line that has it, e.g. "rendering 0.676 s" -> 0.676.
double reported_seconds(const std::string& log, const std::string& key) {
	size_t at = log.rfind(key);
	if (at == std::string::npos) return -1.0;
	return std::strtod(log.c_str() + at + key.size(), nullptr);
}

std::string tail(const std::string& text, size_t lines) {
	size_t at = text.size();
	for (size_t n = 0; n <= lines && at > 0; n++) at = text.rfind('\n', at - 1);
	return at == std::string::npos ? text : text.substr(at + 1);
}

} // namespace

Renderer_Run run_renderer(Renderer renderer, const Render_Request& request, const std::string& work_dir) {
	std::string stem = work_dir + "/" + (renderer == Renderer::lab ? "lab" : "cycles");
	std::string image = stem + ".exr", log_path = stem + ".log";
	std::vector<std::string> args = command(renderer, request, image);
	std::vector<char*> argv;
	for (std::string& arg : args) argv.push_back(arg.data());
	argv.push_back(nullptr);

	posix_spawn_file_actions_t files;
	posix_spawn_file_actions_init(&files);
	posix_spawn_file_actions_addopen(&files, 1, log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
	posix_spawn_file_actions_adddup2(&files, 1, 2);
	auto start = std::chrono::steady_clock::now();
	pid_t pid;
	int spawn_error = posix_spawnp(&pid, argv[0], &files, nullptr, argv.data(), environ);
	posix_spawn_file_actions_destroy(&files);
	if (spawn_error != 0) throw std::runtime_error(std::string("cannot start ") + argv[0]);
	int status = 0;
	waitpid(pid, &status, 0);
	Renderer_Run run;
	run.command_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

	std::string log = read_text_file(log_path);
	std::string shown;
	for (const std::string& arg : args) shown += arg + " ";
	if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
		throw std::runtime_error(shown + "failed; the end of its output (" + log_path + "):\n" + tail(log, 15));
	run.render_seconds = reported_seconds(log, renderer == Renderer::lab ? "rendering " : ", render ");
	if (run.render_seconds < 0)
		throw std::runtime_error(shown + "did not report its render time; its output: " + log_path);
	// Ours with --adaptive: "adaptive sampling (threshold T): X samples per pixel on average".
	size_t average = log.rfind(" samples per pixel on average");
	size_t number = average == std::string::npos ? std::string::npos : log.rfind(' ', average - 1);
	if (number != std::string::npos) run.mean_spp = std::strtod(log.c_str() + number + 1, nullptr);
	run.image = read_image(image);
	return run;
}

std::string load_average() {
	std::ifstream file("/proc/loadavg");
	std::string one, five, fifteen;
	file >> one >> five >> fifteen;
	return file ? one + " " + five + " " + fifteen : "unknown";
}

std::string fmt(const char* format, double a, double b) {
	char text[96];
	std::snprintf(text, sizeof text, format, a, b);
	return text;
}

Noisy_Image from_two_halves(const HDR_Image& a, const HDR_Image& b) {
	if (a.w != b.w || a.h != b.h) throw std::runtime_error("two halves of different sizes");
	Noisy_Image n{HDR_Image(a.w, a.h), HDR_Image(a.w, a.h)};
	for (size_t i = 0; i < a.pixels.size(); i++) {
		Spectrum d = a.pixels[i] - b.pixels[i];
		n.mean.pixels[i] = 0.5f * (a.pixels[i] + b.pixels[i]);
		n.variance.pixels[i] = 0.25f * d * d;
	}
	return n;
}

namespace {
double relative(double squared_error, double r) {
	return squared_error / (r * r + REL_MSE_EPSILON);
}
} // namespace

double rel_mse(const HDR_Image& x, const HDR_Image& r) {
	if (x.w != r.w || x.h != r.h) throw std::runtime_error("relMSE of images of different sizes");
	double sum = 0.0;
	for (size_t i = 0; i < x.pixels.size(); i++)
		for (int c = 0; c < 3; c++) {
			double d = double(x.pixels[i][c]) - r.pixels[i][c];
			sum += relative(d * d, r.pixels[i][c]);
		}
	return sum / (3.0 * double(x.pixels.size()));
}

double noise_rel_mse(const Noisy_Image& noisy, const HDR_Image& r) {
	double sum = 0.0;
	for (size_t i = 0; i < r.pixels.size(); i++)
		for (int c = 0; c < 3; c++) sum += relative(noisy.variance.pixels[i][c], r.pixels[i][c]);
	return sum / (3.0 * double(r.pixels.size()));
}
