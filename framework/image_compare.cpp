#include "image_compare.h"

#include "film.h"
#include "significance.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

Image_Estimate Image_Estimate::from(const Film& film) {
	Image_Estimate estimate{film.mean(), film.variance(), {}};
	for (const Pixel_Stats& pixel : film.pixels) estimate.samples.push_back(pixel.count);
	return estimate;
}

Image_Estimate Image_Estimate::uniform(HDR_Image mean, HDR_Image variance, uint32_t samples) {
	std::vector<uint32_t> counts(mean.pixels.size(), samples);
	return Image_Estimate{std::move(mean), std::move(variance), std::move(counts)};
}

namespace {
// z of one pixel channel (see the header).
double pixel_z(double x, double var_x, double n_x, double r, double var_r, double n_r) {
	if (x == r) return 0.0;
	if (n_x < 1.0) return INFINITY; // no finite sample at all
	double s2 = std::max(var_x, var_r);
	double floor = IMAGE_SIGMA_FLOOR * std::max(std::abs(x), std::abs(r));
	return (x - r) / std::sqrt(s2 / n_x + var_r / n_r + floor * floor);
}

// z of channel `ch` of pixel `i` of the render against the reference.
double channel_z(const Image_Estimate& render, const Image_Estimate& reference, size_t i, int ch) {
	return pixel_z(render.mean.pixels[i][ch], render.variance.pixels[i][ch], render.samples[i],
	               reference.mean.pixels[i][ch], reference.variance.pixels[i][ch], reference.samples[i]);
}

void require_same_size(const std::string& caller, const HDR_Image& x, const HDR_Image& r) {
	if (x.w != r.w || x.h != r.h) {
		throw std::invalid_argument(caller + ": the render is " + std::to_string(x.w) + " x " +
		                            std::to_string(x.h) + ", the reference " + std::to_string(r.w) + " x " +
		                            std::to_string(r.h));
	}
}

std::string describe(const Image_Comparison& c, uint32_t w, uint32_t h) {
	std::ostringstream out;
	out << c.failed << " of " << c.tests << " pixel channels differ from the reference by more than |z| = "
	    << c.z_critical << " (allowed: " << size_t((1.0 - IMAGE_MIN_PASS_FRACTION) * double(c.tests)) << ")";
	if (c.failed) {
		out << "; they lie in pixels x " << c.box_x0 << ".." << c.box_x1 << ", y " << c.box_y0 << ".." << c.box_y1
		    << " of the " << w << " x " << h << " image (0, 0 = top-left); the worst is pixel (" << c.worst_x << ", "
		    << c.worst_y << ") with z = " << c.worst_z
		    << (c.worst_z > 0 ? " (the render is too bright there)" : " (the render is too dark there)");
	}
	out << "; relMSE = " << c.rel_mse;
	return out.str();
}
} // namespace

Image_Comparison compare_images(const Image_Estimate& render, const Image_Estimate& reference) {
	const HDR_Image& x = render.mean;
	const HDR_Image& r = reference.mean;
	require_same_size("compare_images", x, r);
	Image_Comparison c;
	c.tests = x.pixels.size() * 3;
	c.z_critical = stats::two_sided_z(stats::sidak(IMAGE_ALPHA, c.tests));
	c.box_x0 = x.w, c.box_y0 = x.h;
	double squared_error = 0.0;
	for (uint32_t py = 0; py < x.h; py++) {
		for (uint32_t px = 0; px < x.w; px++) {
			size_t i = size_t(py) * x.w + px;
			for (int ch = 0; ch < 3; ch++) {
				double xm = x.pixels[i][ch], rm = r.pixels[i][ch];
				squared_error += (xm - rm) * (xm - rm) / (rm * rm + 0.01);
				double z = channel_z(render, reference, i, ch);
				if (std::abs(z) > std::abs(c.worst_z)) c.worst_z = z, c.worst_x = px, c.worst_y = py;
				if (!(std::abs(z) <= c.z_critical)) {
					c.failed++;
					c.box_x0 = std::min(c.box_x0, px), c.box_x1 = std::max(c.box_x1, px);
					c.box_y0 = std::min(c.box_y0, py), c.box_y1 = std::max(c.box_y1, py);
				}
			}
		}
	}
	c.rel_mse = squared_error / double(c.tests);
	c.pass = double(c.tests - c.failed) >= IMAGE_MIN_PASS_FRACTION * double(c.tests);
	c.message = describe(c, x.w, x.h);
	return c;
}

HDR_Image z_scores(const Image_Estimate& render, const Image_Estimate& reference) {
	require_same_size("z_scores", render.mean, reference.mean);
	HDR_Image z(render.mean.w, render.mean.h);
	for (size_t i = 0; i < z.pixels.size(); i++) {
		for (int ch = 0; ch < 3; ch++) z.pixels[i][ch] = float(channel_z(render, reference, i, ch));
	}
	return z;
}
