// The judge's program: Catch2's runner with the judge's options, and the per-test-case subject.
//
//   judge_taskN --subject PROGRAM [--seed S | --seed @FILE] [--sandbox auto|bubblewrap|process-limits|none]
//               [--time-limit SECONDS] [--cpu-limit SECONDS] [--save-requests DIR] [Catch2 options]
#include "catch2_session.h" // first: with Catch2 2, its runner is compiled here

#include "judge.h"
#include "lab_reporter.h"
#include "significance.h"
#include "verdict_summary.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include <sys/prctl.h>
#include <sys/resource.h>
#include <unistd.h>

namespace {

// The judge's address space: its own work (a reference render, the largest test scene's BVH) takes
// a few hundred MiB, its threads' stacks and allocator arenas a few hundred more.
constexpr rlim_t JUDGE_MEMORY_BYTES = rlim_t(4) << 30;

struct Judge_State {
	std::string program;   // the subject program
	std::optional<Sandbox> sandbox;
	std::optional<uint64_t> secret_seed;
	std::string save_dir;  // where test cases' requests are saved, or empty
	// The running test case.
	std::string test_case;
	std::string test_case_id;
	size_t test_case_number = 0;
	size_t secret_draws = 0; // generators secret_inputs() gave it
	// Statistical checks: the grader's budget (every test case's [statistical:N]), the running test
	// case's N and the checks it made, and the test cases whose count differed (grader mistakes).
	size_t budget = 0, declared_checks = 0, made_checks = 0;
	std::vector<std::string> miscounted;
	Subject::Clock::time_point deadline;
	std::unique_ptr<Subject> subject;
	// The next test case's subject, started when this one's was taken: a process as fresh as any,
	// which has booted by the time it is asked (a sandbox takes milliseconds to start, mostly
	// waiting for the kernel to make its namespaces).
	std::unique_ptr<Subject> next_subject;
	Hang_Record hangs; // over the whole run
};

Judge_State& state() {
	static Judge_State s;
	return s;
}

std::string requests_file() {
	Judge_State& s = state();
	if (s.save_dir.empty()) return "";
	std::string slug;
	for (char c : s.test_case) slug += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
	return s.save_dir + "/" + std::to_string(s.test_case_number) + "_" + slug.substr(0, 60) + ".requests";
}

// The N of a test case's [statistical:N], 0 if it has none.
size_t declared_checks(const catch2_seam::Test_Case& test_case) {
	size_t checks = 0;
	for (const std::string& count : test_case.tagged("statistical:")) {
		size_t used = 0;
		try {
			checks += std::stoul(count, &used);
		} catch (const std::exception&) {
		}
		if (used == 0 || used != count.size()) {
			throw std::invalid_argument(test_case.file + ":" + std::to_string(test_case.line) + ": [statistical:" + count +
			                            "] takes the number of the test case's statistical checks");
		}
	}
	return checks;
}

// Starts each test case with no subject and its own time limit, and ends its subject with it;
// keeps the count of its secret draws and statistical checks.
class Subject_Lifecycle : public catch2_seam::Events {
public:
	void run_starting(const std::string&, const std::vector<catch2_seam::Test_Case>& all_test_cases) override {
		Judge_State& s = state();
		s.budget = 0;
		for (const catch2_seam::Test_Case& test_case : all_test_cases) s.budget += declared_checks(test_case);
	}

	void test_case_starting(const catch2_seam::Test_Case& test_case) override {
		Judge_State& s = state();
		s.subject.reset();
		s.test_case = test_case.name;
		std::vector<std::string> ids = test_case.tagged("id:");
		s.test_case_id = ids.empty() ? "" : ids.front();
		s.secret_draws = 0;
		s.declared_checks = declared_checks(test_case);
		s.made_checks = 0;
		s.test_case_number++;
		s.deadline = Subject::Clock::now() + std::chrono::duration_cast<Subject::Clock::duration>(
		                                        std::chrono::duration<double>(s.sandbox->limits().test_case_seconds));
		if (!s.save_dir.empty()) std::filesystem::remove(requests_file());
	}

	void test_case_ended(const catch2_seam::Test_Case& test_case, catch2_seam::Counts checks) override {
		Judge_State& s = state();
		s.subject.reset();
		if (checks.failed == 0 && s.made_checks != s.declared_checks) {
			s.miscounted.push_back(test_case.file + ":" + std::to_string(test_case.line) + ": '" + test_case.name +
			                       "' declares [statistical:" + std::to_string(s.declared_checks) + "] but made " +
			                       std::to_string(s.made_checks) + " statistical checks (significance() and "
			                       "z_critical() count one, significance(k) and z_critical(k) k)");
		}
		if (!s.save_dir.empty() && checks.failed == 0) std::filesystem::remove(requests_file());
	}
};

std::optional<uint64_t> parse_seed(const std::string& text) {
	if (text.empty()) return std::nullopt;
	std::string digits = text;
	if (text[0] == '@') {
		std::ifstream in(text.substr(1));
		if (!(in >> digits)) throw std::invalid_argument("cannot read a seed from " + text.substr(1));
	}
	size_t used = 0;
	uint64_t seed = std::stoull(digits, &used, 0);
	if (used != digits.size()) throw std::invalid_argument("--seed takes a number, not '" + digits + "'");
	return seed;
}

} // namespace

LAB_CATCH2_LISTENER(Subject_Lifecycle)

namespace judge {

Subject& subject() {
	Judge_State& s = state();
	if (!s.subject) {
		auto start = [&] { return std::make_unique<Subject>(s.program, *s.sandbox, s.hangs); };
		s.subject = s.next_subject ? std::move(s.next_subject) : start();
		s.subject->begin(s.deadline, requests_file());
		s.next_subject = start();
	}
	return *s.subject;
}

namespace {
// FNV-1a of `what`: a stream per draw.
uint64_t stream_of(const std::string& what) {
	uint64_t h = 1469598103934665603ull;
	for (unsigned char c : what) h = (h ^ c) * 1099511628211ull;
	return h;
}
} // namespace

std::optional<RNG> secret_inputs(Secret what) {
	Judge_State& s = state();
	if (!s.secret_seed) return std::nullopt;
	if (s.test_case_id.empty()) {
		throw std::logic_error("secret_inputs() in the test case '" + s.test_case + "', which has no [id:...] tag");
	}
	uint64_t seed = *s.secret_seed;
	const char* variations = std::getenv("LAB_SCENE_VARIATIONS");
	uint64_t n = variations ? std::strtoull(variations, nullptr, 10) : 0;
	if (what == Secret::graded_scene && n != 0) seed %= n;
	return RNG(seed, stream_of(s.test_case_id + "#" + std::to_string(s.secret_draws++)));
}

bool inputs_are_secret() {
	return state().secret_seed.has_value();
}

uint64_t seed_or_public(std::optional<RNG>& secret, uint64_t public_seed) {
	return secret ? uint64_t(secret->integer()) << 32 | secret->integer() : public_seed;
}

uint64_t secret_seed_or(uint64_t public_seed) {
	std::optional<RNG> secret = secret_inputs();
	return seed_or_public(secret, public_seed);
}

namespace {
// One check's share of the grader's budget (Šidák), counting `checks` checks made.
double one_check_level(size_t checks) {
	Judge_State& s = state();
	s.made_checks += checks;
	return stats::sidak(GRADER_ALPHA, std::max<size_t>(s.budget, 1));
}
} // namespace

double significance(size_t checks) {
	double one = one_check_level(checks);
	return checks == 1 ? one : -std::expm1(double(checks) * std::log1p(-one));
}

double z_critical(size_t checks) {
	return stats::two_sided_z(one_check_level(checks));
}

const Sandbox& sandbox() {
	return *state().sandbox;
}

} // namespace judge

int main(int argc, char** argv) {
	// Not dumpable: a subject running as the same user (process limits, no Landlock) can neither
	// trace the judge nor read or write its memory through /proc.
	prctl(PR_SET_DUMPABLE, 0, 0, 0, 0);
	// The judge's own memory is bounded: what a subject sends can cost it no more than this
	// (Subject::answer_limit, and wire.h's decoding in proportion to the bytes received).
	// (The hard limit stays, so that a debug subject, which needs the address space of its
	// sanitizers, can lift the soft one: subject.cpp.)
	const rlimit memory{JUDGE_MEMORY_BYTES, RLIM_INFINITY};
	setrlimit(RLIMIT_AS, &memory);
	wire::keep_large_buffers();
	Catch::Session session;
	Judge_State& s = state();
	std::string sandbox_mode = "auto", seed_text, check_sandbox;
	double time_limit = 0.0, cpu_limit = 0.0;
	using catch2_seam::cli::Opt;
	session.cli(session.cli() |
	            Opt(s.program, "program")["--subject"]("the subject program that runs the code under test") |
	            Opt(seed_text, "seed|@file")["--seed"]("an instructor's secret grading seed, or a file holding it") |
	            Opt(sandbox_mode, "auto|bubblewrap|process-limits|none")["--sandbox"]("how the subject runs (default auto)") |
	            Opt(time_limit, "seconds")["--time-limit"]("wall time per request (default 30; 3 times that per test case)") |
	            Opt(cpu_limit, "seconds")["--cpu-limit"]("CPU time of one test case's subject (default 90)") |
	            Opt(s.save_dir, "folder")["--save-requests"]("save failed test cases' requests for --replay") |
	            Opt(check_sandbox, "mode")["--check-sandbox"]("say how subjects would run in that mode, and exit"));
	if (int status = catch2_seam::apply_command_line(session, argc, argv, LAB_REPORTER)) return status;
	if (!check_sandbox.empty()) {
		try {
			std::cout << Sandbox::choose(check_sandbox).notice() << "\n";
			return 0;
		} catch (const std::exception& problem) {
			std::cerr << "judge: " << problem.what() << "\n";
			return 3;
		}
	}
	if (catch2_seam::lists_only(session)) {
		s.sandbox = Sandbox::choose("none");
		return session.run();
	}
	try {
		if (s.program.empty() || access(s.program.c_str(), X_OK) != 0) {
			throw std::invalid_argument("--subject must name the subject program (got '" + s.program + "')");
		}
		s.program = std::filesystem::absolute(s.program).string();
		s.secret_seed = parse_seed(seed_text);
		s.sandbox = Sandbox::choose(sandbox_mode);
		if (time_limit < 0.0) throw std::invalid_argument("--time-limit must be positive");
		if (time_limit > 0.0) {
			s.sandbox->limits().request_seconds = time_limit;
			s.sandbox->limits().test_case_seconds = 3.0 * time_limit;
		}
		if (cpu_limit < 0.0) throw std::invalid_argument("--cpu-limit must be positive");
		if (cpu_limit > 0.0) s.sandbox->limits().cpu_seconds = uint64_t(std::ceil(cpu_limit));
		if (!s.save_dir.empty()) std::filesystem::create_directories(s.save_dir);
	} catch (const std::exception& problem) {
		std::cerr << "judge: " << problem.what() << "\n";
		return 2;
	}
	int status = session.run();
	print_verdict_summary(std::cout);
	// How the code ran, after what it did: a student's first lines are the first failure's message.
	std::cout << s.sandbox->notice() << "\n"
	          << (s.secret_seed ? "inputs: drawn from the grading seed" : "inputs: the public test cases") << "\n";
	if (!s.miscounted.empty()) {
		for (const std::string& miscount : s.miscounted) std::cerr << "judge: the grader miscounts: " << miscount << "\n";
		return 4;
	}
	return status;
}
