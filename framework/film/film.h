#pragma once
// The film: per-pixel running mean, variance and higher central moments of the samples, and a count
// of non-finite samples (which are never added to the mean but always reported). The third and
// fourth moments are what a grader needs to bound the sampling error of a variance: the variance
// of a sample variance s^2 of n samples is (mu4 - (n - 3) / (n - 1) sigma^4) / n.
#include "hdr_image.h"

#include <vector>

struct Pixel_Stats {
	// Welford's online algorithm, in double precision per channel, extended to the third and fourth
	// moments (Pébay 2008, "Formulas for robust, one-pass parallel computation of covariances and
	// arbitrary-order statistical moments", Sandia report SAND2008-6212, eq. 2.1-2.3).
	void add(Spectrum sample);
	// Adds another set of samples' statistics, as if its samples had been added one by one (Chan,
	// Golub and LeVeque 1979; Pébay 2008, eq. 3.1 for m3 and m4): the same sums in another order.
	void merge(const Pixel_Stats& other);

	// The pixel's value (the mean) and per-sample variance s^2 (0 below two samples), as the
	// film's images hold them.
	Spectrum mean_value() const {
		return Spectrum(mean);
	}
	Spectrum variance_value() const {
		return count > 1 ? Spectrum(m2 / double(count - 1)) : Spectrum{0.0f};
	}

	uint32_t count = 0;     // finite samples added
	uint32_t non_finite = 0;
	glm::dvec3 mean{0.0};
	glm::dvec3 m2{0.0};     // sum of squared deviations from the mean
	glm::dvec3 m3{0.0};     // sum of cubed deviations
	glm::dvec3 m4{0.0};     // sum of fourth powers of the deviations
};

struct Film {
	Film(uint32_t w, uint32_t h) : w(w), h(h), pixels(size_t(w) * h) {
	}

	HDR_Image mean() const;
	// Per-sample variance estimate s^2 (unbiased, n - 1); the variance of the mean is s^2 / n.
	HDR_Image variance() const;
	// Per-sample fourth central moment m4 / n (0 with fewer than two samples).
	HDR_Image fourth_moment() const;
	uint64_t non_finite() const;
	HDR_Image non_finite_map() const; // 1 where a pixel had a non-finite sample

	uint32_t w, h;
	std::vector<Pixel_Stats> pixels;
};
