// The BVH benchmark: builds the reference BVH<Triangle> (task 3's model solution) over an OBJ or a
// scene's meshes, and the framework's fast accelerator from it, and measures build time, memory, SAH
// cost, node visits and Mrays/s for primary, incoherent closest-hit and occlusion rays, on one thread
// and on all cores: the accelerator's queries, and task 3's BVH::hit alone. With Embree, the same for
// Embree on the same rays (rtcIntersect1, and making the record BVH::hit makes), and the ratios.
// Usage: bvh_bench [OBJ|SCENE] [--repeats N] [--rays N] [--film WxH]. See README.md.
#include "bench_geometry.h"
#include "bench_rays.h"
#include "bench_stats.h"
#include "bench_timing.h"
#include "accelerator.h"
#include "wide_bvh_queries.h"
#ifdef LAB_HAVE_EMBREE
#include "embree_bvh.h"
#endif

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>

namespace {

struct Options {
	std::string path = "scenes/meshes/stanford_bunny.obj";
	int repeats = 5;
	size_t secondary_rays = 500000;
	int width = 800, height = 600;
};

Options parse(int argc, char** argv) {
	Options options;
	for (int i = 1; i < argc; i++) {
		std::string arg = argv[i];
		bool has_value = i + 1 < argc;
		if (arg == "--repeats" && has_value) options.repeats = std::max(1, std::atoi(argv[++i]));
		else if (arg == "--rays" && has_value) options.secondary_rays = size_t(std::atoll(argv[++i]));
		else if (arg == "--film" && has_value) std::sscanf(argv[++i], "%dx%d", &options.width, &options.height);
		else if (arg == "-h" || arg == "--help") {
			std::printf("usage: bvh_bench [OBJ|SCENE] [--repeats N] [--rays N] [--film WxH]\n");
			std::exit(0);
		} else options.path = arg;
	}
	return options;
}

// The absolute part of the tolerance on t, per unit of the scene's size (count_differences).
constexpr float T_FLOOR = 1e-5f;

// Hit distances (INF_F for a miss) or occlusion flags (1 or INF_F) of one method on one ray set.
using Results = std::vector<float>;
struct Method {
	std::string name;
	std::function<float(const Ray&)> trace;
};

struct Measurement {
	std::vector<double> single, all; // Mrays/s of each repeat, on one thread and on all cores
	Results results;
};

// Traces `rays` with every method, `repeats` times, the methods taking turns within each repeat so
// that a change in the machine's load affects them alike. Checks that one thread and all cores
// give the same results: an ERROR, and `status` becomes 1, if not.
std::vector<Measurement> measure(const std::vector<Ray>& rays, const std::vector<Method>& methods, unsigned threads,
                                 int repeats, int& status) {
	std::vector<Measurement> out(methods.size());
	Results parallel(rays.size());
	for (int repeat = 0; repeat < repeats; repeat++)
		for (size_t m = 0; m < methods.size(); m++) {
			Measurement& me = out[m];
			me.results.resize(rays.size());
			double single = timed_serial_for(rays.size(), [&](size_t i) { me.results[i] = methods[m].trace(rays[i]); });
			double all =
				timed_parallel_for(rays.size(), threads, [&](size_t i) { parallel[i] = methods[m].trace(rays[i]); });
			me.single.push_back(rays.size() / single * 1e-6);
			me.all.push_back(rays.size() / all * 1e-6);
			if (parallel != me.results) {
				std::printf("ERROR: %s: results on %u threads differ from those on one thread\n",
				            methods[m].name.c_str(), threads);
				status = 1;
			}
		}
	return out;
}

// The median over repeats of the ratio a / b within each repeat.
double median_ratio(const std::vector<double>& a, const std::vector<double>& b) {
	std::vector<double> ratios;
	for (size_t i = 0; i < a.size(); i++) ratios.push_back(a[i] / b[i]);
	return median(ratios);
}

// How many results differ: hit against miss, or distances differing by more than 1e-4 relative
// plus `floor` (Embree's triangle test rounds differently, and ours accepts hits 1e-5 outside an
// edge). The floor is for rays that start on a surface and meet a neighbour very close by: their
// t differ by the rounding of the hit points, which grows with the scene's size, not with t.
size_t count_differences(const Results& a, const Results& b, float floor) {
	size_t differ = 0;
	for (size_t i = 0; i < a.size(); i++) {
		bool a_hit = a[i] < INF_F, b_hit = b[i] < INF_F;
		if (a_hit != b_hit || (a_hit && std::abs(a[i] - b[i]) > 1e-4f * std::abs(a[i]) + floor)) differ++;
	}
	return differ;
}

float hit_distance(const Trace& trace) {
	return trace.hit ? trace.distance : INF_F;
}

// A closest hit's distance, its whole record made (keep): every method pays for the record it
// returns, though the benchmark compares distances only.
float made_record_distance(const Trace& trace) {
	keep(trace);
	return hit_distance(trace);
}

// The measurement of the method named `name`.
const Measurement& of(const std::vector<Measurement>& results, const std::vector<Method>& methods,
                      const std::string& name) {
	for (size_t m = 0; m < methods.size(); m++)
		if (methods[m].name == name) return results[m];
	std::printf("ERROR: no method %s\n", name.c_str());
	std::exit(1);
}

float blocked(bool hit) {
	return hit ? 1.0f : INF_F;
}

} // namespace

int main(int argc, char** argv) {
	Options options = parse(argc, argv);
	unsigned threads = std::max(1u, std::thread::hardware_concurrency());
	Bench_Geometry geometry = load_bench_geometry(options.path);
	const size_t n = geometry.triangles.size();
	std::printf("%s: %zu triangles; %d repeats, medians; all cores = %u threads\n", options.path.c_str(), n,
	            options.repeats, threads);

	// Build (single-threaded, CPU time), as often as the rays are traced: task 3's tree, then the
	// framework's accelerator from it.
	BVH<Triangle> bvh;
	Accelerator<Triangle> accelerator;
	std::vector<double> tree_builds, builds;
	for (int repeat = 0; repeat < options.repeats; repeat++) {
		std::vector<Triangle> copy = geometry.triangles;
		double start = process_cpu_seconds();
		bvh.build(std::move(copy), 4); // Tri_Mesh's leaf size
		double tree = process_cpu_seconds();
		accelerator = Accelerator<Triangle>(bvh);
		tree_builds.push_back(tree - start);
		builds.push_back(process_cpu_seconds() - start);
	}

	std::vector<Ray> primary = primary_rays(geometry.camera, options.width, options.height);
	std::vector<float> primary_hits;
	for (const Ray& ray : primary) primary_hits.push_back(hit_distance(accelerator.hit(bvh, ray)));
	Ray_Sets rays = make_ray_sets(geometry, std::move(primary), primary_hits, options.secondary_rays);
	const std::vector<Ray>* sets[3] = {&rays.primary, &rays.incoherent, &rays.occlusion};
	const char* names[3] = {"primary", "incoherent", "occlusion"};

	// Methods per ray set. "ours" is the accelerator (any hit for occlusion rays), "task3" task 3's
	// BVH::hit alone (occlusion: the closest hit on the segment); "closest" the accelerator's closest
	// hit on the occlusion segments, to show what stopping at the first hit buys.
	auto closest = [&](const Ray& ray) { return made_record_distance(accelerator.hit(bvh, ray)); };
	auto task3 = [&](const Ray& ray) { return made_record_distance(bvh.hit(ray)); };
	std::vector<Method> methods[3] = {
		{{"ours", closest}, {"task3", task3}},
		{{"ours", closest}, {"task3", task3}},
		{{"ours", [&](const Ray& ray) { return blocked(accelerator.occluded(bvh, ray)); }},
		 {"task3", [&](const Ray& ray) { return blocked(task3(ray) < INF_F); }},
		 {"closest", [&](const Ray& ray) { return blocked(closest(ray) < INF_F); }}},
	};
#ifdef LAB_HAVE_EMBREE
	std::vector<double> embree_builds;
	std::unique_ptr<Embree_BVH> embree;
	for (int repeat = 0; repeat < options.repeats; repeat++) {
		embree.reset();
		embree = std::make_unique<Embree_BVH>(geometry.triangles);
		embree_builds.push_back(embree->build_seconds);
	}
	// "embree": rtcIntersect1 or rtcOccluded1; "embree record": the record BVH::hit returns, too.
	for (int s = 0; s < 2; s++) {
		methods[s].push_back({"embree", [&](const Ray& ray) { return embree->closest_hit(ray); }});
		methods[s].push_back(
			{"embree record", [&](const Ray& ray) { return made_record_distance(embree->hit(ray, geometry.triangles)); }});
	}
	methods[2].push_back({"embree", [&](const Ray& ray) { return blocked(embree->occluded(ray)); }});
#endif
	int status = 0;
	std::vector<Measurement> results[3];
	for (int s = 0; s < 3; s++) results[s] = measure(*sets[s], methods[s], threads, options.repeats, status);
	auto result = [&](int s, const char* name) -> const Measurement& { return of(results[s], methods[s], name); };

	std::printf("\ntask 3's BVH (reference/task3_bvh.cpp): build %.0f ms, %.1f bytes/triangle, SAH cost %.2f, %zu nodes\n",
	            median(tree_builds) * 1e3, double(bvh_bytes(bvh)) / n, sah_cost(bvh), bvh.nodes.size());
	std::printf("accelerator (framework/accel/), made from it: %.0f ms more, %.1f bytes/triangle more; "
	            "%d lanes per node test (LAB_VECTOR_WIDTH=4 asks for 4)\n",
	            (median(builds) - median(tree_builds)) * 1e3, double(accelerator.bytes()) / n, chosen_queries().lanes);
	std::printf("per ray, nodes overlapped up to the closest hit (ideal front-to-back) / triangles in their leaves:\n");
	for (int s = 0; s < 3; s++) {
		std::vector<float> hits = results[s][0].results; // occlusion: count the whole segment
		if (s == 2) std::fill(hits.begin(), hits.end(), INF_F);
		Visit_Counts visits = visit_counts(bvh, *sets[s], hits);
		std::printf("  %-10s %6.1f / %5.1f  (%zu rays)\n", names[s], visits.nodes, visits.triangles, sets[s]->size());
	}

	const float floor = T_FLOOR * glm::length(geometry.bounds.max - geometry.bounds.min);
	for (int s = 0; s < 3; s++) {
		size_t differ = count_differences(result(s, "task3").results, result(s, "ours").results, 0.0f);
		if (differ > 0) {
			std::printf("ERROR: %s rays: task 3's BVH::hit and the accelerator disagree on %zu\n", names[s], differ);
			status = 1;
		}
	}
	const Measurement &any_hit = result(2, "ours"), &closest_hit = result(2, "closest");
	std::printf("occlusion rays, ours: any hit %.2f Mrays/s, closest hit on the segment %.2f: "
	            "stopping at the first hit is %.2fx as fast (1 thread)\n",
	            median(any_hit.single), median(closest_hit.single), median_ratio(any_hit.single, closest_hit.single));
	if (any_hit.results != closest_hit.results) {
		std::printf("ERROR: the accelerator's any hit and closest hit disagree on whether an occlusion ray is blocked\n");
		status = 1;
	}
#ifdef LAB_HAVE_EMBREE
	std::printf("Embree (RTC_BUILD_QUALITY_HIGH, 1 build thread): build %.0f ms, %.1f bytes/triangle\n",
	            median(embree_builds) * 1e3, double(embree->bytes) / n);
	std::printf("build time ours (tree and accelerator) / Embree: %.2f\n\n", median_ratio(builds, embree_builds));
	// The comparison: closest hits against Embree making the same record, occlusion against rtcOccluded1.
	auto embree_like = [](int s) { return s < 2 ? "embree record" : "embree"; };
	std::printf("Mrays/s; Embree: closest hit with BVH::hit's record (the hit point, the vertex normals interpolated at\n"
	            "its u, v), occlusion rtcOccluded1; task 3: BVH::hit alone (occlusion: its closest hit on the segment);\n"
	            "ratios to Embree: ours / Embree (ours/E) and task 3 / Embree (t3/E)\n");
	std::printf("%-11s %-40s   %-40s\n", "", "1 thread (CPU time)", "all cores (wall time)");
	std::printf("%-11s %8s %7s %7s %7s %6s   %8s %7s %7s %7s %6s   %s\n", "", "ours", "task 3", "Embree", "ours/E",
	            "t3/E", "ours", "task 3", "Embree", "ours/E", "t3/E", "results differing");
	for (int s = 0; s < 3; s++) {
		const Measurement &a = result(s, "ours"), &t = result(s, "task3"), &e = result(s, embree_like(s));
		size_t differ = count_differences(a.results, e.results, floor);
		std::printf("%-11s %8.2f %7.2f %7.2f %7.2f %6.2f   %8.2f %7.2f %7.2f %7.2f %6.2f   %zu of %zu\n", names[s],
		            median(a.single), median(t.single), median(e.single), median_ratio(a.single, e.single),
		            median_ratio(t.single, e.single), median(a.all), median(t.all), median(e.all),
		            median_ratio(a.all, e.all), median_ratio(t.all, e.all), differ, sets[s]->size());
		if (differ > sets[s]->size() / 1000) {
			std::printf("ERROR: more than 0.1%% of the %s rays differ between our BVH and Embree\n", names[s]);
			status = 1;
		}
		if (s < 2 && e.results != result(s, "embree").results) {
			std::printf("ERROR: Embree's %s hits differ with and without the record\n", names[s]);
			status = 1;
		}
	}
	std::printf("(ratios: median over the repeats of the ratio within a repeat)\n");
	std::printf("for information, Embree's rtcIntersect1 alone (t, u, v and the triangle, no record), 1 thread:");
	for (int s = 0; s < 2; s++) {
		const Measurement &a = result(s, "ours"), &e = result(s, "embree");
		std::printf(" %s %.2f Mrays/s, ours / it %.2f%s", names[s], median(e.single), median_ratio(a.single, e.single),
		            s == 0 ? ";" : "\n");
	}
#else
	std::printf("\n(Embree not found at configure time: install libembree-dev, or run ./lab bench, to compare)\n\n");
	std::printf("%-11s %21s   %21s\n", "Mrays/s", "1 thread: ours task 3", "all cores: ours task 3");
	for (int s = 0; s < 3; s++) {
		const Measurement &a = result(s, "ours"), &t = result(s, "task3");
		std::printf("%-11s %14.2f %6.2f   %15.2f %6.2f\n", names[s], median(a.single), median(t.single), median(a.all),
		            median(t.all));
	}
#endif
	return status;
}
