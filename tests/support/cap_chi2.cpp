#include "cap_chi2.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace stats {

namespace {
constexpr int POINTS = 4;         // midpoint rule, per axis
constexpr int MAX_DEPTH = 6;      // splits of a piece that straddles a jump
constexpr double ROUGH = 0.05;    // relative spread of the integrand that calls for a split
constexpr double NUDGE = 1e-2;    // border probes sit this fraction of a piece inside it
constexpr double ROUNDING = 1e-6; // slack in u for grazing samples (float directions)
constexpr double TWO_PI = 2.0 * M_PI;
} // namespace

Cap_Cells::Cap_Cells(Vec3 axis_, std::vector<double> ring_edges, uint32_t sectors_, double silhouette_)
	: axis(glm::normalize(axis_)), edges(std::move(ring_edges)), sectors(sectors_),
	  silhouette(std::isnan(silhouette_) ? -INFINITY : silhouette_) {
	// Any two unit vectors completing an orthonormal frame.
	Vec3 helper = std::abs(axis.x) < 0.9f ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
	x = glm::normalize(glm::cross(helper, axis));
	z = glm::cross(axis, x);
}

std::vector<double> Cap_Cells::even_edges(double cos_min, uint32_t rings) {
	std::vector<double> e;
	for (uint32_t i = 0; i <= rings; i++) e.push_back(cos_min + (1.0 - cos_min) * double(i) / double(rings));
	e.back() = 1.0;
	return e;
}

Vec3 Cap_Cells::direction(double u, double phi) const {
	double sin_alpha = std::sqrt(std::max(0.0, 1.0 - u * u));
	glm::dvec3 d = sin_alpha * std::cos(phi) * glm::dvec3(x) + sin_alpha * std::sin(phi) * glm::dvec3(z) +
	               u * glm::dvec3(axis);
	return Vec3(glm::normalize(d));
}

glm::dvec2 Cap_Cells::u_phi(Vec3 dir) const {
	glm::dvec3 d(dir);
	double phi = std::atan2(glm::dot(d, glm::dvec3(z)), glm::dot(d, glm::dvec3(x)));
	return {glm::dot(d, glm::dvec3(axis)), phi < 0.0 ? phi + TWO_PI : phi};
}

size_t Cap_Cells::cell(Vec3 dir) const {
	glm::dvec2 up = u_phi(dir);
	double u = up.x, phi = up.y;
	if (u < silhouette && u >= silhouette - ROUNDING) u = silhouette;
	if (u < edges.front() - ROUNDING) return count();
	size_t ring = size_t(std::upper_bound(edges.begin(), edges.end(), u) - edges.begin());
	ring = std::clamp<size_t>(ring, 1, edges.size() - 1) - 1;
	size_t sector = std::min<size_t>(size_t(phi / TWO_PI * sectors), sectors - 1);
	return ring * sectors + sector;
}

Cap_Cells::Integral Cap_Cells::integrate(size_t cell, const Density_Of_Directions& pdf) const {
	size_t ring = cell / sectors, sector = cell % sectors;
	double u_lo = edges[ring], u_hi = edges[ring + 1];
	glm::dvec2 phi{TWO_PI * double(sector) / sectors, TWO_PI * double(sector + 1) / sectors};
	bool above = std::isfinite(silhouette) && u_lo >= silhouette;
	glm::dvec2 t = above ? glm::dvec2{std::sqrt(u_lo - silhouette), std::sqrt(u_hi - silhouette)}
	                     : glm::dvec2{u_lo, u_hi};
	return integrate_piece(above, t, phi, pdf, 0);
}

Cap_Cells::Integral Cap_Cells::integrate(const Density_Of_Directions& pdf) const {
	Integral total;
	for (size_t c = 0; c < count(); c++) {
		Integral cell = integrate(c, pdf);
		total.value += cell.value;
		total.error_bound += cell.error_bound;
	}
	return total;
}

// The piece [t0, t1] x [phi0, phi1] of a cell: above the silhouette u = u_s + t^2 and
// d(omega) = du d(phi) = 2 t dt d(phi); below it u = t.
Cap_Cells::Integral Cap_Cells::integrate_piece(bool above_silhouette, glm::dvec2 t_range, glm::dvec2 phi_range,
                                                 const Density_Of_Directions& pdf, int depth) const {
	double t0 = t_range.x, t1 = t_range.y, phi0 = phi_range.x, phi1 = phi_range.y;
	auto u_of = [&](double t) { return above_silhouette ? silhouette + t * t : t; };
	auto jacobian = [&](double t) { return above_silhouette ? 2.0 * t : 1.0; };

	double ht = (t1 - t0) / POINTS, hphi = (phi1 - phi0) / POINTS;
	double sum = 0.0, low = INFINITY, high = 0.0;
	auto integrand = [&](double t, double phi) {
		double f = pdf(direction(u_of(t), phi)) * jacobian(t);
		low = std::min(low, f), high = std::max(high, f);
		return f;
	};
	for (int i = 0; i < POINTS; i++) {
		for (int j = 0; j < POINTS; j++) sum += integrand(t0 + (i + 0.5) * ht, phi0 + (j + 0.5) * hphi);
	}
	// Probes on the border of the piece (nudged inside) catch a jump that only grazes it.
	for (int i = 0; i <= POINTS; i++) {
		for (int j = 0; j <= POINTS; j++) {
			if (i != 0 && i != POINTS && j != 0 && j != POINTS) continue;
			double ti = glm::clamp(double(i) / POINTS, NUDGE, 1.0 - NUDGE);
			double tj = glm::clamp(double(j) / POINTS, NUDGE, 1.0 - NUDGE);
			integrand(t0 + ti * (t1 - t0), phi0 + tj * (phi1 - phi0));
		}
	}
	Integral result{sum * ht * hphi, 0.0};
	// Above a silhouette the integrand is smooth by construction; splitting there would only
	// reach the float rounding of directions that graze the sphere.
	bool smooth = above_silhouette || (high - low <= ROUGH * high && !contains_corner(t_range, phi_range));
	if (smooth) return result;
	// The midpoint sum and the true integral both lie in [low, high] * area (up to what the probes
	// missed), so they differ by at most (high - low) * area.
	if (depth == MAX_DEPTH) return Integral{result.value, (high - low) * (t1 - t0) * (phi1 - phi0)};

	Integral total;
	double tm = 0.5 * (t0 + t1), pm = 0.5 * (phi0 + phi1);
	for (glm::dvec2 t : {glm::dvec2{t0, tm}, glm::dvec2{tm, t1}}) {
		for (glm::dvec2 phi : {glm::dvec2{phi0, pm}, glm::dvec2{pm, phi1}}) {
			Integral piece = integrate_piece(above_silhouette, t, phi, pdf, depth + 1);
			total.value += piece.value;
			total.error_bound += piece.error_bound;
		}
	}
	return total;
}

// (Pieces below the silhouette only, where t = u.)
bool Cap_Cells::contains_corner(glm::dvec2 u_range, glm::dvec2 phi_range) const {
	for (Vec3 corner : corners) {
		glm::dvec2 up = u_phi(corner);
		double u = up.x, phi = up.y;
		if (u >= u_range.x && u <= u_range.y && phi >= phi_range.x && phi <= phi_range.y) return true;
	}
	return false;
}

std::string Cap_Chi2_Result::summary() const {
	std::ostringstream out;
	out << samples << " samples: chi2 = " << chi2.statistic << " with " << chi2.dof << " degrees of freedom, p = "
	    << chi2.p_value << "; " << chi2.observed_in_impossible_cells
	    << " samples where the density is zero (of which " << outside_cap << " outside the light's cone)"
	    << "; density integrates to " << pdf_integral << " (+- " << integral_error_bound << ")";
	return out.str();
}

Cap_Chi2_Result cap_chi2(const Cap_Cells& cells, const Sampler_Of_Directions& sample,
                         const Density_Of_Directions& pdf, size_t samples, uint64_t seed) {
	Cap_Chi2_Result result;
	result.samples = samples;
	std::vector<double> observed(cells.count() + 1, 0.0), expected(cells.count() + 1, 0.0);
	RNG rng(seed);
	for (size_t i = 0; i < samples; i++) observed[cells.cell(sample(rng))] += 1.0;
	result.outside_cap = size_t(observed.back());
	for (size_t c = 0; c < cells.count(); c++) {
		Cap_Cells::Integral integral = cells.integrate(c, pdf);
		expected[c] = double(samples) * integral.value;
		result.pdf_integral += integral.value;
		result.integral_error_bound += integral.error_bound;
	}
	// expected.back() stays 0: the cap must contain every sample.
	result.chi2 = chi2_test(observed, expected);
	return result;
}

} // namespace stats
