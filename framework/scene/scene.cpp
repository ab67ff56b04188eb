#include "scene.h"
#include "render_observer.h"

void Scene::commit() {
	area_lights.build(objects, materials);
	// A handful of objects gets no hierarchy: one leaf holding them all, so a ray tests them in turn
	// after a single box test. More objects get a leaf each.
	size_t leaf_size = objects.size() <= HANDFUL_OF_OBJECTS ? objects.size() : 1;
	bvh.build(std::move(objects), leaf_size);
	accelerator = Accelerator<Instance>(bvh);
	objects.clear();
}

bool Scene::occluded(const Ray& ray) const {
	bool blocked = accelerator.occluded(bvh, ray);
	report<Shadow_Ray_Tested>(blocked, ray); // the ray lifecycle (--follow-pixel) shows shadow rays
	return blocked;
}

Spectrum Scene::environment_radiance(Vec3 dir) const {
	if (!environment) return Spectrum{0.0f};
	return std::visit([&](const auto& env) { return env.evaluate(dir); }, *environment);
}
