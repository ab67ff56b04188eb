#include "furnace_scenes.h"
#include "render.h"

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

Film render_square(const Scene& scene, uint32_t size, uint32_t spp, uint32_t max_depth, uint64_t seed) {
	Render_Settings settings;
	settings.width = settings.height = size;
	settings.samples = spp;
	settings.max_depth = max_depth;
	settings.seed = seed;
	return render(Pathtracer(scene, settings));
}
