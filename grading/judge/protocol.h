#pragma once
// The judge-subject protocol: how a grader (the *judge*) asks a student's code (the *subject*, a
// separate sandboxed process, grading/judge/subject_main.cpp) to run a task function on inputs the
// judge chose, and gets the raw outputs back to check them itself.
//
// Transport: the subject reads requests from file descriptor 3 and writes answers to descriptor 4
// (its stdout and stderr are only logged, never read for a verdict). Every message is a header
// followed by `length` bytes of payload:
//
//   request: u32 MAGIC, u32 kind, u32 sequence, u64 length, payload
//   answer:  u32 MAGIC, u32 kind, u32 sequence, u32 status, u64 length, payload
//
// An answer repeats its request's kind and sequence number; anything else is an answer out of turn
// and ends the subject. status OK: the payload is the request's Answer; status THREW: the payload
// is the text of the exception the task function threw.
//
// One request asks back: BVH_Instances gives the subject only the objects' boxes, and the subject's
// Instance::hit asks the judge for each object it tests (status QUESTION on the answer channel, an
// Object_Question as payload), which replies on the request channel (a message with the request's
// header, an encoded Trace as payload) before the subject goes on. So the judge counts the objects a
// traversal tests itself, and a subject cannot find a hit without asking. Numbers are little-endian, floats are IEEE
// binary32 bit patterns, a vector is a u64 count and its elements, a string a u64 length and bytes.
// The headers and the encoding of each type are in wire.h, which both sides use. Each request's `fits` says whether an answer has the shape
// its inputs call for (one result per query): one that does not is malformed.
//
// Requests are batched: one request per student function (or per render) with every input of a
// test case, never one request per ray. Each request below names the task function it runs, its
// inputs and its Answer. Functions that sample take one generator (RNG_State) for the whole batch
// and draw from it in the order of the inputs, as a loop over the inputs would.
#include "adaptive_sampling.h"
#include "material.h"
#include "pathtracer.h"
#include "estimator.h"
#include "film.h"
#include "rng_state.h"
#include "scene.h"

#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

namespace protocol {

constexpr uint32_t MAGIC = 0x4a4c5450; // "PTLJ"
constexpr uint64_t MAX_PAYLOAD = uint64_t(1) << 30; // larger messages are malformed
constexpr int REQUEST_FD = 3, ANSWER_FD = 4;

enum class Status : uint32_t { OK = 0, THREW = 1, QUESTION = 2 };
constexpr uint64_t MAX_QUESTION = 1024; // bytes; a longer question is malformed

// A request's number on the wire: each request's KIND.
enum class Kind : uint32_t {};
const char* kind_name(Kind kind);
// The student functions a request runs, in the handouts' words (for messages).
const char* kind_functions(Kind kind);

// ---- Task 1 ----

// Camera::generate_ray(film_uv) for each query.
struct Generate_Rays {
	static constexpr Kind KIND{1};
	static constexpr const char* NAME = "generate_rays";
	static constexpr const char* FUNCTIONS = "Camera::generate_ray";
	struct Query {
		Camera camera;
		Vec2 film_uv;
		template<class A> void fields(A& a) { a(camera, film_uv); }
	};
	std::vector<Query> queries;
	template<class A> void fields(A& a) { a(queries); }
	using Answer = std::vector<Ray>;
	bool fits(const Answer& a) const { return a.size() == queries.size(); }
};

// Pathtracer(scene, settings, view, estimator).trace_pixel(x, y, rng) for each sample, each with its
// own generator.
struct Trace_Pixels {
	static constexpr Kind KIND{2};
	static constexpr const char* NAME = "trace_pixels";
	static constexpr const char* FUNCTIONS = "Pathtracer::trace_pixel";
	struct Sample {
		uint32_t x = 0, y = 0;
		RNG_State rng;
		template<class A> void fields(A& a) { a(x, y, rng); }
	};
	Scene scene;
	Render_Settings settings;
	Estimator_Choice estimator;
	View view = View::path;
	std::vector<Sample> samples;
	template<class A> void fields(A& a) { a(scene, settings, estimator, view, samples); }
	using Answer = std::vector<Spectrum>;
	bool fits(const Answer& a) const { return a.size() == samples.size(); }
};

// render(Pathtracer(scene, settings, view, estimator)) on `threads` threads: the whole film, every
// pixel's samples drawn by the framework as `./lab render` draws them.
struct Render {
	static constexpr Kind KIND{3};
	static constexpr const char* NAME = "render";
	static constexpr const char* FUNCTIONS = "a render of the scene with your code";
	Scene scene;
	Render_Settings settings;
	Estimator_Choice estimator;
	View view = View::path;
	uint32_t threads = 1;
	template<class A> void fields(A& a) { a(scene, settings, estimator, view, threads); }
	using Answer = Film;
	bool fits(const Answer& a) const { return a.w == settings.width && a.h == settings.height; }
};

// ---- Task 2 ----

// Triangle::hit(ray) for each pair.
struct Triangle_Hits {
	static constexpr Kind KIND{4};
	static constexpr const char* NAME = "triangle_hits";
	static constexpr const char* FUNCTIONS = "Triangle::hit";
	struct Query {
		Triangle triangle;
		Ray ray;
		template<class A> void fields(A& a) { a(triangle, ray); }
	};
	std::vector<Query> queries;
	template<class A> void fields(A& a) { a(queries); }
	using Answer = std::vector<Trace>;
	bool fits(const Answer& a) const { return a.size() == queries.size(); }
};

// Sphere::hit(ray) for each pair.
struct Sphere_Hits {
	static constexpr Kind KIND{5};
	static constexpr const char* NAME = "sphere_hits";
	static constexpr const char* FUNCTIONS = "Sphere::hit";
	struct Query {
		Sphere sphere;
		Ray ray;
		template<class A> void fields(A& a) { a(sphere, ray); }
	};
	std::vector<Query> queries;
	template<class A> void fields(A& a) { a(queries); }
	using Answer = std::vector<Trace>;
	bool fits(const Answer& a) const { return a.size() == queries.size(); }
};

// ---- Task 3 ----

// BBox::hit(ray, times) for each query: whether it hit, and `times` as the call left it.
struct BBox_Hits {
	static constexpr Kind KIND{6};
	static constexpr const char* NAME = "bbox_hits";
	static constexpr const char* FUNCTIONS = "BBox::hit";
	struct Query {
		BBox box;
		Ray ray;
		Vec2 times;
		template<class A> void fields(A& a) { a(box, ray, times); }
	};
	struct Result {
		bool hit = false;
		Vec2 times;
		template<class A> void fields(A& a) { a(hit, times); }
	};
	std::vector<Query> queries;
	template<class A> void fields(A& a) { a(queries); }
	using Answer = std::vector<Result>;
	bool fits(const Answer& a) const { return a.size() == queries.size(); }
};

// A built BVH's nodes (bvh.h), as the student's BVH::build left them.
struct Tree {
	struct Node {
		BBox bbox;
		uint64_t start = 0, size = 0, l = 0, r = 0;
		template<class A> void fields(A& a) { a(bbox, start, size, l, r); }
	};
	std::vector<Node> nodes;
	uint64_t root_idx = 0;
	template<class A> void fields(A& a) { a(nodes, root_idx); }
};

// BVH<Triangle>(triangles, max_leaf_size), then bvh.hit(ray) for each ray.
struct BVH_Triangles {
	static constexpr Kind KIND{7};
	static constexpr const char* NAME = "bvh_triangles";
	static constexpr const char* FUNCTIONS = "BVH::build and BVH::hit over triangles";
	std::vector<Triangle> triangles;
	uint64_t max_leaf_size = 1;
	std::vector<Ray> rays;
	template<class A> void fields(A& a) { a(triangles, max_leaf_size, rays); }
	struct Answer {
		Tree tree;
		std::vector<Triangle> primitives; // bvh.primitives: the triangles in the build's order
		std::vector<Trace> hits;
		template<class A> void fields(A& a) { a(tree, primitives, hits); }
	};
	bool fits(const Answer& a) const {
		return a.primitives.size() == triangles.size() && a.hits.size() == rays.size();
	}
};

// BVH<Instance>(objects, max_leaf_size), then bvh.hit(ray) for each ray, over objects of which the
// subject knows only their boxes: boxes[i] is the world box of the object with Instance::index i.
// Each Instance::hit asks the judge (an Object_Question, see the top), which counts them.
struct BVH_Instances {
	static constexpr Kind KIND{8};
	static constexpr const char* NAME = "bvh_instances";
	static constexpr const char* FUNCTIONS = "BVH::build and BVH::hit over scene objects";
	std::vector<BBox> boxes;
	uint64_t max_leaf_size = 1;
	std::vector<Ray> rays;
	template<class A> void fields(A& a) { a(boxes, max_leaf_size, rays); }
	struct Answer {
		Tree tree;
		std::vector<uint32_t> order; // Instance::index of bvh.primitives[i]
		std::vector<Trace> hits;
		template<class A> void fields(A& a) { a(tree, order, hits); }
	};
	bool fits(const Answer& a) const {
		return a.order.size() == boxes.size() && a.hits.size() == rays.size();
	}
};

// The subject's Instance::hit(ray) of object `object` during BVH_Instances; the judge replies with
// the Trace.
struct Object_Question {
	uint32_t object = 0;
	Ray ray;
	template<class A> void fields(A& a) { a(object, ray); }
};

// ---- Tasks 4 and 5 ----

// bsdf.scatter(rng, out_dir) for each direction, from one generator.
struct BSDF_Scatter {
	static constexpr Kind KIND{9};
	static constexpr const char* NAME = "bsdf_scatter";
	static constexpr const char* FUNCTIONS = "the BSDF's scatter";
	BSDF bsdf;
	std::vector<Vec3> out_dirs;
	RNG_State rng;
	template<class A> void fields(A& a) { a(bsdf, out_dirs, rng); }
	using Answer = std::vector<Scatter>;
	bool fits(const Answer& a) const { return a.size() == out_dirs.size(); }
};

struct Direction_Pair {
	Vec3 out_dir, in_dir;
	template<class A> void fields(A& a) { a(out_dir, in_dir); }
};

// bsdf.evaluate(out_dir, in_dir) for each pair.
struct BSDF_Evaluate {
	static constexpr Kind KIND{10};
	static constexpr const char* NAME = "bsdf_evaluate";
	static constexpr const char* FUNCTIONS = "the BSDF's evaluate";
	BSDF bsdf;
	std::vector<Direction_Pair> pairs;
	template<class A> void fields(A& a) { a(bsdf, pairs); }
	using Answer = std::vector<Spectrum>;
	bool fits(const Answer& a) const { return a.size() == pairs.size(); }
};

// bsdf.pdf(out_dir, in_dir) for each pair.
struct BSDF_Pdf {
	static constexpr Kind KIND{11};
	static constexpr const char* NAME = "bsdf_pdf";
	static constexpr const char* FUNCTIONS = "the BSDF's pdf";
	BSDF bsdf;
	std::vector<Direction_Pair> pairs;
	template<class A> void fields(A& a) { a(bsdf, pairs); }
	using Answer = std::vector<float>;
	bool fits(const Answer& a) const { return a.size() == pairs.size(); }
};

// reflect(dir) for each direction.
struct Reflect {
	static constexpr Kind KIND{12};
	static constexpr const char* NAME = "reflect";
	static constexpr const char* FUNCTIONS = "reflect";
	std::vector<Vec3> dirs;
	template<class A> void fields(A& a) { a(dirs); }
	using Answer = std::vector<Vec3>;
	bool fits(const Answer& a) const { return a.size() == dirs.size(); }
};

// refract(out_dir, index_of_refraction, was_internal) for each query.
struct Refract {
	static constexpr Kind KIND{13};
	static constexpr const char* NAME = "refract";
	static constexpr const char* FUNCTIONS = "refract";
	struct Query {
		Vec3 out_dir;
		float index_of_refraction = 1.0f;
		template<class A> void fields(A& a) { a(out_dir, index_of_refraction); }
	};
	struct Result {
		Vec3 in_dir;
		bool was_internal = false;
		template<class A> void fields(A& a) { a(in_dir, was_internal); }
	};
	std::vector<Query> queries;
	template<class A> void fields(A& a) { a(queries); }
	using Answer = std::vector<Result>;
	bool fits(const Answer& a) const { return a.size() == queries.size(); }
};

// fresnel(cos_theta, index_of_refraction) for each query.
struct Fresnel {
	static constexpr Kind KIND{14};
	static constexpr const char* NAME = "fresnel";
	static constexpr const char* FUNCTIONS = "fresnel";
	struct Query {
		float cos_theta = 1.0f, index_of_refraction = 1.0f;
		template<class A> void fields(A& a) { a(cos_theta, index_of_refraction); }
	};
	std::vector<Query> queries;
	template<class A> void fields(A& a) { a(queries); }
	using Answer = std::vector<float>;
	bool fits(const Answer& a) const { return a.size() == queries.size(); }
};

// ---- Task 6 ----

// Pathtracer(scene, settings).sample_incoming(rng, hit, bsdf, out_dir) for each query, from one
// generator.
struct Sample_Incoming {
	static constexpr Kind KIND{15};
	static constexpr const char* NAME = "sample_incoming";
	static constexpr const char* FUNCTIONS = "Pathtracer::sample_incoming";
	struct Query {
		Trace hit;
		BSDF bsdf;
		Vec3 out_dir;
		template<class A> void fields(A& a) { a(hit, bsdf, out_dir); }
	};
	Scene scene;
	Render_Settings settings;
	std::vector<Query> queries;
	RNG_State rng;
	template<class A> void fields(A& a) { a(scene, settings, queries, rng); }
	using Answer = std::vector<Incoming_Sample>;
	bool fits(const Answer& a) const { return a.size() == queries.size(); }
};

// ---- Task 6's optional extension: next-event estimation (handout §6.5) ----

// power_heuristic(pdf_f, pdf_g) for each pair (x: pdf_f, y: pdf_g).
struct Power_Heuristic {
	static constexpr Kind KIND{22};
	static constexpr const char* NAME = "power_heuristic";
	static constexpr const char* FUNCTIONS = "power_heuristic";
	std::vector<Vec2> pairs;
	template<class A> void fields(A& a) { a(pairs); }
	using Answer = std::vector<float>;
	bool fits(const Answer& a) const { return a.size() == pairs.size(); }
};

// Pathtracer(scene, settings).estimate_direct(rng, hit, bsdf, out_dir) for each query, from one
// generator. (Renders by the NEE integrator are Trace_Pixels and Render with estimator.integrator.)
struct Estimate_Direct {
	static constexpr Kind KIND{23};
	static constexpr const char* NAME = "estimate_direct";
	static constexpr const char* FUNCTIONS = "Pathtracer::estimate_direct";
	Scene scene;
	Render_Settings settings;
	std::vector<Sample_Incoming::Query> queries;
	RNG_State rng;
	template<class A> void fields(A& a) { a(scene, settings, queries, rng); }
	using Answer = std::vector<Spectrum>;
	bool fits(const Answer& a) const { return a.size() == queries.size(); }
};

// ---- Task 7 ----

// direction_to_uv(dir) for each direction.
struct Direction_To_UV {
	static constexpr Kind KIND{16};
	static constexpr const char* NAME = "direction_to_uv";
	static constexpr const char* FUNCTIONS = "direction_to_uv";
	std::vector<Vec3> dirs;
	template<class A> void fields(A& a) { a(dirs); }
	using Answer = std::vector<Vec2>;
	bool fits(const Answer& a) const { return a.size() == dirs.size(); }
};

// uv_to_direction(uv) for each point.
struct UV_To_Direction {
	static constexpr Kind KIND{17};
	static constexpr const char* NAME = "uv_to_direction";
	static constexpr const char* FUNCTIONS = "uv_to_direction";
	std::vector<Vec2> uvs;
	template<class A> void fields(A& a) { a(uvs); }
	using Answer = std::vector<Vec3>;
	bool fits(const Answer& a) const { return a.size() == uvs.size(); }
};

// What a sampler answers: sample(u) for each u, pdf(dir) for each dir.
struct Sampler_Answer {
	std::vector<Vec3> samples;
	std::vector<float> pdfs;
	template<class A> void fields(A& a) { a(samples, pdfs); }
};

// Samplers::Sphere::Uniform: sample(u) for each u and pdf(dir) for each dir.
struct Uniform_Sphere {
	static constexpr Kind KIND{18};
	static constexpr const char* NAME = "uniform_sphere";
	static constexpr const char* FUNCTIONS = "Samplers::Sphere::Uniform";
	std::vector<Vec2> us;
	std::vector<Vec3> dirs;
	template<class A> void fields(A& a) { a(us, dirs); }
	using Answer = Sampler_Answer;
	bool fits(const Answer& a) const { return a.samples.size() == us.size() && a.pdfs.size() == dirs.size(); }
};

// Samplers::Sphere::Image(image): its tables, then sample(u) for each u and pdf(dir) for each dir.
struct Image_Sampler {
	static constexpr Kind KIND{19};
	static constexpr const char* NAME = "image_sampler";
	static constexpr const char* FUNCTIONS = "Samplers::Sphere::Image";
	HDR_Image image;
	std::vector<Vec2> us;
	std::vector<Vec3> dirs;
	template<class A> void fields(A& a) { a(image, us, dirs); }
	struct Answer {
		uint32_t w = 0, h = 0;
		std::vector<float> pdf_texel, cdf;
		Sampler_Answer queries;
		template<class A> void fields(A& a) { a(w, h, pdf_texel, cdf, queries); }
	};
	bool fits(const Answer& a) const {
		return a.queries.samples.size() == us.size() && a.queries.pdfs.size() == dirs.size();
	}
};

// Env_Map(image, importance_sampling): sample(u) for each u, pdf(dir) and evaluate(dir) for each
// dir.
struct Env_Map_Queries {
	static constexpr Kind KIND{20};
	static constexpr const char* NAME = "env_map";
	static constexpr const char* FUNCTIONS = "Env_Map";
	HDR_Image image;
	bool importance_sampling = true;
	std::vector<Vec2> us;
	std::vector<Vec3> dirs;
	template<class A> void fields(A& a) { a(image, importance_sampling, us, dirs); }
	struct Answer {
		Sampler_Answer queries;
		std::vector<Spectrum> radiance;
		template<class A> void fields(A& a) { a(queries, radiance); }
	};
	bool fits(const Answer& a) const {
		return a.queries.samples.size() == us.size() && a.queries.pdfs.size() == dirs.size() &&
		       a.radiance.size() == dirs.size();
	}
};

// Env_Constant{radiance} (framework, sampling with Samplers::Sphere::Uniform): sample(u) for each u,
// pdf(dir) and evaluate(dir) for each dir.
struct Env_Constant_Queries {
	static constexpr Kind KIND{21};
	static constexpr const char* NAME = "env_constant";
	static constexpr const char* FUNCTIONS = "Env_Constant (with your Samplers::Sphere::Uniform)";
	Spectrum radiance{1.0f};
	std::vector<Vec2> us;
	std::vector<Vec3> dirs;
	template<class A> void fields(A& a) { a(radiance, us, dirs); }
	using Answer = Env_Map_Queries::Answer;
	bool fits(const Answer& a) const {
		return a.queries.samples.size() == us.size() && a.queries.pdfs.size() == dirs.size() &&
		       a.radiance.size() == dirs.size();
	}
};

// ---- Task 8 ----

// An Adaptive_Sampling (api/adaptive_sampling.h) on the wire.
struct Adaptive_Rule {
	float threshold = 0.0f;
	uint32_t min_samples = 0, batch = 0;
	template<class A> void fields(A& a) { a(threshold, min_samples, batch); }
	Adaptive_Sampling restored() const { return Adaptive_Sampling{threshold, min_samples, batch}; }
};

// rule.pixel_converged(sums) for each query: 1 where it may stop, else 0.
struct Pixel_Converged {
	static constexpr Kind KIND{24};
	static constexpr const char* NAME = "pixel_converged";
	static constexpr const char* FUNCTIONS = "Adaptive_Sampling::pixel_converged";
	struct Query {
		Adaptive_Rule rule;
		uint32_t n = 0;
		double sum = 0.0, sum_of_squares = 0.0;
		template<class A> void fields(A& a) { a(rule, n, sum, sum_of_squares); }
	};
	std::vector<Query> queries;
	template<class A> void fields(A& a) { a(queries); }
	using Answer = std::vector<uint32_t>;
	bool fits(const Answer& a) const { return a.size() == queries.size(); }
};

// rule.sample_pixel(max_samples, take_sample) for each pixel, whose take_sample(s) returns the grey
// sample Spectrum(samples[s]) (0 past the end): the indices it asked for, in order (at most twice
// max_samples of them), and the count it returned.
struct Sample_Pixels {
	static constexpr Kind KIND{25};
	static constexpr const char* NAME = "sample_pixels";
	static constexpr const char* FUNCTIONS = "Adaptive_Sampling::sample_pixel";
	struct Pixel {
		uint32_t max_samples = 0;
		std::vector<float> samples;
		template<class A> void fields(A& a) { a(max_samples, samples); }
	};
	struct Result {
		std::vector<uint32_t> asked;
		uint32_t returned = 0;
		template<class A> void fields(A& a) { a(asked, returned); }
	};
	Adaptive_Rule rule;
	std::vector<Pixel> pixels;
	template<class A> void fields(A& a) { a(rule, pixels); }
	using Answer = std::vector<Result>;
	bool fits(const Answer& a) const { return a.size() == pixels.size(); }
};

// render(Pathtracer(scene, settings)) on `threads` threads with adaptive sampling by `rule`: every
// pixel's samples drawn by the framework as `./lab render --adaptive` draws them.
struct Adaptive_Render {
	static constexpr Kind KIND{26};
	static constexpr const char* NAME = "adaptive_render";
	static constexpr const char* FUNCTIONS = "an adaptive render of the scene with your code";
	Scene scene;
	Render_Settings settings;
	Adaptive_Rule rule;
	uint32_t threads = 1;
	template<class A> void fields(A& a) { a(scene, settings, rule, threads); }
	using Answer = Film;
	bool fits(const Answer& a) const { return a.w == settings.width && a.h == settings.height; }
};

// ---- Every request, once ----
// The judge asks them (judge.h); the subject answers each with answer(request), which each task's
// answers/task<N>.h defines; kind_name, kind_functions and the subject's dispatch are made from
// this list. A new request: its struct above and its answer, nothing else.
using Requests = std::tuple<
	Generate_Rays,
	Trace_Pixels,
	Render,
	Triangle_Hits,
	Sphere_Hits,
	BBox_Hits,
	BVH_Triangles,
	BVH_Instances,
	BSDF_Scatter,
	BSDF_Evaluate,
	BSDF_Pdf,
	Reflect,
	Refract,
	Fresnel,
	Sample_Incoming,
	Power_Heuristic,
	Estimate_Direct,
	Direction_To_UV,
	UV_To_Direction,
	Uniform_Sphere,
	Image_Sampler,
	Env_Map_Queries,
	Env_Constant_Queries,
	Pixel_Converged,
	Sample_Pixels,
	Adaptive_Render>;

// Each request's KIND is its own.
template<class... Request> constexpr bool kinds_differ(std::tuple<Request...>*) {
	const Kind kinds[] = {Request::KIND...};
	for (size_t i = 0; i < sizeof...(Request); i++) {
		for (size_t j = 0; j < i; j++) {
			if (kinds[i] == kinds[j]) return false;
		}
	}
	return true;
}
static_assert(kinds_differ(static_cast<Requests*>(nullptr)), "two requests share a KIND");

} // namespace protocol
