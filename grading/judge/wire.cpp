#include "wire.h"

#include <algorithm>
#include <cstring>

#include <malloc.h>

namespace wire {

void keep_large_buffers() {
	mallopt(M_MMAP_THRESHOLD, 256 << 20);
	mallopt(M_TRIM_THRESHOLD, 512 << 20);
}

namespace {

template<class T> void append(std::string& bytes, T value) {
	bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
}
template<class T> T take(const char*& bytes) {
	T value;
	std::memcpy(&value, bytes, sizeof value);
	bytes += sizeof value;
	return value;
}

} // namespace

std::string message(Request_Header header, const std::string& payload) {
	std::string bytes;
	append(bytes, header.magic), append(bytes, header.kind), append(bytes, header.sequence);
	append(bytes, uint64_t(payload.size()));
	return bytes + payload;
}

std::string message(Answer_Header header, const std::string& payload) {
	std::string bytes;
	append(bytes, header.magic), append(bytes, header.kind), append(bytes, header.sequence), append(bytes, header.status);
	append(bytes, uint64_t(payload.size()));
	return bytes + payload;
}

Request_Header request_header(const char* bytes) {
	Request_Header header;
	header.magic = take<uint32_t>(bytes), header.kind = take<uint32_t>(bytes), header.sequence = take<uint32_t>(bytes);
	header.length = take<uint64_t>(bytes);
	return header;
}

Answer_Header answer_header(const char* bytes) {
	Answer_Header header;
	header.magic = take<uint32_t>(bytes), header.kind = take<uint32_t>(bytes), header.sequence = take<uint32_t>(bytes);
	header.status = take<uint32_t>(bytes), header.length = take<uint64_t>(bytes);
	return header;
}

namespace {

enum class Shape_Tag : uint32_t { sphere = 0, mesh = 1 };
enum class Environment_Tag : uint32_t { none = 0, constant = 1, map = 2 };

// The scene's objects in their description's order: as filled in, or as commit() moved them into
// the top-level BVH.
std::vector<const Instance*> objects_of(const Scene& scene) {
	std::vector<const Instance*> objects;
	const std::vector<Instance>& source = scene.objects.empty() ? scene.bvh.primitives : scene.objects;
	for (const Instance& object : source) objects.push_back(&object);
	std::sort(objects.begin(), objects.end(), [](auto a, auto b) { return a->index < b->index; });
	return objects;
}

} // namespace

// ---- Writer ----

void Writer::put(const Mat4& m) {
	for (int c = 0; c < 4; c++)
		for (int r = 0; r < 4; r++) put(m[c][r]);
}
void Writer::put(const std::string& s) {
	put(uint64_t(s.size()));
	raw(s.data(), s.size());
}
void Writer::put(View view) {
	put(uint32_t(view));
}
void Writer::put(const RNG_State& rng) {
	(*this)(rng.state, rng.increment, rng.low_discrepancy, rng.reversed_index, rng.dimension, rng.pixel_key);
}
void Writer::put(const Camera& camera) {
	put(camera.camera_to_world), put(camera.v_fov), put(camera.aspect_ratio);
}
void Writer::put(const Render_Settings& s) {
	(*this)(s.width, s.height, s.samples, s.max_depth, s.seed, s.light_sampling, s.russian_roulette);
}
void Writer::put(const Estimator_Choice& e) {
	(*this)(e.integrator, uint32_t(e.sampler), uint32_t(e.light_choice));
}
void Writer::put(const Ray& ray) {
	(*this)(ray.point, ray.dir, ray.dist_bounds, ray.depth);
}
void Writer::put(const Trace& t) {
	(*this)(t.hit, t.distance, t.position, t.normal, t.origin, t.object, t.material);
}
void Writer::put(const Tri_Mesh_Vert& vertex) {
	put(vertex.position), put(vertex.normal);
}
void Writer::put(const Triangle& triangle) {
	(*this)(triangle.v0, triangle.v1, triangle.v2);
}
void Writer::put(const Sphere& sphere) {
	put(sphere.radius);
}
void Writer::put(const BBox& box) {
	put(box.min), put(box.max);
}
void Writer::put(const BSDF& bsdf) {
	put(uint32_t(bsdf.bsdf.index()));
	if (auto* b = std::get_if<BSDF_Lambertian>(&bsdf.bsdf)) put(b->albedo);
	if (auto* b = std::get_if<BSDF_Mirror>(&bsdf.bsdf)) put(b->reflectance);
	if (auto* b = std::get_if<BSDF_Glass>(&bsdf.bsdf)) (*this)(b->reflectance, b->transmittance, b->index_of_refraction);
}
void Writer::put(const Material& material) {
	put(material.bsdf), put(material.emission);
}
void Writer::put(const Scatter& scatter) {
	put(scatter.direction), put(scatter.attenuation);
}
void Writer::put(const Incoming_Sample& s) {
	(*this)(s.direction, s.attenuation, s.pdf, s.discrete);
}
void Writer::put(const HDR_Image& image) {
	(*this)(image.w, image.h, image.pixels);
}
void Writer::put(const Pixel_Stats& p) {
	(*this)(p.count, p.non_finite, p.mean, p.m2, p.m3, p.m4);
}
void Writer::put(const Film& film) {
	(*this)(film.w, film.h, film.pixels);
}
void Writer::put(const Instance& object) {
	if (auto* sphere = std::get_if<Sphere>(&object.shape)) {
		(*this)(uint32_t(Shape_Tag::sphere), *sphere);
	} else {
		(*this)(uint32_t(Shape_Tag::mesh), std::get<Tri_Mesh>(object.shape).bvh.primitives);
	}
	(*this)(object.to_world, object.material, object.index);
}
void Writer::put(const Scene& scene) {
	(*this)(scene.path, scene.camera, scene.settings, scene.materials, scene.material_names);
	std::vector<const Instance*> objects = objects_of(scene);
	put(uint64_t(objects.size()));
	for (const Instance* object : objects) put(*object);
	if (!scene.environment) {
		put(uint32_t(Environment_Tag::none));
	} else if (auto* constant = std::get_if<Env_Constant>(&*scene.environment)) {
		(*this)(uint32_t(Environment_Tag::constant), constant->radiance);
	} else {
		const Env_Map& map = std::get<Env_Map>(*scene.environment);
		(*this)(uint32_t(Environment_Tag::map), map.image, map.importance_sampling);
	}
}

// ---- Reader ----

void Reader::ends_early() const {
	throw Malformed("the message ends in the middle of a value");
}
size_t Reader::count(size_t item_bytes) {
	uint64_t n = 0;
	get(n);
	if (n > (bytes.size() - at) / item_bytes) throw Malformed("a count of " + std::to_string(n) + " items is larger than the message");
	return size_t(n);
}
void Reader::expect_end() const {
	if (at != bytes.size()) throw Malformed(std::to_string(bytes.size() - at) + " bytes after the last value");
}
void Reader::get(bool& b) {
	uint8_t byte = 0;
	raw(&byte, 1);
	if (byte > 1) throw Malformed("a yes/no value of " + std::to_string(byte));
	b = byte == 1;
}
void Reader::get(Mat4& m) {
	for (int c = 0; c < 4; c++)
		for (int r = 0; r < 4; r++) get(m[c][r]);
}
void Reader::get(std::string& s) {
	s.resize(count(1));
	raw(s.data(), s.size());
}
void Reader::get(View& view) {
	uint32_t n = 0;
	get(n);
	if (n > uint32_t(View::direction)) throw Malformed("an unknown view " + std::to_string(n));
	view = View(n);
}
void Reader::get(RNG_State& rng) {
	(*this)(rng.state, rng.increment, rng.low_discrepancy, rng.reversed_index, rng.dimension, rng.pixel_key);
}
void Reader::get(Camera& camera) {
	get(camera.camera_to_world), get(camera.v_fov), get(camera.aspect_ratio);
}
void Reader::get(Render_Settings& s) {
	(*this)(s.width, s.height, s.samples, s.max_depth, s.seed, s.light_sampling, s.russian_roulette);
}
void Reader::get(Estimator_Choice& e) {
	uint32_t sampler = 0, light_choice = 0;
	(*this)(e.integrator, sampler, light_choice); // an integrator's name is checked where it is used
	if (sampler > uint32_t(Sampler::sobol)) throw Malformed("an unknown sampler " + std::to_string(sampler));
	if (light_choice > uint32_t(Light_Choice::tree))
		throw Malformed("an unknown light choice " + std::to_string(light_choice));
	e.sampler = Sampler(sampler), e.light_choice = Light_Choice(light_choice);
}
void Reader::get(Ray& ray) {
	(*this)(ray.point, ray.dir, ray.dist_bounds, ray.depth);
}
void Reader::get(Trace& t) {
	(*this)(t.hit, t.distance, t.position, t.normal, t.origin, t.object, t.material);
}
void Reader::get(Tri_Mesh_Vert& vertex) {
	get(vertex.position), get(vertex.normal);
}
void Reader::get(Triangle& triangle) {
	(*this)(triangle.v0, triangle.v1, triangle.v2);
}
void Reader::get(Sphere& sphere) {
	get(sphere.radius);
}
void Reader::get(BBox& box) {
	get(box.min), get(box.max);
}
void Reader::get(BSDF& bsdf) {
	uint32_t tag = 0;
	get(tag);
	if (tag == 0) {
		BSDF_Lambertian b;
		get(b.albedo);
		bsdf = b;
	} else if (tag == 1) {
		BSDF_Mirror b;
		get(b.reflectance);
		bsdf = b;
	} else if (tag == 2) {
		BSDF_Glass b;
		(*this)(b.reflectance, b.transmittance, b.index_of_refraction);
		bsdf = b;
	} else {
		throw Malformed("an unknown BSDF " + std::to_string(tag));
	}
}
void Reader::get(Material& material) {
	get(material.bsdf), get(material.emission);
}
void Reader::get(Scatter& scatter) {
	get(scatter.direction), get(scatter.attenuation);
}
void Reader::get(Incoming_Sample& s) {
	(*this)(s.direction, s.attenuation, s.pdf, s.discrete);
}
void Reader::get(HDR_Image& image) {
	(*this)(image.w, image.h, image.pixels);
	if (image.pixels.size() != size_t(image.w) * image.h) throw Malformed("an image whose size and pixels disagree");
}
void Reader::get(Pixel_Stats& p) {
	(*this)(p.count, p.non_finite, p.mean, p.m2, p.m3, p.m4);
}
void Reader::get(Film& film) {
	(*this)(film.w, film.h, film.pixels);
	if (film.pixels.size() != size_t(film.w) * film.h) throw Malformed("a film whose size and pixels disagree");
}
void Reader::get(Scene& scene) {
	(*this)(scene.path, scene.camera, scene.settings, scene.materials, scene.material_names);
	size_t objects = count(1);
	for (size_t i = 0; i < objects; i++) {
		uint32_t tag = 0;
		get(tag);
		std::variant<Sphere, Tri_Mesh> shape;
		if (tag == uint32_t(Shape_Tag::sphere)) {
			Sphere sphere;
			get(sphere);
			shape = sphere;
		} else if (tag == uint32_t(Shape_Tag::mesh)) {
			std::vector<Triangle> triangles;
			get(triangles);
			shape = Tri_Mesh(std::move(triangles));
		} else {
			throw Malformed("an unknown shape " + std::to_string(tag));
		}
		Mat4 to_world;
		uint32_t material = 0, index = 0;
		(*this)(to_world, material, index);
		if (material >= scene.materials.size()) throw Malformed("an object with material " + std::to_string(material));
		scene.objects.emplace_back(std::move(shape), to_world, material, index);
	}
	uint32_t environment = 0;
	get(environment);
	if (environment == uint32_t(Environment_Tag::constant)) {
		Env_Constant constant;
		get(constant.radiance);
		scene.environment = constant;
	} else if (environment == uint32_t(Environment_Tag::map)) {
		HDR_Image image;
		bool importance_sampling = true;
		(*this)(image, importance_sampling);
		scene.environment = Env_Map(std::move(image), importance_sampling);
	} else if (environment != uint32_t(Environment_Tag::none)) {
		throw Malformed("an unknown environment " + std::to_string(environment));
	}
	scene.commit();
}

} // namespace wire
