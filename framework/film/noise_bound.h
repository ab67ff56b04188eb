#pragma once
// A one-sided bound on a submission's noise: its per-sample variance may not exceed the reference's
// by more than sampling explains. Without it, noise and fireflies would only make the mean tests
// fail now and then, by chance; with it they fail every time, with a message that says "noise".
//
// A group of G independent estimates (the pixels of an image, or one closed-form estimate), each
// the mean of n samples, has unbiased per-sample variances s²_g. If the submission samples as the
// reference does, their sum S = Σ s²_g has mean E = Σ σ²_g and variance
//
//     V_n = Σ Var(s²_g),   Var(s²) = (μ4 - (n - 3) / (n - 1) σ⁴) / n
//
// (exact for independent samples of any law with a fourth moment; Cramér 1946, Mathematical
// Methods of Statistics, eq. 27.4.2). σ² and μ4 are the reference's, themselves estimated from
// N samples: Ê is off by the same formula with N, independently of S, so S - Ê has variance
// V = V_n + V_N. Cantelli's one-sided inequality (Cantelli 1928; any law with a variance),
//
//     P(S - Ê >= t) <= V / (V + t²),   so   t = sqrt(V (1 - α) / α)
//
// bounds the chance that a correct submission exceeds Ê + t by α. No normal approximation:
// path-tracing samples are heavy-tailed and their variances more so (a pixel that caught one
// firefly), so an F or χ² bound per pixel, or a normal one on S, would fail correct work. The
// submission fails when S > Ê + t + R, R the float-rounding allowance of its mean test (squared),
// that is when its variance is more than k = 1 + t / Ê times the reference's. k is a consequence
// of α, N, n and the reference's moments, never chosen.
//
// Channels of one sample are not independent (one path carries all three), and their cross moments
// are not kept, so channels are combined by Minkowski's inequality: the standard deviation of a sum
// is at most the sum of the standard deviations.
#include <array>
#include <string>

struct Variance_Sum {
	double expected = 0.0;  // Ê: the reference's Σ σ²
	double variance = 0.0;  // V: the variance of S - Ê under H0
	double rounding = 0.0;  // R: Σ (float-rounding standard deviation)², allowed on top

	// One estimate of n samples, against the reference's variance and per-sample fourth central
	// moment (m4 / N) estimated from N samples; rounding_sd: its mean test's float allowance.
	void add(double reference_variance, double reference_fourth, double n, double n_reference, double rounding_sd);
};

// Three channels' sums as one (Minkowski: standard deviations add).
Variance_Sum combine_channels(const std::array<Variance_Sum, 3>& channels);

struct Noise_Check {
	bool pass = false;
	double submitted = 0.0; // S
	double reference = 0.0; // Ê
	double allowed = 0.0;   // Ê + t + R
	double ratio = 0.0;     // S / Ê (infinite when Ê = 0 < S)
	double k = 0.0;         // allowed / Ê: the largest ratio a correct submission reaches (but for α)
	double alpha = 0.0;
};

// S against the reference's sum at significance alpha (one-sided).
Noise_Check check_noise(double submitted, const Variance_Sum& reference, double alpha);

// "the per-sample variance of <what> is 37.2 times the reference's (6.1 against 0.164); a correct
// solution stays below 1.21 times (one-sided bound at alpha = 0.005)".
std::string describe(const Noise_Check& check, const std::string& what);
