// ./lab view's server (framework/viewer/viewer_server.h), over HTTP on 127.0.0.1 as a page uses it:
// the token, the status of every kind of bad request, paths kept inside the scene's and the output
// folder, the picture after N samples, the z-test's verdict, a pixel's path and a grader's lines.
// The renderers are the real ones (LAB_REFERENCE_RENDERER, LAB_STUDENT_RENDERER: the shipped
// stubs), on a 32 x 32 Cornell box.
#include "error.h"
#include "image_io.h"
#include "viewer_server.h"

#include "lab_catch2.h"
#include <httplib.h>

#include <array>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

namespace fs = std::filesystem;
using namespace std::chrono_literals;

namespace {
std::string environment(const char* name) {
	const char* value = std::getenv(name);
	if (!value) FAIL(name << " is not set (ctest sets it: tests/viewer/CMakeLists.txt)");
	return value;
}

// A scratch folder with scenes/cornell_box.json at 32 x 32 pixels and an out/ folder beside it.
fs::path scratch_folder(const std::string& name) {
	fs::path dir = fs::path(environment("LAB_TEST_DIR")) / name;
	fs::remove_all(dir);
	fs::create_directories(dir / "scenes");
	nlohmann::json scene = nlohmann::json::parse(std::ifstream("scenes/cornell_box.json"));
	scene["film"]["width"] = 32;
	scene["film"]["height"] = 32;
	std::ofstream(dir / "scenes" / "cornell_box.json") << scene.dump();
	return dir;
}

// A viewer on a free port, serving from its own thread until the test ends.
struct Running_Viewer {
	explicit Running_Viewer(const Viewer_Config& config)
		: session(config, hub), server(session, hub, new_token()), port(server.bind(0)),
		  client("127.0.0.1", port) {
		session.start();
		thread = std::thread([this] { server.serve(); });
		client.set_read_timeout(60s);
	}
	~Running_Viewer() {
		server.stop();
		thread.join();
	}
	std::string with_token(const std::string& path) const {
		return path + (path.find('?') == std::string::npos ? "?" : "&") + "token=" + server.url_token();
	}
	httplib::Result get(const std::string& path) {
		return client.Get(with_token(path).c_str());
	}
	httplib::Result post(const std::string& path) {
		return client.Post(with_token(path).c_str());
	}
	// Waits up to a minute for the side's latest frame to have `samples` samples.
	void wait_for_samples(const std::string& side, uint32_t samples) {
		for (auto start = std::chrono::steady_clock::now(); std::chrono::steady_clock::now() - start < 60s;) {
			nlohmann::json state = session.state();
			auto& frame = state["sides"][side]["frame"];
			if (frame.is_object() && frame["samples"] >= samples) return;
			std::this_thread::sleep_for(20ms);
		}
		FAIL("the " << side << " side did not reach " << samples << " samples within a minute: " << session.state().dump());
	}

	Event_Hub hub;
	Viewer_Session session;
	Viewer_Server server;
	int port;
	httplib::Client client;
	std::thread thread;
};

Viewer_Config config_in(const fs::path& dir, uint32_t samples) {
	Viewer_Config config;
	config.scene = (dir / "scenes" / "cornell_box.json").string();
	config.out_dir = (dir / "out").string();
	config.reference_renderer = environment("LAB_REFERENCE_RENDERER");
	config.student_renderer = environment("LAB_STUDENT_RENDERER");
	config.max_samples = samples;
	return config;
}

std::string error_of(const httplib::Result& result) {
	return nlohmann::json::parse(result->body).value("error", "");
}
} // namespace

TEST_CASE("Every request without the viewer's token is refused with 403, whatever it asks", "[viewer]") {
	fs::path dir = scratch_folder("token");
	Running_Viewer viewer(config_in(dir, 4));
	for (std::string path : {"/", "/viewer.js", "/api/state", "/api/events", "/api/image?side=student&layer=mean",
	                         "/api/path?side=student&x=1&y=1", "/no/such/page", "/../../etc/passwd"}) {
		INFO(path);
		auto without = viewer.client.Get(path.c_str());
		REQUIRE(without);
		CHECK(without->status == 403);
		CHECK(error_of(without).find("token") != std::string::npos);
		auto wrong = viewer.client.Get((path + (path.find('?') == std::string::npos ? "?" : "&") + "token=0123").c_str());
		CHECK(wrong->status == 403);
	}
	CHECK(viewer.client.Post("/api/grade?task=1")->status == 403);
	auto page = viewer.get("/");
	CHECK(page->status == 200);
	// The page's own links carry the token.
	CHECK(page->body.find("viewer.js?token=" + viewer.server.url_token()) != std::string::npos);
	CHECK(viewer.get("/viewer.js")->status == 200);
}

TEST_CASE("A malformed request gets a 4xx answer that names what was expected", "[viewer]") {
	fs::path dir = scratch_folder("malformed");
	Running_Viewer viewer(config_in(dir, 2));
	viewer.wait_for_samples("student", 1);
	struct Case {
		std::string method, path;
		int status;
		std::string says;
	};
	std::vector<Case> cases{
		{"GET", "/api/image?side=left&layer=mean", 400, "expected student or reference"},
		{"GET", "/api/image?side=student", 400, "missing parameter layer"},
		{"GET", "/api/image?side=student&layer=depth", 400, "expected mean, variance, non_finite, z or samples"},
		{"GET", "/api/path?side=student&x=abc&y=1", 400, "x: expected a whole number"},
		{"GET", "/api/path?side=student&x=-1&y=1", 400, "x: expected a whole number"},
		{"GET", "/api/path?side=student&x=32&y=1", 400, "outside the 32 x 32 image"},
		{"GET", "/api/path?side=student&x=1&y=1&samples=0", 400, "samples: expected a whole number from 1"},
		{"POST", "/api/grade?task=9", 400, "task: expected a whole number from 1 to 8"},
		{"POST", "/api/grade", 400, "missing parameter task"},
		{"POST", "/api/restart?view=xray", 400, "view: expected path, eye, normals, albedo, bvh or direction"},
		{"POST", "/api/restart?seed=-1", 400, "seed: expected a whole number"},
		{"POST", "/api/snapshot?side=student", 400, "missing parameter name"},
		{"POST", "/api/snapshot?side=student&name=a.png&exposure=a", 400, "exposure: expected a number of stops"},
		{"GET", "/api/nothing", 404, "no such page or call: GET /api/nothing"},
		{"GET", "/api/grade?task=1", 404, "no such page or call"}, // a change of state is a POST
	};
	for (const Case& c : cases) {
		INFO(c.method << " " << c.path);
		auto result = c.method == "GET" ? viewer.get(c.path) : viewer.post(c.path);
		REQUIRE(result);
		CHECK(result->status == c.status);
		CHECK_THAT(error_of(result), contains_text(c.says));
	}
	CHECK(viewer.get("/api/state")->status == 200); // and the viewer goes on
}

TEST_CASE("No path from the browser reaches beyond the scene's folder and the output folder", "[viewer]") {
	fs::path dir = scratch_folder("paths");
	std::ofstream(dir / "secret.json") << "{}"; // beside the scene folder: never reachable
	Running_Viewer viewer(config_in(dir, 2));
	viewer.wait_for_samples("reference", 1);
	for (std::string scene : {"../secret.json", "..%2Fsecret.json", "%2e%2e/secret.json", "/etc/passwd",
	                          "scenes/cornell_box.json", ".hidden.json", "cornell_box.obj"}) {
		INFO("scene=" << scene);
		auto result = viewer.post("/api/restart?scene=" + scene);
		CHECK(result->status == 400);
		CHECK_THAT(error_of(result), contains_text("expected the name of a .json file in"));
	}
	auto missing = viewer.post("/api/restart?scene=missing.json");
	CHECK(missing->status == 404);
	for (std::string name : {"../escaped.png", "..%2Fescaped.png", "/tmp/escaped.png", "picture.exr", ".png"}) {
		INFO("name=" << name);
		auto result = viewer.post("/api/snapshot?side=reference&name=" + name);
		CHECK(result->status == 400);
		CHECK_THAT(error_of(result), contains_text("expected a file name ending in .png"));
	}
	CHECK_FALSE(fs::exists(dir / "escaped.png"));
	auto written = viewer.post("/api/snapshot?side=reference&name=picture.png");
	CHECK(written->status == 200);
	CHECK(fs::exists(dir / "out" / "picture.png"));
	// The scenes the page may choose from are the folder's own.
	CHECK(viewer.session.state()["scenes"] == nlohmann::json::array({"cornell_box.json"}));
}

namespace {
// The pixels of an sRGB layer (3 bytes a pixel: z, samples) that have this colour.
size_t pixels_coloured(const std::string& layer, const std::array<uint8_t, 3>& colour) {
	size_t count = 0;
	for (size_t i = 0; i + 3 <= layer.size(); i += 3) count += std::memcmp(layer.data() + i, colour.data(), 3) == 0;
	return count;
}

// The picture the page got (float32 RGB) is the reference renderer's with these options, bit for bit.
void check_same_as_renderer(const std::string& picture, const Viewer_Config& config, const fs::path& dir,
                            const std::vector<std::string>& options) {
	std::string exr = (dir / "render.exr").string(), out, err;
	std::vector<std::string> args{config.reference_renderer, config.scene};
	args.insert(args.end(), options.begin(), options.end());
	args.insert(args.end(), {"--exr", exr, "--out", (dir / "render.png").string(), "--quiet"});
	REQUIRE(run_program(args, out, err) == 0);
	HDR_Image rendered = read_image(exr);
	REQUIRE(picture.size() == rendered.pixels.size() * 3 * sizeof(float));
	CHECK(std::memcmp(picture.data(), rendered.pixels.data(), picture.size()) == 0);
}
} // namespace

TEST_CASE("The picture after N samples is the renderer's --spp N, bit for bit", "[viewer]") {
	fs::path dir = scratch_folder("determinism");
	Viewer_Config config = config_in(dir, 12);
	config.compare = false; // the reference alone renders with the seed itself
	config.seed = 5;
	Running_Viewer viewer(config);
	viewer.wait_for_samples("reference", 12);
	auto image = viewer.get("/api/image?side=reference&layer=mean");
	REQUIRE(image->status == 200);
	CHECK(image->get_header_value("X-Samples") == "12");
	check_same_as_renderer(image->body, config, dir, {"--spp", "12", "--seed", "5"});
}

TEST_CASE("With adaptive sampling the last picture is the renderer's --adaptive render, and its samples map shows "
          "where pixels stopped", "[viewer]") {
	fs::path dir = scratch_folder("adaptive");
	Viewer_Config config = config_in(dir, 128);
	config.compare = false;
	config.seed = 3;
	Running_Viewer viewer(config);
	auto bad = viewer.post("/api/restart?adaptive=2");
	CHECK(bad->status == 400);
	CHECK_THAT(bad->body, contains_text("adaptive: expected 0 (off) or a relative precision from 0.001 to 1"));
	REQUIRE(viewer.post("/api/restart?adaptive=0.1")->status == 200);
	CHECK(viewer.session.state()["adaptive"] == 0.1f);
	viewer.wait_for_samples("reference", 128);
	auto image = viewer.get("/api/image?side=reference&layer=mean");
	REQUIRE(image->status == 200);
	check_same_as_renderer(image->body, config, dir, {"--spp", "128", "--seed", "3", "--adaptive", "0.1"});
	// The samples map: the noisiest pixels take all 128 samples (white), the others stop before.
	auto rate = viewer.get("/api/image?side=reference&layer=samples");
	REQUIRE(rate->status == 200);
	REQUIRE(rate->body.size() == 32 * 32 * 3);
	size_t white = pixels_coloured(rate->body, {255, 255, 255});
	CHECK(white > 0);
	CHECK(white < 32 * 32);
}

TEST_CASE("The z-map and the verdict are the graders': a black render fails, too dark", "[viewer]") {
	fs::path dir = scratch_folder("verdict");
	Running_Viewer viewer(config_in(dir, 16)); // the shipped stubs render black
	viewer.wait_for_samples("student", 16);
	viewer.wait_for_samples("reference", 16);
	nlohmann::json comparison;
	for (int i = 0; i < 500 && !(comparison = viewer.session.state()["comparison"]).is_object(); i++) std::this_thread::sleep_for(10ms);
	REQUIRE(comparison.is_object());
	CHECK(comparison["pass"] == false);
	CHECK_THAT(comparison["message"].get<std::string>(), contains_text("the render is too dark there"));
	auto z = viewer.get("/api/image?side=student&layer=z");
	REQUIRE(z->status == 200);
	REQUIRE(z->body.size() == 32 * 32 * 3);
	CHECK(pixels_coloured(z->body, z_colours::fail_too_dark) > 32 * 32 / 4); // the lit walls, where 16 samples already tell
}

TEST_CASE("A clicked pixel's path comes back as JSON, from the renderer's own recorder", "[viewer]") {
	fs::path dir = scratch_folder("path");
	Viewer_Config config = config_in(dir, 4);
	config.compare = false;
	Running_Viewer viewer(config);
	viewer.wait_for_samples("reference", 1);
	auto result = viewer.get("/api/path?side=reference&x=16&y=30&samples=4&brightest=2"); // the floor
	REQUIRE(result->status == 200);
	nlohmann::json doc = nlohmann::json::parse(result->body);
	CHECK(doc["pixel"] == nlohmann::json::array({16, 30}));
	CHECK(doc["followed"] == 4);
	REQUIRE(doc["samples"].size() == 2);
	const nlohmann::json& hit = doc["samples"][0]["ray"]["hit"];
	CHECK(hit["material"] == "white");
	CHECK(std::abs(hit["position"][1].get<double>()) < 1e-3); // the floor is y = 0
	CHECK(std::abs(hit["film_pixel"][0].get<double>() - 16.5) < 1.0);
}

TEST_CASE("A grader run from the page sends its lines and its exit status; one runs at a time", "[viewer]") {
	fs::path dir = scratch_folder("grade");
	fs::path lab = dir / "lab"; // stands in for ./lab: `lab grade N`
	std::ofstream(lab) << "#!/bin/sh\necho \"$1 task $2\"\nsleep 1\necho 'last line'\nexit 3\n";
	fs::permissions(lab, fs::perms::owner_all);
	Viewer_Config config = config_in(dir, 1);
	config.grade_command = {lab.string(), "grade"};
	Running_Viewer viewer(config);
	auto events = viewer.hub.subscribe();
	auto started = viewer.post("/api/grade?task=4");
	CHECK(started->status == 202);
	auto second = viewer.post("/api/grade?task=5");
	CHECK(second->status == 409);
	CHECK_THAT(error_of(second), contains_text("the grader of task 4 is still running"));
	std::vector<std::string> lines;
	nlohmann::json graded;
	std::string event;
	for (auto start = std::chrono::steady_clock::now(); graded.is_null() && std::chrono::steady_clock::now() - start < 30s;) {
		if (!viewer.hub.next(events, event, 100ms)) continue;
		nlohmann::json data = nlohmann::json::parse(event.substr(event.find("data: ") + 6));
		if (event.rfind("event: grade\n", 0) == 0 && data.contains("line")) lines.push_back(data["line"]);
		if (event.rfind("event: graded\n", 0) == 0) graded = data;
	}
	CHECK(lines == std::vector<std::string>{"grade task 4", "last line"});
	REQUIRE(graded.is_object());
	CHECK(graded["status"] == 3);
	CHECK(viewer.post("/api/grade?task=5")->status == 202); // once it has ended
}

TEST_CASE("A renderer that crashes is shown as failed with its last words, and the viewer goes on", "[viewer]") {
	fs::path dir = scratch_folder("crash");
	fs::path crashing = dir / "pathtracer_crashing"; // stands in for a student's renderer that crashes
	std::ofstream(crashing) << "#!/bin/sh\necho 'in Triangle::hit' >&2\nkill -SEGV $$\n";
	fs::permissions(crashing, fs::perms::owner_all);
	Viewer_Config config = config_in(dir, 4);
	config.student_renderer = crashing.string();
	Running_Viewer viewer(config);
	nlohmann::json student;
	for (int i = 0; i < 500 && (student = viewer.session.state()["sides"]["student"])["state"] != "failed"; i++) {
		std::this_thread::sleep_for(10ms);
	}
	CHECK(student["state"] == "failed");
	CHECK_THAT(student["message"].get<std::string>(), contains_text("in Triangle::hit") && contains_text("killed by signal 11"));
	viewer.wait_for_samples("reference", 1); // the other side renders on
	CHECK(viewer.get("/api/image?side=student&layer=mean")->status == 409);
}

TEST_CASE("A student renderer that hangs does not hold up the viewer: its estimator probe stops at 10 s",
          "[viewer]") {
	fs::path dir = scratch_folder("hanging");
	fs::path hanging = dir / "hanging_renderer";
	std::ofstream(hanging) << "#!/bin/sh\nexec sleep 600\n";
	fs::permissions(hanging, fs::perms::owner_all);
	Viewer_Config config = config_in(dir, 2);
	config.student_renderer = hanging.string();
	auto start = std::chrono::steady_clock::now();
	Running_Viewer viewer(config);
	double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	INFO("the viewer started in " << seconds << " s");
	CHECK(seconds < 30); // 10 s for the probe, the rest for a loaded machine
	viewer.wait_for_samples("reference", 1);
}
