#pragma once
// What the viewer shows and does, apart from HTTP (viewer_server.h): the renderers streaming the
// student's and the reference's films, their comparison by the graders' z-test
// (image_compare.h), the watch on the student's files with the rebuild it triggers, a pixel's path
// (--follow-pixel), and a task's grader. Every change is published on the event hub.
#include "event_hub.h"
#include "film_stream.h"
#include "render_process.h"
#include "z_heat_map.h"

#include <nlohmann/json.hpp>

#include <atomic>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

struct Viewer_Config {
	std::string scene;      // the scene file first shown
	std::string out_dir;    // where snapshots are written
	std::string student_renderer, reference_renderer; // programs (pathtracer_student, pathtracer_reference)
	bool compare = true;    // the student's render beside the reference's; false: the reference alone
	std::string student_dir; // watched for edits (empty: not watched)
	std::vector<std::string> rebuild_command; // rebuilds student_renderer (empty: never rebuilt)
	std::vector<std::string> grade_command;   // runs a task's grader, given the task number after it
	uint32_t max_samples = 4096; // samples per pixel a render stops at
	uint32_t threads = 0;        // per renderer (0: all cores)
	uint64_t seed = 0;
};

// A request the viewer refuses, with the HTTP status that says why (400 bad value, 404 no such
// thing, 409 not now) and a message naming what was expected.
struct Request_Error : std::runtime_error {
	Request_Error(int status, const std::string& message) : std::runtime_error(message), status(status) {
	}
	int status;
};

enum class Side { student, reference };
const char* side_name(Side side);
Side side_named(const std::string& name); // throws Request_Error

// samples: each pixel's samples as the heat ramp of samples / the frame's (sRGB, 3 bytes a pixel):
// with adaptive sampling (task 8), the rate map.
enum class Layer { mean, variance, non_finite, z, samples };
Layer layer_named(const std::string& name); // throws Request_Error

class Viewer_Session {
public:
	Viewer_Session(Viewer_Config config, Event_Hub& hub);
	~Viewer_Session();

	// Starts the renders (the student's after its build, if there is a rebuild command) and the
	// watch on the student's files.
	void start();

	struct Restart {
		std::optional<uint64_t> seed;
		std::optional<std::string> view;
		std::optional<std::string> scene; // a file name in the scene's folder
		std::optional<float> adaptive;    // the threshold of adaptive sampling (task 8); 0: off
	};
	// Throws Request_Error for an unknown view, or a scene that is not a .json file of the folder.
	void restart(const Restart& changes);
	void pause();
	void resume();

	nlohmann::json state() const;

	// A layer of the latest frame of a side, as the page draws it: mean and variance as float32 RGB,
	// non_finite as one byte per pixel (1: a sample was NaN or infinite), z as the z-map's sRGB
	// colours (3 bytes per pixel; the comparison's frames). Throws Request_Error(409) before the
	// first frame.
	struct Image {
		uint32_t width = 0, height = 0, samples = 0;
		uint64_t generation = 0; // which render of the side (it restarts after an edit, a new seed...)
		std::string bytes;
	};
	Image image(Side side, Layer layer) const;

	// The paths of pixel (x, y) as --follow-pixel --follow-format json gives them: its first
	// `samples` samples, or of them the `brightest`. Throws Request_Error for a pixel outside the
	// image, 500 if the renderer fails.
	std::string follow(Side side, uint32_t x, uint32_t y, uint32_t samples, uint32_t brightest) const;

	// Runs the grader of task 1-8 in the background, its output published line by line; throws
	// Request_Error(409) while one runs.
	void grade(int task);

	// Writes the side's latest mean as OUT/NAME (a PNG, exposure in stops); returns its path.
	std::string snapshot(Side side, const std::string& name, float exposure) const;

	// Rebuilds the student's renderer and restarts its render (the watch calls it after an edit).
	void rebuild_student();

	// The scene files the page may choose from: *.json in the scene's folder.
	std::vector<std::string> scene_names() const;

private:
	struct Render_Side {
		std::unique_ptr<Render_Process> process;
		std::shared_ptr<const Film_Frame> frame;
		std::string state = "waiting"; // waiting, rendering, finished, failed, build failed
		std::string message;
		uint64_t generation = 0; // frames of an older process are ignored
	};
	struct Comparison {
		std::shared_ptr<const Film_Frame> student, reference;
		nlohmann::json summary;
		std::vector<Srgb8> colours;
	};

	std::vector<std::string> renderer_arguments(Side side) const;
	// Like with like: whether the student's renderer samples the lights (its task 6's
	// sample_incoming calls sample_area_lights), found by following a few of its paths; the
	// reference then renders the same estimator (match_reference_estimator).
	bool student_samples_lights_now() const;
	bool probe_student_estimator(); // probes and keeps the answer: true when it changed
	void match_reference_estimator();
	void start_side(Side side);
	std::unique_ptr<Render_Process> stop_side(Side side); // to destroy outside the lock
	void on_frame(Side side, uint64_t generation, std::shared_ptr<const Film_Frame> frame);
	void on_end(Side side, uint64_t generation, int status, const std::string& errors);
	void compare_latest();
	void compare_when_asked(); // the comparer thread: compares the latest frames once asked
	void watch_student_files();
	void publish_state();
	nlohmann::json state_locked() const; // with the mutex held
	// Runs a build or a grader, handing each line of its output (and standard error) to `line`;
	// returns its exit status. The destructor kills it.
	int run_lines(const std::vector<std::string>& argv, const std::function<void(const std::string&)>& line);
	Render_Side& side(Side s) {
		return s == Side::student ? student : reference;
	}
	const Render_Side& side(Side s) const {
		return s == Side::student ? student : reference;
	}

	Viewer_Config config;
	Event_Hub& hub;
	mutable std::mutex mutex;
	std::string scene;
	std::string view = "path";
	uint64_t seed;
	float adaptive = 0.0f; // --adaptive of both renderers; 0: off
	bool paused = false;
	// The estimator the reference renders beside the student's (renderer_arguments): task 4's path
	// tracer, as the student's renderer is, with light sampling only if the student's task 6 samples
	// the lights. Until the first probe, as a finished task 6 does.
	bool student_samples_lights = true;
	Render_Side student, reference;
	std::shared_ptr<const Comparison> comparison;
	std::string build_state = "none"; // none, building, failed, ok
	int grading = 0;                  // the task whose grader runs, or 0

	std::mutex build_mutex; // one build at a time
	std::atomic<bool> stopping{false};
	std::thread watcher, builder, grader, comparer;
	// New frames to compare: set by the frame readers, taken by the comparer, so that a reader
	// goes back to its pipe at once (the renderer waits while its frame is unread).
	bool comparison_wanted = false;
	std::condition_variable comparison_asked;
	std::vector<Child_Process*> running; // builds and graders, under `mutex`
};
