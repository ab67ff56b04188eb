// The subject: the program that runs a student's code for the judge (protocol.h). It is linked
// with the student's task N and the reference of the other six (cmake/lab.cmake) and started by
// the judge inside the sandbox, one fresh process per test case. It reads a request, runs the task
// functions on the request's inputs and writes back their raw outputs; it decides nothing.
//
// For debugging (./lab grade N --debug), `subject --replay FILE` answers the requests a judge
// saved in FILE and discards the answers, so the student's code can be stepped through in gdb.
#include "protocol.h"
#include "wire.h"

#include "object_answers.h"
#include "render.h"
#include "render_observer.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <mutex>
#include <string>
#include <thread>

#include <fcntl.h>
#include <unistd.h>

namespace {

using namespace protocol;

// ---- The task functions, per request ----

Generate_Rays::Answer answer(const Generate_Rays& request) {
	Generate_Rays::Answer rays;
	for (const auto& q : request.queries) rays.push_back(q.camera.generate_ray(q.film_uv));
	return rays;
}

Trace_Pixels::Answer answer(const Trace_Pixels& request) {
	Pathtracer pathtracer(request.scene, request.settings, request.view);
	Trace_Pixels::Answer colours;
	for (const auto& s : request.samples) {
		RNG rng = RNG::restore(s.rng);
		colours.push_back(pathtracer.trace_pixel(s.x, s.y, rng));
	}
	return colours;
}

Render::Answer answer(const Render& request) {
	Pathtracer pathtracer(request.scene, request.settings, request.view);
	Render_Options options;
	options.threads = std::max(1u, request.threads);
	return render(pathtracer, options);
}

Triangle_Hits::Answer answer(const Triangle_Hits& request) {
	Triangle_Hits::Answer hits;
	for (const auto& q : request.queries) hits.push_back(q.triangle.hit(q.ray));
	return hits;
}

Sphere_Hits::Answer answer(const Sphere_Hits& request) {
	Sphere_Hits::Answer hits;
	for (const auto& q : request.queries) hits.push_back(q.sphere.hit(q.ray));
	return hits;
}

BBox_Hits::Answer answer(const BBox_Hits& request) {
	BBox_Hits::Answer results;
	for (const auto& q : request.queries) {
		BBox_Hits::Result result;
		result.times = q.times;
		result.hit = q.box.hit(q.ray, result.times);
		results.push_back(result);
	}
	return results;
}

template<typename Primitive> Tree tree_of(const BVH<Primitive>& bvh) {
	Tree tree;
	for (const auto& n : bvh.nodes) tree.nodes.push_back(Tree::Node{n.bbox, n.start, n.size, n.l, n.r});
	tree.root_idx = bvh.root_idx;
	return tree;
}

// f(i) for i in [0, count), on every core (as a render calls BVH::hit: from several threads at
// once); an exception thrown by any call is thrown again here, after all threads have ended.
template<class F> void for_each_in_parallel(size_t count, F f) {
	size_t threads = std::clamp<size_t>(std::thread::hardware_concurrency(), 1, 8);
	std::atomic<size_t> next{0};
	std::exception_ptr thrown;
	std::mutex thrown_mutex;
	auto work = [&] {
		try {
			for (size_t i; (i = next.fetch_add(1)) < count;) f(i);
		} catch (...) {
			std::lock_guard<std::mutex> lock(thrown_mutex);
			if (!thrown) thrown = std::current_exception();
			next = count; // the others stop too
		}
	};
	std::vector<std::thread> pool;
	for (size_t t = 1; t < threads; t++) pool.emplace_back(work);
	work();
	for (std::thread& thread : pool) thread.join();
	if (thrown) std::rethrow_exception(thrown);
}

BVH_Triangles::Answer answer(const BVH_Triangles& request) {
	BVH<Triangle> bvh(std::vector<Triangle>(request.triangles), request.max_leaf_size);
	BVH_Triangles::Answer result;
	result.tree = tree_of(bvh);
	result.primitives = bvh.primitives;
	result.hits.resize(request.rays.size());
	for_each_in_parallel(request.rays.size(), [&](size_t i) { result.hits[i] = bvh.hit(request.rays[i]); });
	return result;
}

// Asks the judge about each object Instance::hit tests (protocol.h: Object_Question; defined with
// the transport below).
struct Judge_Answers : Object_Answers {
	Trace hit(uint32_t object, const Ray& ray) const override;
};

BVH_Instances::Answer answer(const BVH_Instances& request) {
	// Objects that are boxes alone: their shapes stay with the judge, who answers Instance::hit.
	std::vector<Instance> objects;
	for (uint32_t index = 0; index < request.boxes.size(); index++) {
		objects.emplace_back(Sphere{}, Mat4{1.0f}, 0u, index);
		objects.back().world_bbox = request.boxes[index];
	}
	BVH<Instance> bvh(std::move(objects), request.max_leaf_size);
	BVH_Instances::Answer result;
	result.tree = tree_of(bvh);
	for (const Instance& object : bvh.primitives) result.order.push_back(object.index);
	Judge_Answers judge;
	Object_Answers::Scope asking(judge);
	for (const Ray& ray : request.rays) result.hits.push_back(bvh.hit(ray));
	return result;
}

BSDF_Scatter::Answer answer(const BSDF_Scatter& request) {
	RNG rng = RNG::restore(request.rng);
	BSDF_Scatter::Answer samples;
	for (Vec3 out_dir : request.out_dirs) samples.push_back(request.bsdf.scatter(rng, out_dir));
	return samples;
}

BSDF_Evaluate::Answer answer(const BSDF_Evaluate& request) {
	BSDF_Evaluate::Answer values;
	for (const auto& p : request.pairs) values.push_back(request.bsdf.evaluate(p.out_dir, p.in_dir));
	return values;
}

protocol::BSDF_Pdf::Answer answer(const protocol::BSDF_Pdf& request) {
	protocol::BSDF_Pdf::Answer values;
	for (const auto& p : request.pairs) values.push_back(request.bsdf.pdf(p.out_dir, p.in_dir));
	return values;
}

Reflect::Answer answer(const Reflect& request) {
	Reflect::Answer dirs;
	for (Vec3 dir : request.dirs) dirs.push_back(reflect(dir));
	return dirs;
}

Refract::Answer answer(const Refract& request) {
	Refract::Answer results;
	for (const auto& q : request.queries) {
		Refract::Result result;
		result.in_dir = refract(q.out_dir, q.index_of_refraction, result.was_internal);
		results.push_back(result);
	}
	return results;
}

Fresnel::Answer answer(const Fresnel& request) {
	Fresnel::Answer values;
	for (const auto& q : request.queries) values.push_back(fresnel(q.cos_theta, q.index_of_refraction));
	return values;
}

Sample_Incoming::Answer answer(const Sample_Incoming& request) {
	Pathtracer pathtracer(request.scene, request.settings);
	RNG rng = RNG::restore(request.rng);
	Sample_Incoming::Answer samples;
	for (const auto& q : request.queries) samples.push_back(pathtracer.sample_incoming(rng, q.hit, q.bsdf, q.out_dir));
	return samples;
}

Power_Heuristic::Answer answer(const Power_Heuristic& request) {
	Power_Heuristic::Answer weights;
	for (Vec2 pdfs : request.pairs) weights.push_back(power_heuristic(pdfs.x, pdfs.y));
	return weights;
}

Estimate_Direct::Answer answer(const Estimate_Direct& request) {
	Pathtracer pathtracer(request.scene, request.settings);
	RNG rng = RNG::restore(request.rng);
	Estimate_Direct::Answer light;
	for (const auto& q : request.queries) light.push_back(pathtracer.estimate_direct(rng, q.hit, q.bsdf, q.out_dir));
	return light;
}

Direction_To_UV::Answer answer(const Direction_To_UV& request) {
	Direction_To_UV::Answer uvs;
	for (Vec3 dir : request.dirs) uvs.push_back(direction_to_uv(dir));
	return uvs;
}

UV_To_Direction::Answer answer(const UV_To_Direction& request) {
	UV_To_Direction::Answer dirs;
	for (Vec2 uv : request.uvs) dirs.push_back(uv_to_direction(uv));
	return dirs;
}

template<class Sampler> Sampler_Answer ask_sampler(const Sampler& sampler, const std::vector<Vec2>& us,
                                                   const std::vector<Vec3>& dirs) {
	Sampler_Answer result;
	for (Vec2 u : us) result.samples.push_back(sampler.sample(u));
	for (Vec3 dir : dirs) result.pdfs.push_back(sampler.pdf(dir));
	return result;
}

Uniform_Sphere::Answer answer(const Uniform_Sphere& request) {
	return ask_sampler(Samplers::Sphere::Uniform{}, request.us, request.dirs);
}

Image_Sampler::Answer answer(const Image_Sampler& request) {
	Samplers::Sphere::Image sampler(request.image);
	Image_Sampler::Answer result;
	result.w = sampler.w;
	result.h = sampler.h;
	result.pdf_texel = sampler.pdf_texel;
	result.cdf = sampler.cdf;
	result.queries = ask_sampler(sampler, request.us, request.dirs);
	return result;
}

// An environment's sample(u) for each u, pdf(dir) and evaluate(dir) for each dir.
template<class Environment> Env_Map_Queries::Answer ask_environment(const Environment& environment,
                                                                    const std::vector<Vec2>& us,
                                                                    const std::vector<Vec3>& dirs) {
	Env_Map_Queries::Answer result;
	result.queries = ask_sampler(environment, us, dirs);
	for (Vec3 dir : dirs) result.radiance.push_back(environment.evaluate(dir));
	return result;
}

Env_Map_Queries::Answer answer(const Env_Map_Queries& request) {
	return ask_environment(Env_Map(request.image, request.importance_sampling), request.us, request.dirs);
}

Env_Constant_Queries::Answer answer(const Env_Constant_Queries& request) {
	return ask_environment(Env_Constant{request.radiance}, request.us, request.dirs);
}

template<class Request> std::string serve(const std::string& payload) {
	return wire::encode(answer(wire::decode<Request>(payload)));
}

std::string serve(Kind kind, const std::string& payload) {
	switch (kind) {
	case Kind::generate_rays: return serve<Generate_Rays>(payload);
	case Kind::trace_pixels: return serve<Trace_Pixels>(payload);
	case Kind::render: return serve<Render>(payload);
	case Kind::triangle_hits: return serve<Triangle_Hits>(payload);
	case Kind::sphere_hits: return serve<Sphere_Hits>(payload);
	case Kind::bbox_hits: return serve<BBox_Hits>(payload);
	case Kind::bvh_triangles: return serve<BVH_Triangles>(payload);
	case Kind::bvh_instances: return serve<BVH_Instances>(payload);
	case Kind::bsdf_scatter: return serve<BSDF_Scatter>(payload);
	case Kind::bsdf_evaluate: return serve<BSDF_Evaluate>(payload);
	case Kind::bsdf_pdf: return serve<protocol::BSDF_Pdf>(payload);
	case Kind::reflect: return serve<Reflect>(payload);
	case Kind::refract: return serve<Refract>(payload);
	case Kind::fresnel: return serve<Fresnel>(payload);
	case Kind::sample_incoming: return serve<Sample_Incoming>(payload);
	case Kind::direction_to_uv: return serve<Direction_To_UV>(payload);
	case Kind::uv_to_direction: return serve<UV_To_Direction>(payload);
	case Kind::uniform_sphere: return serve<Uniform_Sphere>(payload);
	case Kind::image_sampler: return serve<Image_Sampler>(payload);
	case Kind::env_map: return serve<Env_Map_Queries>(payload);
	case Kind::env_constant: return serve<Env_Constant_Queries>(payload);
	case Kind::power_heuristic: return serve<Power_Heuristic>(payload);
	case Kind::estimate_direct: return serve<Estimate_Direct>(payload);
	}
	throw wire::Malformed("unknown request kind " + std::to_string(uint32_t(kind)));
}

// ---- Transport ----

bool read_all(int fd, void* data, size_t size) {
	char* p = static_cast<char*>(data);
	while (size > 0) {
		ssize_t n = read(fd, p, size);
		if (n < 0 && errno == EINTR) continue;
		if (n <= 0) return false;
		p += n;
		size -= size_t(n);
	}
	return true;
}

void write_all(int fd, const void* data, size_t size) {
	const char* p = static_cast<const char*>(data);
	while (size > 0) {
		ssize_t n = write(fd, p, size);
		if (n < 0 && errno == EINTR) continue;
		if (n <= 0) _exit(3); // the judge is gone
		p += n;
		size -= size_t(n);
	}
}

struct Request_Header {
	uint32_t magic, kind, sequence;
	uint64_t length;
};

// Reads one request; false at the end of the input.
bool read_request(int fd, Request_Header& header, std::string& payload) {
	if (!read_all(fd, &header.magic, 4) || !read_all(fd, &header.kind, 4) || !read_all(fd, &header.sequence, 4) ||
	    !read_all(fd, &header.length, 8)) {
		return false;
	}
	if (header.magic != MAGIC || header.length > MAX_PAYLOAD) {
		std::fprintf(stderr, "subject: not a judge's request\n");
		_exit(2);
	}
	payload.resize(header.length);
	return read_all(fd, payload.data(), payload.size());
}

// The request being answered (its questions repeat its header), and whether it is replayed.
Request_Header current_request;
bool replaying = false;

void write_answer(const Request_Header& request, Status status, const std::string& payload) {
	std::string message;
	auto append = [&](const auto& value) { message.append(reinterpret_cast<const char*>(&value), sizeof value); };
	append(MAGIC);
	append(request.kind);
	append(request.sequence);
	append(uint32_t(status));
	append(uint64_t(payload.size()));
	message += payload;
	write_all(ANSWER_FD, message.data(), message.size());
}

Trace Judge_Answers::hit(uint32_t object, const Ray& ray) const {
	if (replaying) return Trace{}; // the judge's replies are not saved: every object is missed
	write_answer(current_request, Status::QUESTION, wire::encode(Object_Question{object, ray}));
	Request_Header reply;
	std::string payload;
	if (!read_request(REQUEST_FD, reply, payload) || reply.kind != current_request.kind ||
	    reply.sequence != current_request.sequence) {
		_exit(3); // the judge is gone, or not a judge
	}
	return wire::decode<Trace>(payload);
}

int serve_judge() {
	Request_Header& header = current_request;
	std::string payload;
	while (read_request(REQUEST_FD, header, payload)) {
		std::string answer;
		Status status = Status::OK;
		try {
			answer = serve(Kind(header.kind), payload);
		} catch (const std::exception& error) {
			status = Status::THREW;
			answer = error.what();
		}
		write_answer(header, status, answer);
	}
	return 0;
}

// Answers every request saved in `file` (the judge's --save-requests), printing what it runs.
int replay(const char* file) {
	int fd = open(file, O_RDONLY);
	if (fd < 0) {
		std::fprintf(stderr, "subject: cannot open %s: %s\n", file, std::strerror(errno));
		return 2;
	}
	replaying = true;
	Request_Header header;
	std::string payload;
	while (read_request(fd, header, payload)) {
		std::fprintf(stderr, "subject: request %u, %s (%s)\n", header.sequence, kind_name(Kind(header.kind)),
		             kind_functions(Kind(header.kind)));
		if (Kind(header.kind) == Kind::bvh_instances) {
			std::fprintf(stderr, "subject: (the judge answered for its objects, which a replay cannot: every "
			                     "Instance::hit misses)\n");
		}
		serve(Kind(header.kind), payload);
	}
	std::fprintf(stderr, "subject: every request answered\n");
	return 0;
}

} // namespace

int main(int argc, char** argv) {
	wire::keep_large_buffers();
	if (argc == 3 && std::string(argv[1]) == "--replay") return replay(argv[2]);
	if (argc != 1) {
		std::fprintf(stderr, "usage: %s            (started by a judge, see tests/judge/protocol.h)\n"
		                     "       %s --replay FILE (answer the requests a judge saved, for a debugger)\n",
		             argv[0], argv[0]);
		return 2;
	}
	return serve_judge();
}
