// The security suite (label security): one hostile student file per threat (tests/security/hostile/),
// each graded through the normal path (tools/grade-submission: sandboxed compile, subject in
// bubblewrap, verdicts by the judge) and required to earn nothing for its task, with the reason in
// the grade report. Where a threat has a side effect outside the grade (a file rewritten, a process
// left behind, a connection made), that it did not happen is checked too.
//
// Run from the repository root with LAB_KIT naming the grading kit (build/grading/kit.env).
#include "graded_images.h"
#include "sha256.h"
#include "temp_dir.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

namespace fs = std::filesystem;

namespace {

const std::map<int, std::string> TASK_FILES{{1, "task1_camera.cpp"}, {3, "task3_bvh.cpp"},
                                            {7, "task7_env_light.cpp"}};

std::string read_file(const fs::path& path) {
	std::ifstream in(path, std::ios::binary);
	return std::string(std::istreambuf_iterator<char>(in), {});
}

struct Grade {
	bool built = false;         // the file compiled and linked
	size_t test_cases = 0, passed = 0;
	std::string messages;       // every failure message the judge recorded, or the build log
	std::string report;         // the HTML page
};

// Grades `hostile` (with @NAME@ placeholders replaced) as the task's file of a fresh submission.
Grade grade(const std::string& hostile, int task, const std::map<std::string, std::string>& placeholders = {},
            const std::string& options = "") {
	Temp_Dir dir;
	fs::path submission = dir.path() / "submission", out = dir.path() / "out";
	fs::create_directories(submission);
	std::string source = read_file("tests/security/hostile/" + hostile);
	REQUIRE_FALSE(source.empty());
	std::map<std::string, std::string> all = placeholders;
	all.emplace("@ROOT@", fs::current_path().string());
	all.emplace("@OUT@", out.string());
	for (const auto& [key, value] : all) {
		for (size_t at; (at = source.find(key)) != std::string::npos;) source.replace(at, key.size(), value);
	}
	std::ofstream(submission / TASK_FILES.at(task)) << source;
	const char* kit = std::getenv("LAB_KIT");
	REQUIRE(kit != nullptr);
	std::string command = "KIT='" + std::string(kit) + "' tools/grade-submission '" + submission.string() +
	                      "' --out '" + out.string() + "' --tasks " + std::to_string(task) + " " + options +
	                      " > '" + dir.file("grading.log") + "' 2>&1";
	int status = std::system(command.c_str());
	INFO(read_file(dir.file("grading.log")));
	REQUIRE(status == 0);

	Grade grade;
	std::string name = "task" + std::to_string(task);
	grade.report = read_file(out / "index.html");
	if (fs::exists(out / (name + ".build.log"))) {
		grade.messages = read_file(out / (name + ".build.log"));
		return grade;
	}
	grade.built = true;
	nlohmann::json record = nlohmann::json::parse(read_file(out / (name + ".json")));
	for (const auto& test_case : record.at("test_cases")) {
		grade.test_cases++;
		grade.passed += test_case.at("passed").get<bool>();
		for (const auto& failure : test_case.at("failures")) {
			grade.messages += failure.value("expansion", "") + "\n";
			for (const auto& message : failure.at("messages")) grade.messages += message.get<std::string>() + "\n";
		}
	}
	// The judge ran every one of its test cases.
	CHECK(grade.test_cases == record.at("expected_test_cases").size());
	return grade;
}

// The hostile file earned nothing: it did not build, or every test case of its task failed; and
// the report shows why.
void require_nothing_earned(const Grade& grade, const std::string& reason) {
	INFO("the judge's messages:\n" << grade.messages.substr(0, 3000));
	if (grade.built) {
		CHECK(grade.test_cases > 0);
		CHECK(grade.passed == 0);
	}
	CHECK_THAT(grade.messages, Catch::Contains(reason));
	CHECK_THAT(grade.report, Catch::Contains(reason));
}

} // namespace

TEST_CASE("exit(0) in a static initializer earns nothing", "[security]") {
	require_nothing_earned(grade("task1_exit_in_static_initializer.cpp", 1), "exit status 0");
}

TEST_CASE("an atexit handler printing a forged summary earns nothing", "[security]") {
	require_nothing_earned(grade("task1_atexit_forged_summary.cpp", 1), "exit status 0");
}

TEST_CASE("_exit(0) on the first call of a task function earns nothing", "[security]") {
	require_nothing_earned(grade("task1_exit_on_first_call.cpp", 1), "ended before it answered");
}

TEST_CASE("an answer forged on the answer channel, with fewer results than asked for, earns nothing",
          "[security]") {
	require_nothing_earned(grade("task1_forged_short_answer.cpp", 1), "a result count its inputs do not call for");
}

TEST_CASE("a throw from a static initializer earns nothing", "[security]") {
	require_nothing_earned(grade("task1_throw_in_static_initializer.cpp", 1), "SIGABRT");
}

TEST_CASE("forged Catch2, JUnit and report records earn nothing", "[security]") {
	Grade forged = grade("task7_forged_records.cpp", 7);
	require_nothing_earned(forged, "exit status 0");
}

TEST_CASE("including the reference source earns nothing", "[security]") {
	Grade included = grade("task3_include_reference.cpp", 3);
	CHECK_FALSE(included.built);
	require_nothing_earned(included, "reference/task3_bvh.cpp");
}

TEST_CASE("leaving the reference to the linker earns nothing", "[security]") {
	Grade linked = grade("task3_link_reference.cpp", 3);
	CHECK_FALSE(linked.built);
	require_nothing_earned(linked, "undefined"); // "undefined symbol" (lld) or "undefined reference" (ld.bfd)
}

TEST_CASE("rewriting the reference images or test data earns nothing and changes nothing", "[security]") {
	std::vector<std::string> files{GRADED_CHECKSUMS};
	for (const char* suffix : {"_mean.exr", "_var.exr", ".json"}) files.push_back(reference_file("eye_bunny", suffix));
	std::map<std::string, std::string> before;
	for (const std::string& file : files) before[file] = sha256_of_file(file);
	require_nothing_earned(grade("task1_rewrite_references.cpp", 1), "eye_bunny");
	for (const std::string& file : files) {
		INFO(file << " was changed by a submission");
		CHECK(sha256_of_file(file) == before[file]);
	}
}

TEST_CASE("an endless loop earns nothing and is stopped by the time limit", "[security]") {
	require_nothing_earned(grade("task1_endless_loop.cpp", 1, {}, "--time-limit 2"), "time limit");
}

TEST_CASE("unbounded allocation earns nothing and is stopped by the memory limit", "[security]") {
	require_nothing_earned(grade("task1_unbounded_allocation.cpp", 1), "memory limit");
}

TEST_CASE("a forked process earns nothing and outlives nothing", "[security]") {
	require_nothing_earned(grade("task1_fork_survivor.cpp", 1), "generate_ray");
	size_t survivors = 0;
	for (const auto& entry : fs::directory_iterator("/proc")) {
		if (read_file(entry.path() / "comm").rfind("lab-hostile-fork", 0) == 0) survivors++;
	}
	CHECK(survivors == 0);
}

TEST_CASE("reading the judge's data or another submission earns nothing", "[security]") {
	Temp_Dir classmate;
	std::ofstream(classmate.file("task1_camera.cpp")) << "// a classmate's work\n";
	require_nothing_earned(grade("task1_read_judge_data.cpp", 1, {{"@OTHER@", classmate.path().string()}}),
	                       "eye_bunny");
}

TEST_CASE("a network connection earns nothing and reaches nobody", "[security]") {
	int listener = socket(AF_INET, SOCK_STREAM, 0);
	REQUIRE(listener >= 0);
	sockaddr_in address{};
	address.sin_family = AF_INET;
	address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
	socklen_t length = sizeof address;
	REQUIRE(bind(listener, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0);
	REQUIRE(listen(listener, 8) == 0);
	REQUIRE(getsockname(listener, reinterpret_cast<sockaddr*>(&address), &length) == 0);
	std::string port = std::to_string(ntohs(address.sin_port));
	require_nothing_earned(grade("task1_network.cpp", 1, {{"@PORT@", port}}), "generate_ray");
	fcntl(listener, F_SETFL, O_NONBLOCK);
	int connection = accept(listener, nullptr, nullptr);
	INFO("the submission connected to 127.0.0.1:" << port);
	CHECK(connection < 0);
	if (connection >= 0) close(connection);
	close(listener);
}

TEST_CASE("answers special-cased for the public inputs earn nothing under a grading seed", "[security]") {
	// On the public inputs the file looks right: it passes test cases there.
	Grade in_public = grade("task1_public_seed_only.cpp", 1);
	CHECK(in_public.passed > 0);
	require_nothing_earned(grade("task1_public_seed_only.cpp", 1, {}, "--seed 777"), "generate_ray");
}
