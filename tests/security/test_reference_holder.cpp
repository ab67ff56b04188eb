// The security suite's test cases of what a student who holds the student release can hand in
// (issue 35; DESIGN.md, decided points 6 to 8): the compiled reference of every task, the
// reference images of the graded scenes and the framework's headers. Each hostile file must earn
// nothing beyond its honest part in every sandbox mode (the ctest tests security*, by LAB_SANDBOX).
// Tagged [whole]: each submission is graded as Gradescope grades one, all eight tasks in order into
// one output folder, the tasks without a hostile file being the shipped stubs (./lab acceptance, in
// every mode: the ctest tests security_whole, security_process_limits, security_ordinary_user).
#include "image_io.h"
#include "security_grading.h"

#include "lab_catch2.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

namespace fs = std::filesystem;

namespace {

// Grades a submission of `files` (see above), all eight tasks; `options` go to grade-submission.
// Every task graded was, and where it had no hostile file (the shipped stubs) it earned no points
// (the stubs pass a few test cases, which the rubric weighs 0).
std::map<int, Grade> grade_submission(const Temp_Dir& dir, const std::map<int, std::string>& files,
                                      const std::string& options = "") {
	std::map<int, Grade> grades = grade_files(dir, files, options);
	REQUIRE(grades.size() == TASK_FILES.size());
	for (const auto& [task, graded] : grades) {
		if (files.count(task)) continue;
		INFO("task " << task << " (the shipped stub)");
		CHECK(graded.built);
		CHECK(graded.points == 0.0);
	}
	return grades;
}

// reference/<task N's file> as the compiler translates it (assembly, the grading kit's compiler and
// flags), handed in as task N's file: one top-level asm statement, spelled by a macro that pastes
// its name together, so that only the preprocessed text shows it.
std::string reference_as_assembly(int task, const Temp_Dir& dir) {
	std::string assembly = dir.file("reference.s");
	std::string command = kit_value("LAB_CXX") + " " + kit_value("LAB_CXXFLAGS") + " -S -o '" + assembly +
	                      "' reference/" + TASK_FILES.at(task);
	REQUIRE(std::system(command.c_str()) == 0);
	return "#define PASTE(a, b) a##b\n#define EMIT PASTE(__as, m__)\nEMIT(R\"lab(\n" + read_file(assembly) +
	       "\n)lab\");\n";
}

// The shipped reference image's means as a C++ initializer: {r, g, b, r, g, b, ...}.
std::string image_initializer(const std::string& exr) {
	HDR_Image image = read_image(exr);
	std::ostringstream text;
	text.precision(9);
	text << "{";
	for (const Spectrum& pixel : image.pixels) text << pixel.r << ", " << pixel.g << ", " << pixel.b << ", ";
	text << "}";
	return text.str();
}

} // namespace

TEST_CASE("machine code, data run as code and framework functions of its own earn nothing",
          "[security][whole]") {
	Temp_Dir dir;
	fs::path out = dir.path() / "out";
	std::map<int, std::string> files{
		{1, hostile_source("task1_if_data_executes.cpp", out)},
		{3, reference_as_assembly(3, dir)},
		{7, hostile_source("task7_defines_framework.cpp", out, {{"@STUB_TASK7@", read_file("student/task7_env_light.cpp")}})},
		{8, reference_as_assembly(8, dir)},
	};
	std::map<int, Grade> grades = grade_submission(dir, files);
	// The page it would write and run as code is refused: it answers as the stub does.
	require_nothing_earned(grades[1], "generate_ray");
	// The compiled reference, handed in as assembly, is refused before it is linked (task 8's too).
	for (int task : {3, 8}) {
		CHECK_FALSE(grades[task].built);
		require_nothing_earned(grades[task], "assembly");
	}
	// Its own render(), RNG::unit() and Film::non_finite() are refused by name.
	CHECK_FALSE(grades[7].built);
	for (const char* name : {"render(Pathtracer const&, Render_Options const&)", "RNG::unit()", "Film::non_finite() const",
	                         "film_non_finite_count_is_mine"}) {
		CHECK_THAT(grades[7].messages, contains_text(name));
	}
	require_nothing_earned(grades[7], "defines global names that are not task 7");
}

TEST_CASE("an integrator named as the framework's own, to render instead of it, earns nothing", "[security][whole]") {
	Temp_Dir dir;
	std::string hostile = hostile_source("task6_integrator_named_as_framework.cpp", dir.path() / "out",
	                                     {{"@STUB_TASK6@", read_file("student/task6_direct_lighting.cpp")}});
	std::map<int, Grade> grades = grade_submission(dir, {{6, hostile}});
	CHECK(grades[6].built);
	CHECK(grades[6].points == 0.0);
	require_nothing_earned(grades[6], "SIGABRT");
}

TEST_CASE("becoming another program, or seeing what the grading built for an earlier task, earns nothing",
          "[security][whole]") {
	Temp_Dir dir;
	fs::path out = dir.path() / "out";
	std::map<int, std::string> files{
		{1, hostile_source("task1_if_exec_works.cpp", out)},
		{7, hostile_source("task7_if_earlier_builds_visible.cpp", out,
		                   {{"@REFERENCE_TASK7@", read_file("reference/task7_env_light.cpp")},
		                    {"@STUB_TASK7@", read_file("student/task7_env_light.cpp")}})},
	};
	std::map<int, Grade> grades = grade_submission(dir, files);
	require_nothing_earned(grades[1], "generate_ray");
	// The stub's text compiles where the earlier task's folder is out of sight (bubblewrap); where
	// Landlock forbids it instead, the compiler stops at it.
	INFO("task 7: " << grades[7].messages.substr(0, 2000));
	CHECK((grades[7].built || grades[7].messages.find("Permission denied") != std::string::npos));
	CHECK(grades[7].points == 0.0);
}

TEST_CASE("its own copy of an inline framework function is never the one the subject runs",
          "[security][whole]") {
	Temp_Dir dir;
	std::map<int, Grade> grades = grade_submission(dir, {{1, hostile_source("task1_if_inline_replaced.cpp", dir.path() / "out")}});
	require_nothing_earned(grades[1], "generate_ray");
}

TEST_CASE("task 4's answers replayed from the shipped reference image or read off the request earn nothing beyond "
          "its honest part under a grading seed",
          "[security][whole]") {
	Temp_Dir hostile_dir, honest_dir, public_dir;
	std::string hostile = hostile_source("task4_derived_answers.cpp", hostile_dir.path() / "out",
	                                     {{"@CORNELL_DIFFUSE_MEAN@",
	                                       image_initializer("scenes/graded/references/cornell_diffuse_mean.exr")}});
	// Its honest part: the same Lambertian BSDF, and a shade() that finds no light (which the test of
	// a scene without light passes, as the derived answers do).
	size_t shade = hostile.find("Spectrum Pathtracer::shade(");
	REQUIRE(shade != std::string::npos);
	std::string honest = hostile.substr(0, shade) +
	                     "Spectrum Pathtracer::shade(RNG& rng, const Ray& ray, const Trace& hit) const {\n"
	                     "\treturn Spectrum{0.0f};\n}\n";
	// In public the replayed image is right: the shipped reference is the reference of the scene
	// graded (and the attack works).
	Grade in_public = grade_submission(public_dir, {{4, hostile}})[4];
	INFO("in public: " << in_public.messages.substr(0, 2000));
	CHECK(in_public.built);
	const std::string image_test = "the graded scene cornell_diffuse renders like its reference image";
	CHECK(std::find(in_public.passed_names.begin(), in_public.passed_names.end(), image_test) != in_public.passed_names.end());
	// Under a grading seed, nothing beyond what the honest part earns.
	std::map<int, Grade> graded = grade_submission(hostile_dir, {{4, hostile}}, "--seed 4242");
	std::map<int, Grade> honest_graded = grade_submission(honest_dir, {{4, honest}}, "--seed 4242");
	INFO("the hostile file's messages:\n" << graded[4].messages.substr(0, 1500));
	std::string honest_failed;
	for (const std::string& name : honest_graded[4].failed) honest_failed += "\n  " + name;
	INFO("its honest part failed:" << honest_failed);
	CHECK(honest_graded[4].built);
	CHECK(honest_graded[4].points > 0.0);
	CHECK(graded[4].points <= honest_graded[4].points);
	for (const std::string& name : graded[4].passed_names) {
		INFO("passed with derived answers: " << name);
		CHECK(std::find(honest_graded[4].passed_names.begin(), honest_graded[4].passed_names.end(), name) !=
		      honest_graded[4].passed_names.end());
	}
}

TEST_CASE("task 8's answers special-cased for the public cases pass none of its closed-form test cases under a "
          "grading seed",
          "[security][whole]") {
	// Task 8's closed forms (the rule, the minimum, the loop's order and its batches) draw their
	// thresholds, minimums, batches and sample counts from the seed; the file answers right only for
	// the public ones. Its honest part is the rule for the render's and the random pixels' settings.
	Grade in_public = grade("task8_public_cases_only.cpp", 8);
	INFO("in public: " << in_public.messages.substr(0, 1500));
	CHECK(in_public.passed == in_public.test_cases);
	Temp_Dir dir;
	std::string hostile = hostile_source("task8_public_cases_only.cpp", dir.path() / "out");
	Grade seeded = grade_submission(dir, {{8, hostile}}, "--seed 777")[8];
	INFO("under a grading seed: " << seeded.messages.substr(0, 1500));
	CHECK(seeded.built);
	for (const char* closed_form : {"pixel_converged: a pixel stops once", "pixel_converged: never before min_samples",
	                                "sample_pixel: samples 0, 1, 2", "sample_pixel: checks after every batch"}) {
		CAPTURE(closed_form);
		CHECK(std::none_of(seeded.passed_names.begin(), seeded.passed_names.end(),
		                   [&](const std::string& name) { return name.rfind(closed_form, 0) == 0; }));
	}
}

TEST_CASE("an answer claiming more results than its bytes hold costs the judge no more than its bytes, and one larger "
          "than any answer is refused unread",
          "[security][whole]") {
	// 60 MiB of zeros saying 60 million rays follow: decoded as rays for the bytes there are (about
	// 36 a ray), never allocated for the count.
	Temp_Dir amplified_dir, huge_dir;
	std::map<int, Grade> amplified = grade_submission(
		amplified_dir, {{1, hostile_source("task1_amplified_answer.cpp", amplified_dir.path() / "out", {{"@LENGTH@", "uint64_t(60) << 20"}})}},
		"--time-limit 10");
	require_nothing_earned(amplified[1], "generate_ray");
	INFO("the largest process of the grading held " << amplified[1].largest_process_kib << " KiB");
	CHECK(amplified[1].largest_process_kib < 512 * 1024);
	// 200 MiB: more than 64 MiB + 16 times any task-1 request, refused before it is read.
	std::map<int, Grade> huge = grade_submission(
		huge_dir, {{1, hostile_source("task1_amplified_answer.cpp", huge_dir.path() / "out", {{"@LENGTH@", "uint64_t(200) << 20"}})}},
		"--time-limit 10");
	require_nothing_earned(huge[1], "answer is too large");
	CHECK(huge[1].largest_process_kib < 512 * 1024);
}

