#include "sphere_chi2.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace stats {

namespace {

struct Grid {
	uint32_t theta_cells, phi_cells;

	size_t cells() const {
		return size_t(theta_cells) * phi_cells;
	}
	// The cell of a direction (any length).
	size_t cell_of(Vec3 d) const {
		double theta = std::atan2(std::sqrt(double(d.x) * d.x + double(d.z) * d.z), double(d.y));
		double phi = std::atan2(double(d.z), double(d.x));
		if (phi < 0.0) phi += 2.0 * M_PI;
		auto index = [](double t, uint32_t n) { return std::min(uint32_t(t * n), n - 1); };
		return size_t(index(theta / M_PI, theta_cells)) * phi_cells + index(phi / (2.0 * M_PI), phi_cells);
	}
};

Vec3 direction(double theta, double phi) {
	return Vec3(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)), float(std::sin(theta) * std::sin(phi)));
}

} // namespace

bool Sphere_Chi2_Result::pass(double alpha) const {
	return invalid_samples == 0 && invalid_pdf_values == 0 && samples_outside_support_ok() && chi2.dof > 0 &&
	       std::isfinite(chi2.statistic) && chi2.p_value >= alpha;
}

std::string Sphere_Chi2_Result::summary() const {
	std::ostringstream s;
	s << "chi2 = " << chi2.statistic << " with " << chi2.dof << " degrees of freedom, p-value " << chi2.p_value
	  << "; integral of the pdf over the sphere " << pdf_integral << "; " << invalid_samples
	  << " invalid (non-finite or non-unit) sample directions of " << samples << "; " << invalid_pdf_values
	  << " negative or non-finite pdf values; " << chi2.observed_in_impossible_cells
	  << " samples where the pdf is 0";
	return s.str();
}

std::vector<Vec3> sphere_chi2_pdf_directions(const Sphere_Chi2_Settings& settings) {
	const uint32_t r = settings.integration_resolution;
	const double d_theta = M_PI / (double(settings.theta_cells) * r);
	const double d_phi = 2.0 * M_PI / (double(settings.phi_cells) * r);
	std::vector<Vec3> directions;
	for (uint32_t a = 0; a < settings.theta_cells * r; a++) {
		for (uint32_t b = 0; b < settings.phi_cells * r; b++) {
			directions.push_back(direction((a + 0.5) * d_theta, (b + 0.5) * d_phi));
		}
	}
	return directions;
}

Sphere_Chi2_Result sphere_chi2(const std::vector<Vec3>& samples, const std::vector<float>& pdf_values,
                               const Sphere_Chi2_Settings& settings) {
	Grid grid{settings.theta_cells, settings.phi_cells};
	Sphere_Chi2_Result result;
	result.samples = samples.size();

	std::vector<double> observed(grid.cells(), 0.0);
	for (Vec3 d : samples) {
		if (!is_finite(d) || std::abs(glm::length(d) - 1.0f) > 1e-3f) {
			result.invalid_samples++;
			continue;
		}
		observed[grid.cell_of(d)] += 1.0;
	}

	// Expected counts: N * integral over the cell of pdf * sin(theta) d theta d phi (midpoint rule
	// at the points of sphere_chi2_pdf_directions, in its order).
	std::vector<double> expected(grid.cells(), 0.0);
	const uint32_t r = settings.integration_resolution;
	if (pdf_values.size() != sphere_chi2_pdf_directions(settings).size()) {
		throw std::invalid_argument("sphere_chi2: " + std::to_string(pdf_values.size()) +
		                            " pdf values, not one per point of sphere_chi2_pdf_directions");
	}
	const double d_theta = M_PI / (double(grid.theta_cells) * r);
	const double d_phi = 2.0 * M_PI / (double(grid.phi_cells) * r);
	size_t k = 0;
	for (uint32_t a = 0; a < grid.theta_cells * r; a++) {
		double theta = (a + 0.5) * d_theta;
		for (uint32_t b = 0; b < grid.phi_cells * r; b++) {
			double p = pdf_values[k++];
			if (!std::isfinite(p) || p < 0.0) {
				result.invalid_pdf_values++;
				continue;
			}
			double mass = p * std::sin(theta) * d_theta * d_phi;
			expected[size_t(a / r) * grid.phi_cells + b / r] += mass;
			result.pdf_integral += mass;
		}
	}
	for (double& e : expected) e *= double(samples.size());

	result.chi2 = chi2_test(observed, expected, settings.min_expected);
	return result;
}

Sphere_Chi2_Result sphere_chi2(const Direction_Sampler& sample, const Direction_Pdf& pdf,
                               const Sphere_Chi2_Settings& settings) {
	std::vector<Vec3> samples(settings.samples);
	RNG rng(settings.seed);
	for (Vec3& d : samples) d = sample(rng);
	std::vector<float> pdf_values;
	for (Vec3 d : sphere_chi2_pdf_directions(settings)) pdf_values.push_back(pdf(d));
	return sphere_chi2(samples, pdf_values, settings);
}

} // namespace stats
