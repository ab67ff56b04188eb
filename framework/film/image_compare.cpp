#include "image_compare.h"

#include "film.h"
#include "significance.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

Image_Estimate Image_Estimate::from(const Film& film) {
	Image_Estimate estimate{film.mean(), film.variance(), film.fourth_moment(), {}};
	for (const Pixel_Stats& pixel : film.pixels) estimate.samples.push_back(pixel.count);
	return estimate;
}

Image_Estimate Image_Estimate::from(const Film& film, uint32_t samples) {
	return uniform(film.mean(), film.variance(), film.fourth_moment(), samples);
}

Image_Estimate Image_Estimate::uniform(HDR_Image mean, HDR_Image variance, HDR_Image fourth, uint32_t samples) {
	std::vector<uint32_t> counts(mean.pixels.size(), samples);
	return Image_Estimate{std::move(mean), std::move(variance), std::move(fourth), std::move(counts)};
}

namespace {

// How a pixel channel's standard error is made (image_compare.h).
enum class Noise_Source {
	reference,          // the reference's variance alone: a submission against the reference
	larger_of_the_two,  // two trusted estimators: the larger per-sample variance for the first
};

double floor_of(double x, double r) {
	return IMAGE_SIGMA_FLOOR * std::max(std::abs(x), std::abs(r));
}

// z of channel `ch` of pixel `i` of the render against the reference.
double channel_z(const Image_Estimate& render, const Image_Estimate& reference, size_t i, int ch, Noise_Source source) {
	double x = render.mean.pixels[i][ch], r = reference.mean.pixels[i][ch];
	if (x == r) return 0.0;
	double n_x = render.samples[i], n_r = reference.samples[i];
	if (n_x < 1.0) return INFINITY; // no finite sample at all
	double var_r = reference.variance.pixels[i][ch];
	double var_x = source == Noise_Source::reference ? var_r : std::max(double(render.variance.pixels[i][ch]), var_r);
	double floor = floor_of(x, r);
	return (x - r) / std::sqrt(var_x / n_x + var_r / n_r + floor * floor);
}

void require_same_size(const std::string& caller, const HDR_Image& x, const HDR_Image& r) {
	if (x.w != r.w || x.h != r.h) {
		throw std::invalid_argument(caller + ": the render is " + std::to_string(x.w) + " x " +
		                            std::to_string(x.h) + ", the reference " + std::to_string(r.w) + " x " +
		                            std::to_string(r.h));
	}
}

// How many pixels differ beyond noise and how many may, in words (`alpha`: the chance that a correct
// render has more than allowed_outliers, for a calibrated comparison); where they are, the worst.
std::string describe(const Image_Comparison& c, uint32_t w, uint32_t h, double alpha) {
	std::ostringstream out;
	out << std::setprecision(3) << c.outliers << " of the " << w * h << " pixels (" << c.failed << " of " << c.tests
	    << " pixel channels) differ from the reference by more than its noise explains (|z| above " << c.z_critical
	    << "). ";
	if (c.lambda >= 0.0) {
		out << "Up to " << c.allowed_outliers << " may: even a correct render has a few, pixels whose few samples "
		    << "caught a rare bright path (" << c.lambda << " on average, at most), and more than "
		    << c.allowed_outliers << " only with a chance below " << std::setprecision(2) << 100.0 * alpha << " %";
	} else {
		out << "Up to " << c.allowed_outliers << " pixel channels may (" << 100.0 * (1.0 - IMAGE_MIN_PASS_FRACTION)
		    << " % of them): both renders are still noisy";
	}
	if (c.failed) {
		out << std::setprecision(6) << "; they lie in pixels x " << c.box_x0 << ".." << c.box_x1 << ", y " << c.box_y0
		    << ".." << c.box_y1 << " of the " << w << " x " << h << " image (0, 0 = top-left); the worst is pixel ("
		    << c.worst_x << ", " << c.worst_y << ") with z = " << c.worst_z
		    << (c.worst_z > 0 ? " (the render is too bright there)" : " (the render is too dark there)");
	}
	out << "; relMSE = " << c.rel_mse;
	return out.str();
}

// The z-score of every pixel channel against z_critical: the channels and pixels beyond it (the
// verdict is the caller's).
Image_Comparison compare_means(const Image_Estimate& render, const Image_Estimate& reference, Noise_Source source) {
	const HDR_Image& x = render.mean;
	const HDR_Image& r = reference.mean;
	require_same_size("compare_images", x, r);
	Image_Comparison c;
	c.tests = x.pixels.size() * 3;
	c.z_critical = outlier_z(x.pixels.size());
	c.box_x0 = x.w, c.box_y0 = x.h;
	double squared_error = 0.0;
	for (uint32_t py = 0; py < x.h; py++) {
		for (uint32_t px = 0; px < x.w; px++) {
			size_t i = size_t(py) * x.w + px;
			bool outlier = false;
			for (int ch = 0; ch < 3; ch++) {
				double xm = x.pixels[i][ch], rm = r.pixels[i][ch];
				squared_error += (xm - rm) * (xm - rm) / (rm * rm + 0.01);
				double z = channel_z(render, reference, i, ch, source);
				if (std::abs(z) > std::abs(c.worst_z)) c.worst_z = z, c.worst_x = px, c.worst_y = py;
				if (!(std::abs(z) <= c.z_critical)) {
					c.failed++;
					outlier = true;
					c.box_x0 = std::min(c.box_x0, px), c.box_x1 = std::max(c.box_x1, px);
					c.box_y0 = std::min(c.box_y0, py), c.box_y1 = std::max(c.box_y1, py);
				}
			}
			c.outliers += outlier;
		}
	}
	c.rel_mse = squared_error / double(c.tests);
	return c;
}

// The most outliers a correct render has but with probability alpha (image_compare.h): the largest
// count whose Poisson(lambda) upper tail is above alpha.
size_t allowed_outliers(double lambda, double alpha) {
	uint64_t count = uint64_t(std::floor(lambda)) + 1; // the tail bound holds from lambda + 1 on
	while (stats::poisson_upper_tail(lambda, count) > alpha) count++;
	return size_t(count - 1);
}

// The render's per-sample variance summed over every pixel channel against the reference's
// (noise_bound.h), with the z-tests' floor as the rounding allowance.
Noise_Check compare_noise(const Image_Estimate& render, const Image_Estimate& reference, double alpha) {
	if (reference.fourth.w != reference.mean.w || reference.fourth.h != reference.mean.h) {
		throw std::invalid_argument("compare_images: the reference has no fourth moments (its _m4.exr)");
	}
	std::array<Variance_Sum, 3> channels;
	double submitted = 0.0;
	for (size_t i = 0; i < render.mean.pixels.size(); i++) {
		for (int ch = 0; ch < 3; ch++) {
			submitted += render.variance.pixels[i][ch];
			double r = reference.mean.pixels[i][ch];
			channels[ch].add(reference.variance.pixels[i][ch], reference.fourth.pixels[i][ch], render.samples[i],
			                 reference.samples[i], floor_of(r, r));
		}
	}
	return check_noise(submitted, combine_channels(channels), alpha);
}

} // namespace

size_t count_outliers(const Image_Estimate& render, const Image_Estimate& reference) {
	return compare_means(render, reference, Noise_Source::reference).outliers;
}

double outlier_z(size_t pixels) {
	return stats::two_sided_z(stats::sidak(IMAGE_ALPHA, 3 * pixels));
}

Image_Comparison compare_images(const Image_Estimate& render, const Image_Estimate& reference,
                                const Image_Calibration& calibration, double alpha) {
	double alpha_check = stats::sidak(alpha, 2); // the outliers and the noise bound
	Image_Comparison c = compare_means(render, reference, Noise_Source::reference);
	if (calibration.renders == 0) throw std::invalid_argument("compare_images: the reference has no outlier counts");
	{
		if (std::abs(calibration.z_critical - c.z_critical) > 1e-6 * c.z_critical) {
			throw std::invalid_argument("compare_images: the reference's outliers were counted at |z| > " +
			                            std::to_string(calibration.z_critical) + ", not " + std::to_string(c.z_critical) +
			                            ": run `./lab references`");
		}
		c.lambda = stats::poisson_upper_limit(calibration.outliers, CALIBRATION_CONFIDENCE) / calibration.renders;
		c.allowed_outliers = allowed_outliers(c.lambda, alpha_check);
	}
	c.means_pass = c.outliers <= c.allowed_outliers;
	c.message = describe(c, render.mean.w, render.mean.h, alpha_check);
	c.noise = compare_noise(render, reference, alpha_check);
	c.noise_message = describe(c.noise, "the render, summed over its pixels and channels,");
	c.pass = c.means_pass && c.noise.pass;
	return c;
}

Image_Comparison compare_estimators(const Image_Estimate& noisier, const Image_Estimate& other) {
	Image_Comparison c = compare_means(noisier, other, Noise_Source::larger_of_the_two);
	c.allowed_outliers = size_t((1.0 - IMAGE_MIN_PASS_FRACTION) * double(c.tests)); // channels, here
	c.lambda = -1.0;                                                                // not calibrated
	c.means_pass = c.failed <= c.allowed_outliers;
	c.message = describe(c, noisier.mean.w, noisier.mean.h, 0.0);
	c.noise.pass = true;
	c.pass = c.means_pass;
	return c;
}

namespace {
HDR_Image z_image(const Image_Estimate& render, const Image_Estimate& reference, Noise_Source source) {
	require_same_size("z_scores", render.mean, reference.mean);
	HDR_Image z(render.mean.w, render.mean.h);
	for (size_t i = 0; i < z.pixels.size(); i++) {
		for (int ch = 0; ch < 3; ch++) z.pixels[i][ch] = float(channel_z(render, reference, i, ch, source));
	}
	return z;
}
} // namespace

HDR_Image z_scores(const Image_Estimate& render, const Image_Estimate& reference) {
	return z_image(render, reference, Noise_Source::reference);
}

HDR_Image estimator_z_scores(const Image_Estimate& noisier, const Image_Estimate& other) {
	return z_image(noisier, other, Noise_Source::larger_of_the_two);
}
