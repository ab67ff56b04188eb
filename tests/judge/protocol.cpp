#include "protocol.h"

namespace protocol {

const char* kind_name(Kind kind) {
	switch (kind) {
	case Kind::generate_rays: return "generate_rays";
	case Kind::trace_pixels: return "trace_pixels";
	case Kind::render: return "render";
	case Kind::triangle_hits: return "triangle_hits";
	case Kind::sphere_hits: return "sphere_hits";
	case Kind::bbox_hits: return "bbox_hits";
	case Kind::bvh_triangles: return "bvh_triangles";
	case Kind::bvh_instances: return "bvh_instances";
	case Kind::bsdf_scatter: return "bsdf_scatter";
	case Kind::bsdf_evaluate: return "bsdf_evaluate";
	case Kind::bsdf_pdf: return "bsdf_pdf";
	case Kind::reflect: return "reflect";
	case Kind::refract: return "refract";
	case Kind::fresnel: return "fresnel";
	case Kind::sample_incoming: return "sample_incoming";
	case Kind::direction_to_uv: return "direction_to_uv";
	case Kind::uv_to_direction: return "uv_to_direction";
	case Kind::uniform_sphere: return "uniform_sphere";
	case Kind::image_sampler: return "image_sampler";
	case Kind::env_map: return "env_map";
	case Kind::env_constant: return "env_constant";
	case Kind::power_heuristic: return "power_heuristic";
	case Kind::estimate_direct: return "estimate_direct";
	}
	return "an unknown request";
}

const char* kind_functions(Kind kind) {
	switch (kind) {
	case Kind::generate_rays: return "Camera::generate_ray";
	case Kind::trace_pixels: return "Pathtracer::trace_pixel";
	case Kind::render: return "a render of the scene with your code";
	case Kind::triangle_hits: return "Triangle::hit";
	case Kind::sphere_hits: return "Sphere::hit";
	case Kind::bbox_hits: return "BBox::hit";
	case Kind::bvh_triangles: return "BVH::build and BVH::hit over triangles";
	case Kind::bvh_instances: return "BVH::build and BVH::hit over scene objects";
	case Kind::bsdf_scatter: return "the BSDF's scatter";
	case Kind::bsdf_evaluate: return "the BSDF's evaluate";
	case Kind::bsdf_pdf: return "the BSDF's pdf";
	case Kind::reflect: return "reflect";
	case Kind::refract: return "refract";
	case Kind::fresnel: return "fresnel";
	case Kind::sample_incoming: return "Pathtracer::sample_incoming";
	case Kind::direction_to_uv: return "direction_to_uv";
	case Kind::uv_to_direction: return "uv_to_direction";
	case Kind::uniform_sphere: return "Samplers::Sphere::Uniform";
	case Kind::image_sampler: return "Samplers::Sphere::Image";
	case Kind::env_map: return "Env_Map";
	case Kind::env_constant: return "Env_Constant (with your Samplers::Sphere::Uniform)";
	case Kind::power_heuristic: return "power_heuristic";
	case Kind::estimate_direct: return "Pathtracer::estimate_direct";
	}
	return "an unknown function";
}

} // namespace protocol
