#include "furnace_scenes.h"

#include <algorithm>
#include <cmath>

namespace {
Scene one_sphere(const Material& material, const Furnace_Options& options, Camera camera) {
	Scene scene;
	scene.camera = camera;
	scene.materials.push_back(material);
	scene.material_names.push_back("furnace material");
	float scale = options.inward_normals ? -1.0f : 1.0f;
	Mat4 to_world = Mat4(scale); // uniform scale (+1 or -1) ...
	to_world[3] = Vec4(options.center, 1.0f); // ... then translation
	scene.objects.emplace_back(Sphere{options.radius}, to_world, 0u, 0u);
	if (options.has_environment) scene.environment = Env_Constant{options.environment};
	scene.commit();
	return scene;
}
} // namespace

Scene sphere_seen_from_outside(const Material& material, const Furnace_Options& options, float distance,
                               float v_fov) {
	Vec3 eye = options.center + Vec3{0.0f, 0.0f, distance};
	return one_sphere(material, options, Camera::look_at(eye, options.center, Vec3{0, 1, 0}, v_fov, 1.0f));
}

Scene sphere_seen_from_inside(const Material& material, const Furnace_Options& options, Vec3 eye, Vec3 target,
                              float v_fov) {
	Camera camera = Camera::look_at(options.center + eye, options.center + target, Vec3{0, 1, 0}, v_fov, 1.0f);
	return one_sphere(material, options, camera);
}

Pixel_Coverage::Pixel_Coverage(float radius, float distance, float v_fov, uint32_t width_, uint32_t height_)
	: width(width_), height(height_) {
	// The sphere subtends the cone of half-angle asin(radius / distance) around the view axis.
	double half_angle = std::asin(double(radius) / double(distance));
	disc_radius = std::tan(half_angle);
	half_h = std::tan(0.5 * double(v_fov) * M_PI / 180.0);
	half_w = half_h * double(width) / double(height);
}

Pixel_Coverage::Kind Pixel_Coverage::operator()(uint32_t x, uint32_t y) const {
	// The pixel's rectangle on the image plane, [x0, x1] x [y0, y1] (the sign of y is irrelevant:
	// the disc is centred).
	double x0 = (2.0 * x / width - 1.0) * half_w, x1 = (2.0 * (x + 1) / width - 1.0) * half_w;
	double y0 = (2.0 * y / height - 1.0) * half_h, y1 = (2.0 * (y + 1) / height - 1.0) * half_h;
	double far_x = std::max(std::abs(x0), std::abs(x1)), far_y = std::max(std::abs(y0), std::abs(y1));
	double near_x = (x0 <= 0.0 && x1 >= 0.0) ? 0.0 : std::min(std::abs(x0), std::abs(x1));
	double near_y = (y0 <= 0.0 && y1 >= 0.0) ? 0.0 : std::min(std::abs(y0), std::abs(y1));
	// A relative margin of 1e-4 keeps float rounding of the camera rays on the right side.
	if (std::hypot(far_x, far_y) < disc_radius * (1.0 - 1e-4)) return sphere;
	if (std::hypot(near_x, near_y) > disc_radius * (1.0 + 1e-4)) return background;
	return silhouette;
}

const char* to_string(Pixel_Coverage::Kind kind) {
	switch (kind) {
	case Pixel_Coverage::sphere: return "pixels showing only the sphere";
	case Pixel_Coverage::background: return "pixels showing only the environment";
	default: return "silhouette pixels";
	}
}

Vec3 random_point(RNG& rng, float lo, float hi) {
	return lo + (hi - lo) * Vec3{rng.unit(), rng.unit(), rng.unit()};
}

Spectrum random_colour(RNG& rng, float lo, float hi) {
	return Spectrum(random_point(rng, lo, hi));
}

Vec3 random_unit_vector(RNG& rng) {
	// Uniform on the sphere: z uniform in [-1, 1] (Archimedes), azimuth uniform.
	float z = 2.0f * rng.unit() - 1.0f, phi = 2.0f * float(M_PI) * rng.unit();
	float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
	return Vec3{r * std::cos(phi), r * std::sin(phi), z};
}

Outside_View random_outside_view(RNG& rng, Furnace_Options options) {
	Outside_View view;
	options.center = random_point(rng, -10.0f, 10.0f);
	options.radius = 0.5f + 1.5f * rng.unit();
	view.options = options;
	view.distance = options.radius * (2.5f + 3.5f * rng.unit());
	double disc_radius = std::tan(std::asin(double(options.radius) / double(view.distance)));
	double half_height = disc_radius / (0.45 + 0.35 * double(rng.unit()));
	view.v_fov = float(2.0 * std::atan(half_height) * 180.0 / M_PI);
	return view;
}

Inside_View random_inside_view(RNG& rng, float max_eye_distance) {
	Inside_View view;
	view.eye = max_eye_distance * std::cbrt(rng.unit()) * random_unit_vector(rng); // uniform in the ball
	Vec3 look;
	do {
		look = random_unit_vector(rng);
	} while (std::abs(look.y) > 0.9f); // look_at needs a direction that is not along its up vector
	view.target = view.eye + look;
	view.v_fov = 40.0f + 50.0f * rng.unit();
	return view;
}

Scene with_probe_sphere(const Scene& furnace, RNG* secret) {
	const Instance& first = furnace.bvh.primitives.at(0);
	Vec3 centre = Vec3(first.to_world[3]);
	float radius = std::get<Sphere>(first.shape).radius * std::abs(first.to_world[0][0]);
	const Mat4& camera = furnace.camera.camera_to_world;
	Vec3 right = Vec3(camera[0]), up = Vec3(camera[1]), back = Vec3(camera[2]), eye = Vec3(camera[3]);
	auto jitter = [&](float value) { return secret ? value * (0.85f + 0.3f * secret->unit()) : value; };
	Spectrum albedo = secret ? random_colour(*secret, 0.2f, 0.9f) : Spectrum{0.3f, 0.6f, 0.9f};
	Vec3 probe_centre;
	float probe_radius;
	if (glm::length(eye - centre) > radius) {
		// Seen from outside: up and to the right of the sphere, a little towards the camera, almost
		// touching it, where the camera sees both and each hides part of the sky from the other.
		probe_centre = centre + radius * (jitter(1.3f) * right + jitter(0.4f) * up + jitter(0.5f) * back);
		probe_radius = 0.45f * radius;
	} else {
		// Seen from inside: in front of the camera, casting its shadow on the walls it sees.
		probe_centre = eye - jitter(0.3f) * radius * back;
		probe_radius = 0.12f * radius;
	}
	Scene scene;
	scene.camera = furnace.camera;
	scene.settings = furnace.settings;
	scene.materials = furnace.materials;
	scene.material_names = furnace.material_names;
	scene.materials.push_back(diffuse_material(albedo));
	scene.material_names.push_back("probe material");
	scene.environment = furnace.environment;
	scene.objects.emplace_back(first.shape, first.to_world, first.material, 0u);
	Mat4 to_world = Mat4(1.0f);
	to_world[3] = Vec4(probe_centre, 1.0f);
	scene.objects.emplace_back(Sphere{probe_radius}, to_world, uint32_t(scene.materials.size() - 1), 1u);
	scene.commit();
	return scene;
}
