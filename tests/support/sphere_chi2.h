#pragma once
// Pearson's chi-square test of a sampler of directions against its density over the unit sphere
// (the method of pbrt-v4's BSDF tests and Mitsuba 3's ChiSquareTest).
//
// Cells are a grid in the spherical coordinates of env_light.h:
//   theta = angle from +y in [0, pi], phi = atan2(z, x) in [0, 2 pi).
// The local shading frame (frame.h) also has +y as its axis, so BSDF samplers fit as they are.
// The expected count of a cell is N times the integral of pdf * sin(theta) over the cell in
// (theta, phi), by the midpoint rule on integration_resolution^2 points. That rule is exact for a
// pdf of the form f(theta, phi) / sin(theta) with f constant on the cell, so choose the grid of an
// environment-map test as a refinement of the map's texel grid (cells never straddle a texel), and
// use a few points per cell for smooth densities.
#include "vec_math.h"
#include "rng.h"
#include "statistics.h"

#include <functional>
#include <string>
#include <vector>

namespace stats {

struct Sphere_Chi2_Settings {
	size_t samples = 1000000;
	uint32_t theta_cells = 32;
	uint32_t phi_cells = 64;
	uint32_t integration_resolution = 4; // points per cell along each axis
	uint64_t seed = 1;
	double min_expected = 5.0; // cells with fewer expected samples are pooled
};

struct Sphere_Chi2_Result {
	Chi2_Result chi2;
	size_t samples = 0;
	double pdf_integral = 0.0;    // the pdf integrated over the sphere with the cells' quadrature
	size_t invalid_samples = 0;   // directions that were not finite or not of unit length (1e-3)
	size_t invalid_pdf_values = 0; // pdf values that were negative or not finite

	// The samples in cells where the pdf is zero may only come from rounding at the border of the
	// pdf's support: at most 1e-5 of them (pbrt-v4's rule).
	bool samples_outside_support_ok() const {
		return chi2.observed_in_impossible_cells <= 1e-5 * double(samples);
	}
	// Everything that must hold for the sampler to match its pdf at significance `alpha`.
	bool pass(double alpha) const;
	// The numbers above, in one line, for failure messages.
	std::string summary() const;
};

using Direction_Sampler = std::function<Vec3(RNG&)>;
using Direction_Pdf = std::function<float(Vec3)>;

Sphere_Chi2_Result sphere_chi2(const Direction_Sampler& sample, const Direction_Pdf& pdf,
                               const Sphere_Chi2_Settings& settings = {});

// The same test for a sampler that ran elsewhere (a subject, grading/judge/): its samples (their
// number replaces settings.samples; settings.seed is not used) and its pdf at the integration
// points sphere_chi2_pdf_directions(settings), in that order.
std::vector<Vec3> sphere_chi2_pdf_directions(const Sphere_Chi2_Settings& settings);
Sphere_Chi2_Result sphere_chi2(const std::vector<Vec3>& samples, const std::vector<float>& pdf_values,
                               const Sphere_Chi2_Settings& settings);

} // namespace stats
