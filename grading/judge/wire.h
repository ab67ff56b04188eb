#pragma once
// The byte encoding of the protocol's messages (protocol.h): a Writer appends values to a byte
// string, a Reader takes them back and throws Malformed on anything that is not a well-formed
// value (a count larger than the bytes left, a bool that is neither 0 nor 1, an unknown tag).
// Structs of the protocol list their members once, in fields(); framework types are encoded here.
#include "protocol.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace wire {

// Types whose bytes in memory are exactly their encoding (little-endian IEEE floats, nothing else):
// vectors of them are copied whole, which matters for batches of millions of samples.
template<class T> constexpr bool is_float_record = false;
template<> inline constexpr bool is_float_record<float> = true;
template<> inline constexpr bool is_float_record<Vec2> = sizeof(Vec2) == 2 * sizeof(float);
template<> inline constexpr bool is_float_record<Vec3> = sizeof(Vec3) == 3 * sizeof(float);
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the protocol's numbers are little-endian");
template<> inline constexpr bool is_float_record<Scatter> = sizeof(Scatter) == 6 * sizeof(float);

template<class T> size_t smallest_encoding();

struct Malformed : std::runtime_error {
	using std::runtime_error::runtime_error;
};

class Writer {
public:
	template<class... T> void operator()(const T&... values) {
		(put(values), ...);
	}
	std::string bytes;

private:
	// The primitives are inline: a batch holds millions of them.
	void raw(const void* data, size_t size) {
		bytes.append(static_cast<const char*>(data), size);
	}
	void put(bool b) {
		char byte = b ? 1 : 0;
		raw(&byte, 1);
	}
	void put(uint32_t n) {
		raw(&n, sizeof n);
	}
	void put(uint64_t n) {
		raw(&n, sizeof n);
	}
	void put(float x) {
		raw(&x, sizeof x);
	}
	void put(double x) {
		raw(&x, sizeof x);
	}
	void put(Vec2 v) {
		raw(&v.x, sizeof(float)), raw(&v.y, sizeof(float));
	}
	void put(Vec3 v) {
		float xyz[3] = {v.x, v.y, v.z};
		raw(xyz, sizeof xyz);
	}
	void put(const glm::dvec3& v) {
		double xyz[3] = {v.x, v.y, v.z};
		raw(xyz, sizeof xyz);
	}
	void put(const Mat4& m);
	void put(const std::string& s);
	void put(View view);
	void put(const RNG_State& rng);
	void put(const Camera& camera);
	void put(const Render_Settings& settings);
	void put(const Estimator_Choice& estimator);
	void put(const Ray& ray);
	void put(const Trace& trace);
	void put(const Tri_Mesh_Vert& vertex);
	void put(const Triangle& triangle);
	void put(const Sphere& sphere);
	void put(const BBox& box);
	void put(const BSDF& bsdf);
	void put(const Material& material);
	void put(const Scatter& scatter);
	void put(const Incoming_Sample& sample);
	void put(const HDR_Image& image);
	void put(const Pixel_Stats& pixel);
	void put(const Film& film);
	void put(const Instance& object);
	void put(const Scene& scene);
	template<class T> void put(const std::vector<T>& items) {
		put(uint64_t(items.size()));
		if constexpr (is_float_record<T>) {
			raw(items.data(), items.size() * sizeof(T));
		} else {
			for (const T& item : items) put(item);
		}
	}
	// A protocol struct: its fields() only read the members when writing.
	template<class T> auto put(const T& value) -> decltype(const_cast<T&>(value).fields(*this)) {
		const_cast<T&>(value).fields(*this);
	}
};

class Reader {
public:
	explicit Reader(const std::string& bytes) : bytes(bytes) {
	}
	template<class... T> void operator()(T&... values) {
		(get(values), ...);
	}
	// Throws Malformed unless every byte was read.
	void expect_end() const;

private:
	void raw(void* data, size_t size) {
		if (size > bytes.size() - at) ends_early();
		std::memcpy(data, bytes.data() + at, size);
		at += size;
	}
	[[noreturn]] void ends_early() const;
	// A count of items each at least `item_bytes` long that the bytes left can hold.
	size_t count(size_t item_bytes);
	void get(bool& b);
	void get(uint32_t& n) {
		raw(&n, sizeof n);
	}
	void get(uint64_t& n) {
		raw(&n, sizeof n);
	}
	void get(float& x) {
		raw(&x, sizeof x);
	}
	void get(double& x) {
		raw(&x, sizeof x);
	}
	void get(Vec2& v) {
		float xy[2];
		raw(xy, sizeof xy);
		v = Vec2(xy[0], xy[1]);
	}
	void get(Vec3& v) {
		float xyz[3];
		raw(xyz, sizeof xyz);
		v = Vec3(xyz[0], xyz[1], xyz[2]);
	}
	void get(glm::dvec3& v) {
		double xyz[3];
		raw(xyz, sizeof xyz);
		v = glm::dvec3(xyz[0], xyz[1], xyz[2]);
	}
	void get(Mat4& m);
	void get(std::string& s);
	void get(View& view);
	void get(RNG_State& rng);
	void get(Camera& camera);
	void get(Render_Settings& settings);
	void get(Estimator_Choice& estimator);
	void get(Ray& ray);
	void get(Trace& trace);
	void get(Tri_Mesh_Vert& vertex);
	void get(Triangle& triangle);
	void get(Sphere& sphere);
	void get(BBox& box);
	void get(BSDF& bsdf);
	void get(Material& material);
	void get(Scatter& scatter);
	void get(Incoming_Sample& sample);
	void get(HDR_Image& image);
	void get(Pixel_Stats& pixel);
	void get(Film& film);
	void get(Scene& scene);
	// A vector is allocated for as many items as the bytes left can encode, so that a message never
	// decodes into much more memory than its own size.
	template<class T> void get(std::vector<T>& items) {
		if constexpr (is_float_record<T>) {
			items.resize(count(sizeof(T)));
			raw(items.data(), items.size() * sizeof(T));
		} else {
			items.resize(count(smallest_encoding<T>()));
			for (T& item : items) get(item);
		}
	}
	template<class T> auto get(T& value) -> decltype(value.fields(*this)) {
		value.fields(*this);
	}

	const std::string& bytes;
	size_t at = 0;
};

template<class T> std::string encode(const T& value) {
	Writer writer;
	writer(value);
	return std::move(writer.bytes);
}

template<class T> T empty_value() {
	return T{};
}
template<> inline Film empty_value<Film>() {
	return Film(0, 0);
}

// The fewest bytes a T is encoded in: an empty value's (no items in its vectors, the first and
// shortest alternative of its variants).
template<class T> size_t smallest_encoding() {
	static const size_t bytes = std::max<size_t>(1, encode(empty_value<T>()).size());
	return bytes;
}

template<class T> T decode(const std::string& bytes) {
	T value = empty_value<T>();
	Reader reader(bytes);
	reader(value);
	reader.expect_end();
	return value;
}

// The messages' headers (protocol.h, "Transport"), for both sides: the judge writes requests and
// reads answers (subject.cpp), the subject reads requests and writes answers (subject_main.cpp).
struct Request_Header {
	uint32_t magic = protocol::MAGIC, kind = 0, sequence = 0;
	uint64_t length = 0; // of the payload that follows
	static constexpr size_t BYTES = 3 * 4 + 8;
};
struct Answer_Header {
	uint32_t magic = protocol::MAGIC, kind = 0, sequence = 0, status = 0;
	uint64_t length = 0;
	static constexpr size_t BYTES = 4 * 4 + 8;
};
// A message: its header with the payload's length, then the payload.
std::string message(Request_Header header, const std::string& payload);
std::string message(Answer_Header header, const std::string& payload);
// The header in the first BYTES bytes at `bytes` (checked by the caller: magic, status, length).
Request_Header request_header(const char* bytes);
Answer_Header answer_header(const char* bytes);

// For the judge and the subject, first thing in main: requests and answers of millions of samples
// are encoded, decoded and freed one after another, and the C library would map each large buffer
// afresh and unmap it when freed (a page fault per 4 KiB every time); this keeps them in the heap.
void keep_large_buffers();

} // namespace wire
