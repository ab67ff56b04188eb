// Task 8, handout §8.3: Adaptive_Sampling::sample_pixel, the batch loop, on pixels whose samples
// the grader chooses: constant ones, alternating ones whose stop follows in closed form, and random
// ones, for each of which the grader states where the rule stops.
#include "adaptive_spec.h"
#include "judge.h"

#include "lab_catch2.h"

#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace task8;
using Result = protocol::Sample_Pixels::Result;

namespace {

std::string show_asked(const std::vector<uint32_t>& asked) {
	std::ostringstream out;
	for (size_t i = 0; i < asked.size(); i++) {
		if (i == 12 && asked.size() > 16) {
			out << " ... " << asked.back();
			break;
		}
		out << (i ? ", " : "") << asked[i];
	}
	return out.str();
}

std::string describe(const Adaptive_Sampling& rule, uint32_t max_samples, const std::string& samples) {
	std::ostringstream out;
	out << "sample_pixel(" << max_samples << ", take_sample) with threshold " << rule.threshold << ", min_samples "
	    << rule.min_samples << " and batch " << rule.batch << ", a pixel whose samples are " << samples;
	return out.str();
}

// The pixel took samples 0, 1, ..., expected - 1, each once, and returned `expected`.
void check_took(const Result& got, uint32_t expected, const std::string& what, const std::string& hint) {
	std::vector<uint32_t> in_order(expected);
	for (uint32_t s = 0; s < expected; s++) in_order[s] = s;
	INFO(what << ": expected it to take samples 0 to " << expected - 1 << " and return " << expected
	          << "; it asked for " << got.asked.size() << " (" << show_asked(got.asked) << ") and returned "
	          << got.returned << ". " << hint);
	CHECK(got.asked == in_order);
	CHECK(got.returned == expected);
}

Adaptive_Sampling rule_with(float threshold, uint32_t min_samples = 32, uint32_t batch = 16) {
	Adaptive_Sampling rule;
	rule.threshold = threshold;
	rule.min_samples = min_samples;
	rule.batch = batch;
	return rule;
}

} // namespace

TEST_CASE("sample_pixel: samples 0, 1, 2, ... in order, each once, at most max_samples, and returns the count",
          "[id:t8.sample.order][task8][fn:Adaptive_Sampling::sample_pixel][uses:Adaptive_Sampling::pixel_converged]") {
	const std::string hint = "Call take_sample(s) for s = 0, 1, 2, ... in order, check after every batch, never take "
	                         "more than max_samples, and return the number taken (handout §8.3)";
	Adaptive_Sampling rule = rule_with(0.01f);
	float constant = 0.5f;
	uint32_t most = 256;
	std::vector<uint32_t> maxima{100, 8};
	if (std::optional<RNG> secret = judge::secret_inputs()) { // under a grading seed, others
		rule = rule_with(0.005f + 0.05f * secret->unit(), 8 + secret->integer(41), 3 + secret->integer(18));
		constant = 0.01f + 4.0f * secret->unit();
		most = 200 + secret->integer(300);
		maxima = {33 + secret->integer(200), 1 + secret->integer(rule.min_samples)};
	}
	// Constant samples: the rule allows a stop at the first check from min_samples on.
	std::vector<std::vector<float>> constants{std::vector<float>(most, constant), std::vector<float>(most, 0.0f)};
	uint32_t stop = *expected_stop(rule, most, constants[0]);
	REQUIRE(stop == (rule.min_samples + rule.batch - 1) / rule.batch * rule.batch); // the first check from the minimum
	std::vector<Result> got = student_sample_pixels(rule, most, constants);
	std::ostringstream all;
	all << "all " << constant;
	check_took(got[0], stop, describe(rule, most, all.str()), hint);
	check_took(got[1], stop, describe(rule, most, "all 0 (a black pixel)"), hint);
	// Samples 1, 100, 1, 100, ... never converge at a threshold below 0.055 within 512 samples: every
	// sample, also where max_samples is not a multiple of the batch, or below min_samples.
	for (uint32_t max_samples : maxima) {
		REQUIRE(expected_stop(rule, max_samples, alternating_values(1.0f, 100.0f, max_samples)) == max_samples);
		got = student_sample_pixels(rule, max_samples, {alternating_values(1.0f, 100.0f, max_samples)});
		check_took(got[0], max_samples, describe(rule, max_samples, "1, 100, 1, 100, ..."), hint);
	}
}

TEST_CASE("sample_pixel: checks after every batch, and stops at the first batch the rule allows",
          "[id:t8.sample.batches][task8][fn:Adaptive_Sampling::sample_pixel][uses:Adaptive_Sampling::pixel_converged]") {
	// Samples 3, 7, 3, 7, ... with threshold 0.08 may stop from n = 98 on (test case
	// t8.converged.rule): a check every 16 samples stops at 112, every 10 at 100, every 7 at 98. And
	// constant samples with min_samples 20 and a batch of 7 stop at 21, the first check from 20 on.
	struct Expected {
		Adaptive_Sampling rule;
		std::vector<float> values;
		std::string samples;
		uint32_t stop;
	};
	std::vector<Expected> cases{
		{rule_with(0.08f, 32, 16), alternating_values(3.0f, 7.0f, 256), "3, 7, 3, 7, ...", 112},
		{rule_with(0.08f, 32, 10), alternating_values(3.0f, 7.0f, 256), "3, 7, 3, 7, ...", 100},
		{rule_with(0.08f, 32, 7), alternating_values(3.0f, 7.0f, 256), "3, 7, 3, 7, ...", 98},
		{rule_with(0.01f, 20, 7), std::vector<float>(256, 2.0f), "all 2", 21},
	};
	if (std::optional<RNG> secret = judge::secret_inputs()) {
		// Under a grading seed, other pixels, batches (3 to 20) and minimums (8 to 40): where the rule
		// stops them follows from the closed form of t8.converged.rule, as the grader states it.
		for (Expected& c : cases) {
			float a = 0.05f + 5.0f * secret->unit(), b = a * (1.5f + 3.0f * secret->unit());
			c.rule = rule_with(0.05f + 0.15f * secret->unit(), 8 + secret->integer(33), 3 + secret->integer(18));
			c.values = alternating_values(a, b, 256);
			std::ostringstream words;
			words << a << ", " << b << ", " << a << ", " << b << ", ...";
			c.samples = words.str();
			std::optional<uint32_t> stop = expected_stop(c.rule, 256, c.values);
			c.stop = stop.value_or(0);
		}
	}
	for (const Expected& c : cases) {
		if (c.stop == 0) continue; // a drawn pixel too close to call at a check (task8::CLEAR)
		REQUIRE(expected_stop(c.rule, 256, c.values) == c.stop); // the closed form above, checked
		std::vector<Result> got = student_sample_pixels(c.rule, 256, {c.values});
		check_took(got[0], c.stop, describe(c.rule, 256, c.samples),
		           "Check when the samples taken, s + 1 after sample s, are a multiple of batch, and stop at the "
		           "first check the rule allows (handout §8.3)");
	}
}

TEST_CASE("sample_pixel: pixels of random samples stop where the rule says",
          "[id:t8.sample.random-pixels][task8][fn:Adaptive_Sampling::sample_pixel][uses:Adaptive_Sampling::pixel_converged]") {
	// Pixels like a render's: a light found with probability p (value L, else 0), or a smooth
	// surface (uniform values around a mean). Each pixel's stop follows from its samples by the rule;
	// a pixel where a check on the way is too close to call (task8::CLEAR) is left out.
	const uint32_t MAX = 512;
	RNG rng(judge::secret_seed_or(8));
	std::vector<std::vector<float>> pixels;
	std::vector<std::string> words;
	for (int i = 0; i < 300; i++) {
		std::vector<float> values(MAX);
		std::ostringstream what;
		if (i % 2 == 0) {
			float p = 0.05f + 0.9f * rng.unit(), light = 0.5f + 10.0f * rng.unit();
			for (float& v : values) v = rng.unit() < p ? light : 0.0f;
			what << light << " with probability " << p << ", else 0";
		} else {
			float mean = 0.1f + rng.unit(), spread = mean * rng.unit();
			for (float& v : values) v = mean + spread * (2.0f * rng.unit() - 1.0f);
			what << "uniform in [" << mean - spread << ", " << mean + spread << "]";
		}
		pixels.push_back(values);
		words.push_back(what.str());
	}
	Adaptive_Sampling rule = rule_with(0.1f);
	std::vector<Result> got = student_sample_pixels(rule, MAX, pixels);
	size_t compared = 0, first_wrong = pixels.size();
	std::vector<uint32_t> stops(pixels.size());
	for (size_t i = 0; i < pixels.size(); i++) {
		std::optional<uint32_t> stop = expected_stop(rule, MAX, pixels[i]);
		if (!stop) continue;
		compared++, stops[i] = *stop;
		bool right = got[i].returned == *stop && got[i].asked.size() == *stop;
		if (!right && first_wrong == pixels.size()) first_wrong = i;
	}
	if (first_wrong < pixels.size()) { // one pixel says it
		check_took(got[first_wrong], stops[first_wrong], describe(rule, MAX, "random: " + words[first_wrong]),
		           "The pixel stops at the first check (a whole number of batches, at least min_samples) where "
		           "1.96 s / sqrt(n) <= threshold * m (handout §8.2, §8.3)");
	}
	INFO("pixels compared: " << compared << " of " << pixels.size());
	CHECK(compared >= pixels.size() * 9 / 10);
}
