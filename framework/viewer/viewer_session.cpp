#include "viewer_session.h"
#include "block_compare.h"
#include "diagnostics.h"
#include "heat_ramp.h"
#include "image_io.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;

namespace {
const std::vector<std::string> VIEWS{"path", "eye", "normals", "albedo", "bvh", "direction"};

// A file name the page may give: letters, digits, '_', '.' and '-', not starting with '.', with
// the extension asked for; never a path.
bool plain_file_name(const std::string& name, const std::string& extension) {
	static const std::regex plain("[A-Za-z0-9_][A-Za-z0-9_.-]*");
	return name.size() <= 128 && std::regex_match(name, plain) && name.size() > extension.size() &&
	       name.compare(name.size() - extension.size(), extension.size(), extension) == 0;
}

nlohmann::json frame_summary(const Film_Frame& frame) {
	double samples = double(frame.samples) * frame.width() * frame.height();
	return {{"samples", frame.samples},
	        {"seconds", frame.seconds},
	        {"samples_per_second", frame.seconds > 0.0 ? samples / frame.seconds : 0.0},
	        {"non_finite", frame.non_finite_total()},
	        {"width", frame.width()},
	        {"height", frame.height()}};
}

// The bytes of a float image, as the page reads them (Float32Array, RGB).
std::string float_bytes(const HDR_Image& image) {
	std::string bytes(image.pixels.size() * 3 * sizeof(float), '\0');
	for (size_t i = 0; i < image.pixels.size(); i++) {
		float rgb[3] = {image.pixels[i].r, image.pixels[i].g, image.pixels[i].b};
		std::memcpy(&bytes[i * sizeof rgb], rgb, sizeof rgb);
	}
	return bytes;
}
// How noisy the student's render is against the reference's, for the student to read: a grader
// bounds this ratio (noise_bound.h) against a reference of many samples, which a render in
// progress is not, so the page only shows it.
std::string noise_ratio(const Image_Estimate& student, const Image_Estimate& reference) {
	double yours = 0.0, theirs = 0.0;
	for (size_t i = 0; i < student.variance.pixels.size(); i++) {
		for (int ch = 0; ch < 3; ch++) yours += student.variance.pixels[i][ch], theirs += reference.variance.pixels[i][ch];
	}
	std::ostringstream out;
	out.precision(3);
	out << "your render's per-sample variance is " << yours / theirs << " times the reference's";
	return out.str();
}

} // namespace

const char* side_name(Side side) {
	return side == Side::student ? "student" : "reference";
}

Side side_named(const std::string& name) {
	if (name == "student") return Side::student;
	if (name == "reference") return Side::reference;
	throw Request_Error(400, "side: expected student or reference, got '" + name + "'");
}

Layer layer_named(const std::string& name) {
	if (name == "mean") return Layer::mean;
	if (name == "variance") return Layer::variance;
	if (name == "non_finite") return Layer::non_finite;
	if (name == "z") return Layer::z;
	if (name == "samples") return Layer::samples;
	throw Request_Error(400, "layer: expected mean, variance, non_finite, z or samples, got '" + name + "'");
}

Viewer_Session::Viewer_Session(Viewer_Config config_, Event_Hub& hub_)
	: config(std::move(config_)), hub(hub_), scene(config.scene), seed(config.seed) {
}

Viewer_Session::~Viewer_Session() {
	{
		std::lock_guard<std::mutex> lock(mutex);
		stopping = true;
		for (Child_Process* child : running) child->kill();
	}
	comparison_asked.notify_all();
	for (std::thread* thread : {&watcher, &builder, &grader, &comparer}) {
		if (thread->joinable()) thread->join();
	}
	auto a = stop_side(Side::student);
	auto b = stop_side(Side::reference);
}

void Viewer_Session::start() {
	if (!config.compare) {
		start_side(Side::reference);
		return;
	}
	comparer = std::thread([this] { compare_when_asked(); });
	if (config.rebuild_command.empty()) {
		// The student's renderer is built: its estimator decides the reference's before either
		// starts, so that the reference's first pictures are not thrown away a moment later.
		probe_student_estimator();
		start_side(Side::reference);
		start_side(Side::student);
	} else {
		start_side(Side::reference); // while the student's code builds; matched once it has
		builder = std::thread([this] { rebuild_student(); });
	}
	if (!config.student_dir.empty()) watcher = std::thread([this] { watch_student_files(); });
}

std::vector<std::string> Viewer_Session::renderer_arguments(Side s) const {
	// The reference renders with another seed than the student's, so that the two are independent
	// estimates, as a grader's reference is.
	uint64_t side_seed = s == Side::reference && config.compare ? seed + 1 : seed;
	std::vector<std::string> args{s == Side::student ? config.student_renderer : config.reference_renderer,
	                              scene, "--spp", std::to_string(config.max_samples), "--view", view,
	                              "--seed", std::to_string(side_seed)};
	if (config.threads) args.insert(args.end(), {"--threads", std::to_string(config.threads)});
	if (adaptive > 0.0f) args.insert(args.end(), {"--adaptive", std::to_string(adaptive)});
	// Like with like: beside the student's render the reference renders the same estimator, never
	// another with other noise (its default, next-event estimation, has far lighter tails than task
	// 4's path tracer, whose pixels at a few hundred samples have rarely met a small light yet: the
	// z-test would blame correct code). The student's renderer runs task 4's path tracer with task
	// 6's sample_incoming, which samples the lights only once task 6 is done. Both sides say so, so that
	// a student renderer whose default is another estimator (the reference's, in a test) is compared
	// alike.
	if (config.compare) {
		args.insert(args.end(), {"--integrator", "mixture"});
		if (s == Side::reference && !student_samples_lights) args.push_back("--no-light-sampling");
	}
	return args;
}

bool Viewer_Session::student_samples_lights_now() const {
	// A few paths of three pixels of a small film: with a finished task 6, the first diffuse hit of
	// a path samples the lights with probability 1/2, so 3 x 32 paths all miss it with probability
	// 2^-96 where a diffuse surface is seen. A renderer that cannot follow (it crashes, or hangs:
	// each run has 10 seconds) keeps the finished estimator.
	std::string scene_now, seed_now;
	{
		std::lock_guard<std::mutex> lock(mutex);
		scene_now = scene, seed_now = std::to_string(seed);
	}
	for (const char* pixel : {"16,16", "8,24", "24,24"}) {
		std::vector<std::string> args{config.student_renderer, scene_now, "--width", "32", "--height", "32",
		                              "--view", "path", "--integrator", "mixture", "--seed", seed_now,
		                              "--follow-pixel", pixel,
		                              "--follow-format", "json", "--follow-samples", "32"};
		std::string out, err;
		if (run_program(args, out, err, 10) != 0) return true;
		if (out.find("\"light_sample\"") != std::string::npos) return true;
	}
	return false;
}

bool Viewer_Session::probe_student_estimator() {
	bool samples_lights = student_samples_lights_now();
	std::lock_guard<std::mutex> lock(mutex);
	bool changed = samples_lights != student_samples_lights;
	student_samples_lights = samples_lights;
	return changed;
}

void Viewer_Session::match_reference_estimator() {
	if (!config.compare || !probe_student_estimator()) return;
	{
		std::lock_guard<std::mutex> lock(mutex);
		if (stopping) return;
	}
	start_side(Side::reference); // the same seed and samples, now the student's estimator
	publish_state();
}

void Viewer_Session::start_side(Side s) {
	std::unique_ptr<Render_Process> old;
	{
		std::lock_guard<std::mutex> lock(mutex);
		Render_Side& rs = side(s);
		old = std::move(rs.process);
		uint64_t generation = ++rs.generation;
		std::vector<std::string> args = renderer_arguments(s);
		args.push_back("--stream");
		rs.frame.reset();
		rs.state = "rendering";
		rs.message.clear();
		comparison.reset();
		rs.process = std::make_unique<Render_Process>(
			args, [this, s, generation](std::shared_ptr<const Film_Frame> f) { on_frame(s, generation, std::move(f)); },
			[this, s, generation](int status, const std::string& errors) { on_end(s, generation, status, errors); });
		if (paused) rs.process->pause();
	}
	hub.publish("renderer", nlohmann::json{{"side", side_name(s)}, {"state", "rendering"}}.dump());
}

std::unique_ptr<Render_Process> Viewer_Session::stop_side(Side s) {
	std::lock_guard<std::mutex> lock(mutex);
	Render_Side& rs = side(s);
	rs.generation++;
	return std::move(rs.process);
}

void Viewer_Session::on_frame(Side s, uint64_t generation, std::shared_ptr<const Film_Frame> frame) {
	nlohmann::json event;
	{
		std::lock_guard<std::mutex> lock(mutex);
		Render_Side& rs = side(s);
		if (generation != rs.generation) return;
		rs.frame = frame;
		event = frame_summary(*frame);
		event["side"] = side_name(s);
		event["generation"] = generation;
	}
	hub.publish("frame", event.dump());
	if (config.compare) {
		std::lock_guard<std::mutex> lock(mutex);
		comparison_wanted = true;
		comparison_asked.notify_one();
	}
}

void Viewer_Session::compare_when_asked() {
	for (;;) {
		{
			std::unique_lock<std::mutex> lock(mutex);
			comparison_asked.wait(lock, [this] { return comparison_wanted || stopping; });
			if (stopping) return;
			comparison_wanted = false;
		}
		compare_latest();
	}
}

void Viewer_Session::on_end(Side s, uint64_t generation, int status, const std::string& errors) {
	nlohmann::json event{{"side", side_name(s)}, {"status", status}};
	{
		std::lock_guard<std::mutex> lock(mutex);
		Render_Side& rs = side(s);
		if (generation != rs.generation) return;
		rs.state = status == 0 ? "finished" : "failed";
		rs.message = status == 0 ? "" : last_lines(errors, 40);
		if (status > 128) rs.message += "(the renderer was killed by signal " + std::to_string(status - 128) + ")\n";
		event["state"] = rs.state;
		event["message"] = rs.message;
	}
	hub.publish("renderer", event.dump());
}

void Viewer_Session::compare_latest() {
	auto result = std::make_shared<Comparison>();
	{
		std::lock_guard<std::mutex> lock(mutex);
		result->student = student.frame;
		result->reference = reference.frame;
		if (!result->student || !result->reference) return;
		if (comparison && comparison->student == result->student && comparison->reference == result->reference) return;
	}
	bool samples_lights;
	{
		std::lock_guard<std::mutex> lock(mutex);
		samples_lights = student_samples_lights;
	}
	const Film_Frame& s = *result->student;
	const Film_Frame& r = *result->reference;
	if (s.width() != r.width() || s.height() != r.height()) return;
	// The graders' z-tests (image_compare.h) for two estimates of few samples each, which a stored
	// reference's calibration does not fit: each pixel's larger variance, at most 0.25 % beyond z_c.
	Image_Comparison c = compare_estimators(s.estimate, r.estimate);
	// And the means over blocks of pixels, which heavy tails cannot hide (block_compare.h).
	Block_Comparison blocks = compare_blocks(s.estimate, r.estimate);
	result->colours = z_colours_of(estimator_z_scores(s.estimate, r.estimate), c.z_critical);
	mark_failing_blocks(blocks, s.width(), s.height(), result->colours);
	result->summary = {{"student_samples", s.samples},
	                   {"reference_samples", r.samples},
	                   {"pass", c.pass && blocks.pass},
	                   {"failed", c.failed},
	                   {"tests", c.tests},
	                   {"allowed", c.allowed_outliers},
	                   {"z_critical", c.z_critical},
	                   {"rel_mse", c.rel_mse},
	                   {"worst", {{"x", c.worst_x}, {"y", c.worst_y}, {"z", c.worst_z}}},
	                   {"reference_estimator", samples_lights ? "task 4's path tracer with task 6's mixture of BSDF "
	                                                            "and light sampling, as yours"
	                                                          : "task 4's path tracer sampling the BSDF only, as "
	                                                            "yours does until task 6 samples the lights"},
	                   {"message", c.message + "; " + blocks.message + "; " + noise_ratio(s.estimate, r.estimate)}};
	{
		std::lock_guard<std::mutex> lock(mutex);
		if (student.frame != result->student || reference.frame != result->reference) return; // outdated
		comparison = result;
	}
	hub.publish("comparison", result->summary.dump());
}

void Viewer_Session::restart(const Restart& changes) {
	if (changes.adaptive && !(*changes.adaptive == 0.0f || (*changes.adaptive >= 0.001f && *changes.adaptive <= 1.0f))) {
		throw Request_Error(400, "adaptive: expected 0 (off) or a relative precision from 0.001 to 1, got " +
		                             std::to_string(*changes.adaptive));
	}
	if (changes.view && std::find(VIEWS.begin(), VIEWS.end(), *changes.view) == VIEWS.end()) {
		throw Request_Error(400, "view: expected path, eye, normals, albedo, bvh or direction, got '" + *changes.view + "'");
	}
	std::string new_scene = scene;
	if (changes.scene) {
		std::vector<std::string> names = scene_names();
		if (!plain_file_name(*changes.scene, ".json")) {
			throw Request_Error(400, "scene: expected the name of a .json file in " +
			                             fs::path(config.scene).parent_path().string() + "/ (e.g. cornell_box.json), got '" +
			                             *changes.scene + "'");
		}
		if (std::find(names.begin(), names.end(), *changes.scene) == names.end()) {
			throw Request_Error(404, "scene: there is no " + *changes.scene + " in " +
			                             fs::path(config.scene).parent_path().string() + "/");
		}
		new_scene = (fs::path(config.scene).parent_path() / *changes.scene).string();
	}
	auto old_student = stop_side(Side::student);
	auto old_reference = stop_side(Side::reference);
	old_student.reset();
	old_reference.reset();
	// Whether the student's code samples the lights shows only in a scene that has some.
	bool probe = changes.scene && config.compare;
	bool student_buildable;
	{
		std::lock_guard<std::mutex> lock(mutex);
		if (changes.seed) seed = *changes.seed;
		if (changes.view) view = *changes.view;
		if (changes.adaptive) adaptive = *changes.adaptive;
		scene = new_scene;
		paused = false;
		student_buildable = build_state != "failed" && build_state != "building";
		comparison.reset();
	}
	if (probe && student_buildable) probe_student_estimator();
	publish_state();
	start_side(Side::reference);
	if (config.compare && student_buildable) start_side(Side::student);
}

void Viewer_Session::pause() {
	std::lock_guard<std::mutex> lock(mutex);
	paused = true;
	for (Render_Side* rs : {&student, &reference}) {
		if (rs->process) rs->process->pause();
	}
	hub.publish("state", state_locked().dump());
}

void Viewer_Session::resume() {
	std::lock_guard<std::mutex> lock(mutex);
	paused = false;
	for (Render_Side* rs : {&student, &reference}) {
		if (rs->process) rs->process->resume();
	}
	hub.publish("state", state_locked().dump());
}

std::vector<std::string> Viewer_Session::scene_names() const {
	std::vector<std::string> names;
	std::error_code error;
	for (const auto& entry : fs::directory_iterator(fs::path(config.scene).parent_path(), error)) {
		std::string name = entry.path().filename().string();
		if (entry.is_regular_file() && plain_file_name(name, ".json")) names.push_back(name);
	}
	std::sort(names.begin(), names.end());
	return names;
}

nlohmann::json Viewer_Session::state() const {
	std::lock_guard<std::mutex> lock(mutex);
	return state_locked();
}

nlohmann::json Viewer_Session::state_locked() const {
	nlohmann::json sides = nlohmann::json::object();
	for (Side s : {Side::student, Side::reference}) {
		if (s == Side::student && !config.compare) continue;
		const Render_Side& rs = side(s);
		nlohmann::json entry{{"state", rs.state}, {"message", rs.message}};
		if (rs.frame) entry["frame"] = frame_summary(*rs.frame);
		sides[side_name(s)] = entry;
	}
	nlohmann::json result{{"scene", fs::path(scene).filename().string()},
	                      {"scenes", scene_names()},
	                      {"scene_folder", fs::path(config.scene).parent_path().string()},
	                      {"view", view},
	                      {"views", VIEWS},
	                      {"seed", seed},
	                      {"adaptive", adaptive},
	                      {"paused", paused},
	                      {"compare", config.compare},
	                      {"max_samples", config.max_samples},
	                      {"build", build_state},
	                      {"grading", grading},
	                      {"watching", config.student_dir},
	                      {"sides", sides},
	                      {"comparison", comparison ? comparison->summary : nlohmann::json(nullptr)}};
	return result;
}

void Viewer_Session::publish_state() {
	hub.publish("state", state().dump());
}

Viewer_Session::Image Viewer_Session::image(Side s, Layer layer) const {
	std::shared_ptr<const Film_Frame> frame;
	std::shared_ptr<const Comparison> compared;
	uint64_t generation;
	{
		std::lock_guard<std::mutex> lock(mutex);
		if (s == Side::student && !config.compare) throw Request_Error(404, "this viewer shows the reference alone (./lab view --reference)");
		frame = side(s).frame;
		generation = side(s).generation;
		compared = comparison;
	}
	if (layer == Layer::z) {
		if (!compared) throw Request_Error(409, "no z-map yet: it needs a picture of both sides");
		frame = s == Side::student ? compared->student : compared->reference;
	}
	if (!frame) throw Request_Error(409, std::string("no picture of the ") + side_name(s) + " side yet");
	Image image{frame->width(), frame->height(), frame->samples, generation, {}};
	switch (layer) {
	case Layer::mean: image.bytes = float_bytes(frame->estimate.mean); break;
	case Layer::variance: image.bytes = float_bytes(frame->estimate.variance); break;
	case Layer::non_finite:
		for (uint32_t n : frame->non_finite) image.bytes.push_back(n > 0 ? 1 : 0);
		break;
	case Layer::z:
		image.bytes.assign(reinterpret_cast<const char*>(compared->colours.data()), compared->colours.size() * 3);
		break;
	case Layer::samples:
		for (uint32_t i = 0; i < frame->estimate.samples.size(); i++) {
			float rate = float(frame->estimate.samples[i] + frame->non_finite[i]) / float(std::max(1u, frame->samples));
			for (uint8_t byte : png_pixel(heat_ramp(rate))) image.bytes.push_back(char(byte));
		}
		break;
	}
	return image;
}

std::string Viewer_Session::follow(Side s, uint32_t x, uint32_t y, uint32_t samples, uint32_t brightest) const {
	std::vector<std::string> args;
	{
		std::lock_guard<std::mutex> lock(mutex);
		if (s == Side::student && !config.compare) throw Request_Error(404, "this viewer shows the reference alone (./lab view --reference)");
		const Render_Side& rs = side(s);
		if (!rs.frame) throw Request_Error(409, std::string("no picture of the ") + side_name(s) + " side yet");
		if (x >= rs.frame->width() || y >= rs.frame->height()) {
			throw Request_Error(400, "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
			                             std::to_string(rs.frame->width()) + " x " + std::to_string(rs.frame->height()) +
			                             " image");
		}
		args = renderer_arguments(s);
	}
	args.insert(args.end(), {"--follow-pixel", std::to_string(x) + "," + std::to_string(y), "--follow-format", "json",
	                         "--follow-samples", std::to_string(samples)});
	if (brightest) args.insert(args.end(), {"--follow-brightest", std::to_string(brightest)});
	std::string out, err;
	int status = run_program(args, out, err);
	if (status != 0) {
		throw Request_Error(500, std::string("the ") + side_name(s) + " renderer failed to follow the pixel (exit status " +
		                             std::to_string(status) + "):\n" + last_lines(err, 40));
	}
	return out;
}

std::string Viewer_Session::snapshot(Side s, const std::string& name, float exposure) const {
	if (!plain_file_name(name, ".png")) {
		throw Request_Error(400, "name: expected a file name ending in .png (letters, digits, _ . -), got '" + name + "'");
	}
	std::shared_ptr<const Film_Frame> frame;
	{
		std::lock_guard<std::mutex> lock(mutex);
		frame = side(s).frame;
	}
	if (!frame) throw Request_Error(409, std::string("no picture of the ") + side_name(s) + " side yet");
	fs::create_directories(config.out_dir);
	std::string path = (fs::path(config.out_dir) / name).string();
	write_png(path, frame->estimate.mean, exposure);
	return path;
}
