#include "embree_bvh.h"
#include "bench_timing.h"

#include <embree3/rtcore.h>

#include <atomic>
#include <stdexcept>

namespace {
std::atomic<long long> device_bytes{0};

bool count_memory(void*, ssize_t bytes, bool) {
	device_bytes += bytes;
	return true;
}
} // namespace

Embree_BVH::Embree_BVH(const std::vector<Triangle>& triangles) {
	RTCDevice device = rtcNewDevice("threads=1");
	if (!device) throw std::runtime_error("Embree: rtcNewDevice failed");
	device_ = device;
	rtcSetDeviceMemoryMonitorFunction(device, count_memory, nullptr);
	device_bytes = 0;

	RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
	auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
	                                                             RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * triangles.size()));
	auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
	                                                               3 * sizeof(unsigned), triangles.size()));
	for (size_t i = 0; i < triangles.size(); i++) {
		const Tri_Mesh_Vert* corners[3] = {&triangles[i].v0, &triangles[i].v1, &triangles[i].v2};
		for (int c = 0; c < 3; c++) {
			for (int axis = 0; axis < 3; axis++) vertices[9 * i + 3 * c + axis] = corners[c]->position[axis];
			indices[3 * i + c] = unsigned(3 * i + c);
		}
	}
	rtcCommitGeometry(geometry);

	RTCScene scene = rtcNewScene(device);
	scene_ = scene;
	rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
	rtcAttachGeometry(scene, geometry);
	rtcReleaseGeometry(geometry);
	double start = process_cpu_seconds();
	rtcCommitScene(scene);
	build_seconds = process_cpu_seconds() - start;
	bytes = size_t(device_bytes.load());
}

Embree_BVH::~Embree_BVH() {
	rtcReleaseScene(static_cast<RTCScene>(scene_));
	rtcReleaseDevice(static_cast<RTCDevice>(device_));
}

namespace {
RTCRay embree_ray(const Ray& ray) {
	RTCRay r{};
	r.org_x = ray.point.x, r.org_y = ray.point.y, r.org_z = ray.point.z;
	r.dir_x = ray.dir.x, r.dir_y = ray.dir.y, r.dir_z = ray.dir.z;
	r.tnear = ray.dist_bounds.x;
	r.tfar = ray.dist_bounds.y;
	r.mask = ~0u;
	r.flags = 0;
	return r;
}

// rtcIntersect1: the closest hit; hit.geomID is RTC_INVALID_GEOMETRY_ID for a miss.
RTCRayHit intersect(void* scene, const Ray& ray) {
	RTCIntersectContext context;
	rtcInitIntersectContext(&context);
	RTCRayHit ray_hit{};
	ray_hit.ray = embree_ray(ray);
	ray_hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
	rtcIntersect1(static_cast<RTCScene>(scene), &context, &ray_hit);
	return ray_hit;
}
} // namespace

float Embree_BVH::closest_hit(const Ray& ray) const {
	RTCRayHit ray_hit = intersect(scene_, ray);
	return ray_hit.hit.geomID == RTC_INVALID_GEOMETRY_ID ? INF_F : ray_hit.ray.tfar;
}

Trace Embree_BVH::hit(const Ray& ray, const std::vector<Triangle>& triangles) const {
	RTCRayHit ray_hit = intersect(scene_, ray);
	Trace trace;
	trace.origin = ray.point;
	if (ray_hit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return trace;
	const Triangle& tri = triangles[ray_hit.hit.primID];
	float t = ray_hit.ray.tfar, u = ray_hit.hit.u, v = ray_hit.hit.v; // Embree's barycentrics are ours
	trace.hit = true;
	trace.distance = t;
	trace.position = ray.at(t);
	trace.normal = glm::normalize((1.0f - u - v) * tri.v0.normal + u * tri.v1.normal + v * tri.v2.normal);
	return trace;
}

bool Embree_BVH::occluded(const Ray& ray) const {
	RTCIntersectContext context;
	rtcInitIntersectContext(&context);
	RTCRay r = embree_ray(ray);
	rtcOccluded1(static_cast<RTCScene>(scene_), &context, &r);
	return r.tfar < 0.0f; // Embree sets tfar to -inf when something is hit
}
