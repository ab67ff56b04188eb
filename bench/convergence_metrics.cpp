#include "convergence_metrics.h"

#include <cmath>

namespace {
double relative(double squared_error, double r) {
	return squared_error / (r * r + REL_MSE_EPSILON);
}
} // namespace

Render_Error render_error(const Film& film, const Reference& reference) {
	Render_Error error;
	for (size_t i = 0; i < film.pixels.size(); i++) {
		const Pixel_Stats& pixel = film.pixels[i];
		for (int c = 0; c < 3; c++) {
			double x = pixel.mean[c], r = reference.mean.pixels[i][c];
			error.rel_mse += relative((x - r) * (x - r), r);
			// Variance of the mean: s^2 / n with s^2 = m2 / (n - 1); 0 when one sample cannot tell.
			if (pixel.count > 1) error.variance += pixel.m2[c] / double(pixel.count - 1) / double(pixel.count);
		}
	}
	double channels = 3.0 * double(film.pixels.size());
	error.rel_mse /= channels;
	error.variance /= channels;
	return error;
}

double reference_rel_mse(const Reference& reference) {
	double sum = 0.0;
	for (size_t i = 0; i < reference.mean.pixels.size(); i++)
		for (int c = 0; c < 3; c++)
			sum += relative(double(reference.variance.pixels[i][c]) / reference.samples, reference.mean.pixels[i][c]);
	return sum / (3.0 * double(reference.mean.pixels.size()));
}

double log_log_slope(const std::vector<double>& x, const std::vector<double>& y) {
	// slope = sum (u - mean u)(v - mean v) / sum (u - mean u)^2 with u = log x, v = log y.
	double n = double(x.size()), mean_u = 0.0, mean_v = 0.0;
	for (size_t i = 0; i < x.size(); i++) {
		mean_u += std::log(x[i]) / n;
		mean_v += std::log(y[i]) / n;
	}
	double covariance = 0.0, spread = 0.0;
	for (size_t i = 0; i < x.size(); i++) {
		double u = std::log(x[i]) - mean_u, v = std::log(y[i]) - mean_v;
		covariance += u * v;
		spread += u * u;
	}
	return covariance / spread;
}
