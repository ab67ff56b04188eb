// The security suite (label security): one hostile student file per threat (tests/security/hostile/),
// each graded through the normal path (grading/bin/grade-submission: sandboxed compile, subject in
// bubblewrap, verdicts by the judge) and required to earn nothing for its task, with the reason in
// the grade report. Where a threat has a side effect outside the grade (a file rewritten, a process
// left behind, a connection made), that it did not happen is checked too.
//
// Run from the repository root with LAB_KIT naming the grading kit (build/grading/kit.env).
#include "graded_images.h"
#include "security_grading.h"
#include "sha256.h"

#include "lab_catch2.h"
#include <nlohmann/json.hpp>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <sstream>
#include <vector>

namespace fs = std::filesystem;

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

TEST_CASE("a traversal that tests objects where the count cannot see earns nothing for its traversal", "[security]") {
	// The judge counts the objects BVH::hit tests by answering each itself (grading/judge/protocol.h,
	// BVH_Instances): the subject holds their boxes alone. The hostile file is the reference but for
	// its BVH<Instance>::hit, whose objects are correct where they are real (the graded image).
	std::string reference = read_file("reference/task3_bvh.cpp");
	size_t instantiations = reference.find("template class BVH<Triangle>;");
	REQUIRE(instantiations != std::string::npos);
	Grade uncounted = grade("task3_uncounted_traversal.cpp", 3, {{"@REFERENCE_BVH@", reference.substr(0, instantiations)}});
	INFO("the judge's messages:\n" << uncounted.messages.substr(0, 3000));
	CHECK(uncounted.built);
	CHECK(uncounted.failed ==
	      std::vector<std::string>{"BVH::hit: objects tested per ray within 1.5x of an ideal front-to-back traversal"});
	CHECK_THAT(uncounted.messages, contains_text("missed the closest hit"));
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

TEST_CASE("a task file that names a library for the linker (.deplibs) earns nothing", "[security]") {
	// It names the grading kit's own compiled reference of task 3, which lld would link in.
	std::string reference = kit_value("LAB_REFERENCE_OBJECTS_3");
	REQUIRE(fs::exists(reference));
	// GCC writes .deplibs only from assembly, which the compile refuses first (compile-student,
	// which would also refuse the section).
	Grade named = grade("task3_dependent_library.cpp", 3, {{"@REFERENCE_TASK3@", reference}});
	CHECK_FALSE(named.built);
	require_nothing_earned(named, "assembly");
}

TEST_CASE("a task file that has the assembler read the reference (.incbin) earns nothing", "[security]") {
	// Refused as assembly; nor could the compile see reference/ (grading/bin/compile-student).
	Grade included = grade("task3_incbin_reference.cpp", 3);
	CHECK_FALSE(included.built);
	require_nothing_earned(included, "assembly");
}

TEST_CASE("assembly behind line directives that call it a system header's earns nothing", "[security]") {
	Grade hidden = grade("task3_line_directive.cpp", 3);
	CHECK_FALSE(hidden.built);
	require_nothing_earned(hidden, "line directive");
}

// The task1_if_* files are task 1 done right when their attack works (correct_task1_if.inc).
TEST_CASE("a task1_if_* file whose attack works earns full marks", "[security]") {
	// The control: without it, "earns nothing" below would prove nothing about the attacks.
	Temp_Dir dir;
	std::string always = "static bool attack_worked() { return true; }\n" +
	                     read_file("tests/security/hostile/correct_task1_if.inc");
	Grade graded = grade_files(dir, {{1, always}}, "--tasks 1")[1];
	CHECK(graded.built);
	CHECK(graded.test_cases > 0);
	CHECK(graded.passed == graded.test_cases);
}

TEST_CASE("writing the judge's memory through /proc earns nothing", "[security]") {
	require_nothing_earned(grade("task1_if_judge_memory_writable.cpp", 1), "generate_ray");
}

TEST_CASE("writing into the grader's records earns nothing", "[security]") {
	require_nothing_earned(grade("task1_if_records_writable.cpp", 1), "generate_ray");
}

TEST_CASE("opening a judge that later submissions use for writing earns nothing", "[security]") {
	std::string judge = kit_value("LAB_JUDGE_2");
	std::string before = sha256_of_file(judge);
	require_nothing_earned(grade("task1_if_judges_writable.cpp", 1, {{"@JUDGE2@", judge}}), "generate_ray");
	CHECK(sha256_of_file(judge) == before);
}

TEST_CASE("reading the grading seed's file earns nothing", "[security]") {
	Temp_Dir dir;
	std::string seed = dir.file("seed");
	std::ofstream(seed) << "777\n";
	fs::permissions(seed, fs::perms::owner_read | fs::perms::owner_write); // as ./lab autograder writes it
	require_nothing_earned(grade("task1_if_seed_readable.cpp", 1, {{"@SEED_FILE@", seed}}, "--seed @" + seed),
	                       "generate_ray");
}

TEST_CASE("the grader's environment tells student code nothing", "[security]") {
	require_nothing_earned(grade("task1_if_environment.cpp", 1), "generate_ray");
}

TEST_CASE("memory outside the memory limit (memfd, /dev/shm) earns nothing", "[security]") {
	require_nothing_earned(grade("task1_if_memory_outside_limits.cpp", 1), "generate_ray");
}

TEST_CASE("burning CPU earns nothing and is stopped by the CPU limit, which the report names", "[security]") {
	require_nothing_earned(grade("task1_cpu_hog.cpp", 1, {}, "--time-limit 20 --cpu-limit 1"), "CPU time limit");
}

TEST_CASE("an answer that declares a huge payload and sends nothing costs the judge no memory", "[security]") {
	// Refused unread: more than any answer to its request can be (grading/judge/subject.h).
	Grade declared = grade("task1_declared_huge_answer.cpp", 1, {}, "--time-limit 2");
	require_nothing_earned(declared, "answer is too large");
	INFO("the largest process of the grading held " << declared.largest_process_kib << " KiB");
	CHECK(declared.largest_process_kib < 512 * 1024); // far below the 1 GiB declared
}

TEST_CASE("a file whose preprocessing never ends is stopped, and says so", "[security]") {
	Grade bomb = grade("task1_macro_bomb.cpp", 1);
	CHECK_FALSE(bomb.built);
	CHECK_THAT(bomb.messages, contains_text("memory") || contains_text("did not finish"));
}

namespace {
// The shipped stub of task n with an endless loop at the start of every function it defines.
std::string hanging_stub(int n) {
	std::istringstream stub(read_file("student/" + TASK_FILES.at(n)));
	std::string hanging = "namespace { volatile bool lab_forever = true; }\n";
	const std::regex definition(R"(^[A-Za-z].*\)( const)? \{$)");
	size_t loops = 0;
	for (std::string line; std::getline(stub, line);) {
		hanging += line;
		if (std::regex_match(line, definition)) hanging += " while (lab_forever) {}", loops++;
		hanging += "\n";
	}
	REQUIRE(loops >= 2);
	return hanging;
}
} // namespace

TEST_CASE("a submission whose every function hangs gets 0 on every task, at most two hangs a task later",
          "[security]") {
	Temp_Dir dir;
	std::map<int, std::string> files;
	for (const auto& [n, file] : TASK_FILES) files[n] = hanging_stub(n);
	// Seconds per request: 1 in ./lab test; ./lab acceptance runs this with the default, 30
	// (LAB_HANG_LIMIT, test security_hangs_default_limit).
	const char* chosen = std::getenv("LAB_HANG_LIMIT");
	const double limit = chosen ? std::stod(chosen) : 1.0;
	std::map<int, Grade> grades = grade_files(dir, files, "--time-limit " + std::to_string(limit));
	REQUIRE(grades.size() == TASK_FILES.size());
	for (const auto& [task, graded] : grades) {
		INFO("task " << task << ": " << graded.messages.substr(0, 2000));
		CHECK(graded.built);
		CHECK(graded.test_cases > 0);
		CHECK(graded.passed == 0);
		CHECK_THAT(graded.messages, contains_text("first: it did not finish") ||
		                                contains_text("first: your code did not finish"));
	}
	// A task waits for at most two hung requests (grading/judge/subject.h, Hang_Record); compiling,
	// starting subjects and the judge's own work take the rest, a few seconds a task. With the
	// default limit that is 8 x (60 + 8) s: within Gradescope's 10 minutes.
	double seconds = grades[1].seconds;
	INFO("graded in " << seconds << " s");
	CHECK(seconds <= TASK_FILES.size() * (2 * limit + 8));
	CHECK(seconds <= 600);
}

TEST_CASE("a file that keeps the compiler busy is stopped by the time limit, and says so", "[security]") {
	setenv("LAB_STEP_SECONDS", "2", 1); // grading/bin/sandboxed's limit on a compile (default 60 s)
	Grade busy = grade("task1_endless_constexpr.cpp", 1);
	unsetenv("LAB_STEP_SECONDS");
	CHECK_FALSE(busy.built);
	CHECK_THAT(busy.messages, contains_text("did not finish in 2 s"));
}

TEST_CASE("a task-4 file whose shade() is the framework's NEE integrator earns nothing for shade()", "[security]") {
	// The integrator is not linked where task 4 is graded (tests/security/test_subject_symbols.sh).
	// What the file's honest Lambertian BSDF earns, with the stub's shade(), is the most it may earn.
	Temp_Dir dir;
	std::string source = hostile_source("task4_shade_by_nee_integrator.cpp", dir.path() / "out");
	std::string by_nee = "return integrator_row(\"--integrator\", \"nee\").integrator.radiance(*this, rng, camera_ray);";
	size_t at = source.find(by_nee);
	REQUIRE(at != std::string::npos);
	std::string honest = source;
	honest.replace(at, by_nee.size(), "return eye_light(ray, hit);");
	Grade bsdf_only = grade_files(dir, {{4, honest}}, "--tasks 4")[4];
	Grade hostile = grade("task4_shade_by_nee_integrator.cpp", 4);
	INFO("the judge's messages:\n" << hostile.messages.substr(0, 3000));
	CHECK(hostile.built);
	CHECK(bsdf_only.passed > 0);
	CHECK(hostile.passed <= bsdf_only.passed);
	CHECK_THAT(hostile.messages, contains_text("--integrator: expected mixture, got 'nee'"));
}
