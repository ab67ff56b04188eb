#pragma once
// Chi-square tests of a direction sampler whose samples fill only part of the sphere: a light seen
// from a point. A grid over the whole sphere (sphere_chi2.h) would put a small light into a handful
// of cells; these cells cover only the CAP of directions within a given angle of an axis.
//
// Cells: rings between given values of u = cos(alpha) (alpha = angle from the axis), times equal
// sectors of azimuth. Cells of one ring have equal area (a zone between u_lo and u_hi has area
// 2 pi (u_hi - u_lo), Archimedes), and evenly spaced ring edges make every cell the same area.
//
// Integrating a light's density over a cell needs care, because the density has jumps (the outline
// of a polygon, the edges between a mesh's triangles) and, for a sphere seen from outside, an
// integrable singularity ~ 1/sqrt(u - u_s) at its silhouette u = u_s (both crossings of the sphere
// meet there at grazing angles):
// - given a silhouette, cells above it are integrated over (t, phi) with u = u_s + t^2, which turns
//   that singularity into a smooth integrand (du = 2 t dt); other cells over (u, phi). Each by the
//   midpoint rule on 4 x 4 points. Put u_s on a ring edge.
// - a piece whose integrand varies by more than 5% over its points (and 24 probes on its border)
//   straddles a jump: it is split in four, recursively, up to 6 times; the pieces still rough at
//   the end add (area * spread of the integrand) to an error bound. Probes can miss the sharp tip
//   of a polygon's corner, so pieces that contain a given corner direction are split as well.
//   Cells above a silhouette are smooth by construction and never split.
#include "vec_math.h"
#include "rng.h"
#include "statistics.h"

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace stats {

using Sampler_Of_Directions = std::function<Vec3(RNG&)>;
using Density_Of_Directions = std::function<double(Vec3)>; // over solid angle

class Cap_Cells {
public:
	// ring_edges: increasing values of cos(alpha), from the cap's edge (>= -1) to 1. silhouette: the
	// u_s above, for a sphere light (NaN: none).
	Cap_Cells(Vec3 axis, std::vector<double> ring_edges, uint32_t sectors, double silhouette = NAN);

	// Directions of the corners of a polygonal light (unit), where the outline has sharp tips.
	std::vector<Vec3> corners;

	// `rings` evenly spaced edges from cos_min to 1 (equal-area cells).
	static std::vector<double> even_edges(double cos_min, uint32_t rings);

	size_t count() const {
		return (edges.size() - 1) * sectors;
	}
	// The cell of a unit direction, or count() if it lies outside the cap. Directions within 1e-6 in
	// u below the cap's edge or the silhouette (float rounding of a grazing sample) count as on it.
	size_t cell(Vec3 dir) const;

	struct Integral {
		double value = 0.0;
		double error_bound = 0.0; // from pieces still rough after all splits
	};
	Integral integrate(size_t cell, const Density_Of_Directions& pdf) const;
	Integral integrate(const Density_Of_Directions& pdf) const; // over the whole cap

private:
	Vec3 direction(double u, double phi) const;
	Integral integrate_piece(bool above_silhouette, glm::dvec2 t_range, glm::dvec2 phi_range,
	                         const Density_Of_Directions& pdf, int depth) const;
	glm::dvec2 u_phi(Vec3 dir) const; // cos(alpha) and azimuth in [0, 2 pi)
	bool contains_corner(glm::dvec2 u_range, glm::dvec2 phi_range) const;

	Vec3 axis, x, z; // orthonormal; alpha is measured from `axis`, phi from x towards z
	std::vector<double> edges;
	uint32_t sectors;
	double silhouette;
};

struct Cap_Chi2_Result {
	Chi2_Result chi2;
	size_t samples = 0;
	size_t outside_cap = 0;          // samples outside the cap (counted as impossible)
	double pdf_integral = 0.0;       // the density integrated over the cap
	double integral_error_bound = 0.0;

	// pbrt-v4's rule: samples in cells of zero expected count may only come from rounding at the
	// border of the support, at most 1e-5 of them.
	bool samples_outside_support_ok() const {
		return chi2.observed_in_impossible_cells <= 1e-5 * double(samples);
	}
	bool pass(double alpha) const {
		return samples_outside_support_ok() && chi2.p_value >= alpha;
	}
	std::string summary() const; // the numbers above in one line, for messages
};

// Draws `samples` directions (RNG seeded with `seed`), histograms them into the cells and tests the
// counts against N * (integral of pdf over each cell). Samples outside the cap count as samples in
// an impossible cell.
Cap_Chi2_Result cap_chi2(const Cap_Cells& cells, const Sampler_Of_Directions& sample,
                         const Density_Of_Directions& pdf, size_t samples, uint64_t seed);

} // namespace stats
