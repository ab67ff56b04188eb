// Task 4: path tracing. Handout: handouts/task4_path.md
#include "pathtracer.h"
#include "frame.h"
#include "material.h"

#include <algorithm>

// ---- The Lambertian BSDF (handout §4.1) ----------------------------------------------------------
// Two-sided: the surface reflects on whichever side out_dir lies, so a path may arrive from below
// the shading normal (back faces, flipped normals) and still scatter.

namespace {
bool same_side(Vec3 a, Vec3 b) {
	return a.y * b.y > 0.0f;
}
} // namespace

Scatter BSDF_Lambertian::scatter(RNG& rng, Vec3 out_dir) const {
	// Malley's method: a point uniform on the unit disk, projected up onto the hemisphere, is
	// distributed with density cos(theta) / pi. Disk point (r, phi) with r = sqrt(u1), phi = 2 pi u2.
	Vec2 u = rng.unit2();
	float r = std::sqrt(u.x);
	float phi = 2.0f * PI_F * u.y;
	float cos_theta = std::sqrt(1.0f - u.x); // > 0 because u.x < 1
	Vec3 in_dir{r * std::cos(phi), cos_theta, r * std::sin(phi)};
	if (out_dir.y < 0.0f) in_dir.y = -in_dir.y; // reflect on the side the path arrived from
	return Scatter{in_dir, evaluate(out_dir, in_dir)};
}

Spectrum BSDF_Lambertian::evaluate(Vec3 out_dir, Vec3 in_dir) const {
	// f = albedo / pi: the cosine-weighted hemisphere integral of f is then exactly the albedo.
	return same_side(out_dir, in_dir) ? albedo * (1.0f / PI_F) : Spectrum{0.0f};
}

float BSDF_Lambertian::pdf(Vec3 out_dir, Vec3 in_dir) const {
	// p(in) = |cos(theta_in)| / pi on out_dir's side, 0 on the other.
	return same_side(out_dir, in_dir) ? std::abs(in_dir.y) * (1.0f / PI_F) : 0.0f;
}

// ---- The estimator (handout §4.2, §4.3) ----------------------------------------------------------

namespace {
float max_component(Spectrum s) {
	return std::max({s.r, s.g, s.b});
}

// The contribution factor of one sample of the reflected light:
// f * |cos(theta_in)| / pdf for a continuous BSDF, the attenuation itself for a discrete one.
Spectrum sample_weight(const Incoming_Sample& s, Vec3 normal) {
	if (s.discrete) return s.attenuation;
	if (s.pdf <= 0.0f) return Spectrum{0.0f}; // a direction that cannot be sampled adds nothing
	return s.attenuation * std::abs(glm::dot(s.direction, normal)) / s.pdf;
}
} // namespace

Spectrum Pathtracer::shade(RNG& rng, const Ray& ray, const Trace& hit) const {
	const Material& material = scene.materials[hit.material];
	Frame frame = Frame::from_normal(hit.normal);
	Vec3 out_dir = -glm::normalize(ray.dir); // towards the previous vertex

	// L_o = L_e + (one-sample estimate of the reflected radiance).
	Spectrum radiance = material.emitted(frame.to_local(out_dir));
	if (ray.depth >= settings.max_depth) return radiance; // no bounce left: emission only
	if (material.bsdf.is_black()) return radiance;         // nothing to sample (e.g. an area light)

	// Directions are drawn, and their density measured, at the point the next ray starts from: the
	// hit lifted to the side the path arrived on, which is where every direction a two-sided
	// Lambertian surface reflects into starts (spawn_ray). Drawn at the hit point itself, a light
	// sample and the ray traced for it would disagree near the light's edges: a ray could hit the
	// light where its light pdf said it misses it, and weigh 2 * albedo * L_e (handout §4.2).
	Trace from = hit;
	from.position = lifted(hit, out_dir);
	Incoming_Sample s = sample_incoming(rng, from, material.bsdf, out_dir);
	Spectrum weight = sample_weight(s, hit.normal);
	// A black weight ends the path. (NaN is not caught here on purpose: the film counts it.)
	if (weight == Spectrum{0.0f}) return radiance;

	// Russian roulette: continue with probability q and divide by q, so the expectation is
	// unchanged, but the second moment of the weight grows by 1 / q. q = min(1, max(largest albedo
	// component, largest weight component)):
	// - a weight of 1 or more is never cut. With task 6's mixture a BSDF-sampled direction weighs
	//   2 * albedo (its pdf is half the BSDF's); cut with q = albedo, its second moment grew by a
	//   factor 2 * albedo > 1 per bounce, and rare long paths became fireflies (handout §4.3);
	// - a small weight is cut no more often than the albedo says: a direction aimed at a light has a
	//   small weight because its pdf is large, and q = weight would kill almost all of them and
	//   multiply the few survivors by the inverse (fireflies, handout §4.3);
	// - a surface that keeps all the energy is never cut (white furnaces, clear glass).
	// max_depth bounds the length. settings.russian_roulette (--no-roulette) turns it off.
	if (settings.russian_roulette && ray.depth >= ROULETTE_DEPTH) {
		float q = std::min(1.0f, std::max(max_component(material.bsdf.albedo()), max_component(weight)));
		if (q < 1.0f) {
			if (!rng.coin_flip(q)) return radiance;
			weight /= q;
		}
	}

	return radiance + weight * trace(rng, spawn_ray(hit, s.direction, ray.depth + 1));
}
