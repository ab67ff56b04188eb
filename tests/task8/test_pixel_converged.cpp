// Task 8, handout §8.2: Adaptive_Sampling::pixel_converged, on sums whose mean and standard deviation
// are known in closed form. Every query of a test case goes to the subject in one request.
#include "adaptive_spec.h"
#include "judge.h"

#include "lab_catch2.h"

#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace task8;

namespace {

struct Case {
	Adaptive_Sampling rule;
	Luminance_Sums sums;
	std::string samples; // what the samples are, in words
};

std::string describe(const Case& c) {
	double n = c.sums.n, mean = c.sums.sum / n;
	double s = std::sqrt(std::max(0.0, (c.sums.sum_of_squares - c.sums.sum * mean) / (n - 1)));
	std::ostringstream out;
	out << "pixel_converged with threshold " << c.rule.threshold << " and min_samples " << c.rule.min_samples
	    << " for n = " << c.sums.n << " samples " << c.samples << ": mean m = " << mean << ", s = " << s
	    << ", so 1.96 s / sqrt(n) = " << 1.96 * s / std::sqrt(n) << " against threshold * m = "
	    << c.rule.threshold * mean;
	return out.str();
}

// Asks the student about every case at once; checks each against the rule, and says the first
// disagreement and how many there are.
void check_cases(const std::vector<Case>& cases, const std::string& hint) {
	std::vector<std::pair<Adaptive_Sampling, Luminance_Sums>> queries;
	for (const Case& c : cases) queries.emplace_back(c.rule, c.sums);
	std::vector<bool> got = student_converged(queries);
	size_t wrong = 0;
	std::string first;
	for (size_t i = 0; i < cases.size(); i++) {
		const Case& c = cases[i];
		Verdict expected = rule_verdict(c.rule, c.sums.n, c.sums.sum, c.sums.sum_of_squares);
		REQUIRE(expected.clear); // the cases are chosen away from the boundary
		if (got[i] == expected.stops) continue;
		if (wrong++ == 0) {
			first = describe(c) + ": expected " + (expected.stops ? "true" : "false") + ", got " +
			        (got[i] ? "true" : "false");
		}
	}
	INFO(first << (wrong > 1 ? " (and " + std::to_string(wrong - 1) + " more of " + std::to_string(cases.size()) +
	                               " cases wrong)"
	                         : std::string()) << ". " << hint);
	CHECK(wrong == 0);
}

Adaptive_Sampling rule_with(float threshold, uint32_t min_samples = 32) {
	Adaptive_Sampling rule;
	rule.threshold = threshold;
	rule.min_samples = min_samples;
	return rule;
}

} // namespace

TEST_CASE("pixel_converged: a pixel stops once 1.96 s / sqrt(n) <= threshold * mean",
          "[id:t8.converged.rule][task8][fn:Adaptive_Sampling::pixel_converged]") {
	// Samples a, b, a, b, ...: for even n the mean is m = (a + b) / 2 and s^2 = d^2 n / (n - 1) with
	// d = (b - a) / 2, so the half-width is 1.96 d / sqrt(n - 1): the pixel stops from
	// n - 1 >= (1.96 d / (threshold m))^2 on. Each threshold puts that boundary between two even
	// counts, the mean is not 1 and s is not 1, so s^2 for s, an absolute threshold, n for n - 1 and
	// a missing 1.96 each answer some count wrong.
	struct Pair {
		float a, b, threshold;
	};
	std::vector<Pair> pairs{
		{3.0f, 7.0f, 0.08f},     // m 5, d 2: stops from n = 98 on
		{3.0f, 7.0f, 0.0802f},   // the boundary at n - 1 >= 95.5: n = 96 stops only with n for n - 1
		{1.0f, 3.0f, 0.05f},     // m 2, d 1: from n = 386 on
		{0.5f, 0.7f, 0.02f},     // m 0.6, d 0.1: from n = 268 on
		{2.0f, 10.0f, 0.2f},     // m 6, d 4: from n = 44 on
		{0.02f, 0.06f, 0.07f},   // a dark pixel, m 0.04, d 0.02: from n = 198 on
	};
	if (std::optional<RNG> secret = judge::secret_inputs()) {
		// Under a grading seed, other pixels: a in [0.01, 5], b = a (1.2 ... 4), and the boundary
		// n - 1 >= X at X = 2k + 1.5 for an even count 2k from 40 to 380, where n for n - 1 answers the
		// count 2k + 2 wrong.
		pairs.clear();
		for (int i = 0; i < 6; i++) {
			float a = 0.01f + 5.0f * secret->unit(), b = a * (1.2f + 2.8f * secret->unit());
			double m = (double(a) + b) / 2.0, d = (double(b) - a) / 2.0, x = 2.0 * (20 + secret->integer(171)) + 1.5;
			pairs.push_back({a, b, float(1.96 * d / (m * std::sqrt(x)))});
		}
	}
	std::vector<Case> cases;
	for (const Pair& p : pairs) {
		Adaptive_Sampling rule = rule_with(p.threshold);
		for (uint32_t n = rule.min_samples; n <= 400; n += 2) {
			Luminance_Sums sums = alternating(p.a, p.b, n);
			if (!rule_verdict(rule, sums.n, sums.sum, sums.sum_of_squares).clear) continue;
			std::ostringstream words;
			words << "alternating " << p.a << ", " << p.b;
			cases.push_back({rule, sums, words.str()});
		}
	}
	check_cases(cases, "m = sum / n, s^2 = (sum_of_squares - n m^2) / (n - 1) (divide by n - 1), and the pixel "
	                   "stops once 1.96 s / sqrt(n) <= threshold * m: relative to the mean (handout §8.2)");
}

TEST_CASE("pixel_converged: never before min_samples; constant pixels, black ones too, stop at it",
          "[id:t8.converged.minimum][task8][fn:Adaptive_Sampling::pixel_converged]") {
	std::vector<uint32_t> minimums{32, 64};
	std::vector<float> values{0.0f, 0.25f, 7.0f};
	if (std::optional<RNG> secret = judge::secret_inputs()) { // under a grading seed, others
		minimums = {8 + 2 * secret->integer(13), 40 + 2 * secret->integer(21)};
		values = {0.0f, 0.01f + secret->unit(), 1.0f + 9.0f * secret->unit()};
	}
	std::vector<Case> cases;
	for (uint32_t min_samples : minimums) {
		// Alternating 1, 3 with threshold 0.5 would stop from n = 5 on: min_samples holds it back.
		Adaptive_Sampling rule = rule_with(0.5f, min_samples);
		for (uint32_t n : {2u, 4u, min_samples / 2, min_samples - 2, min_samples, min_samples + 16}) {
			cases.push_back({rule, alternating(1.0f, 3.0f, n), "alternating 1, 3"});
		}
		// Constant samples: s = 0, so the pixel stops at min_samples and not before, black ones too
		// (0 <= threshold * 0).
		rule.threshold = 0.01f;
		for (float value : values) {
			for (uint32_t n : {min_samples - 1, min_samples, 2 * min_samples}) {
				std::ostringstream words;
				words << "all " << value;
				cases.push_back({rule, alternating(value, value, n), words.str()});
			}
		}
	}
	check_cases(cases, "A pixel never stops before min_samples (sums.n counts its samples), and a pixel whose "
	                   "samples are all equal stops there, a black one too: 0 <= threshold * 0 (handout §8.2)");
}
