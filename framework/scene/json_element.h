#pragma once
// Reading JSON input with errors that say where. A Json_Element is a value of a parsed file
// together with the file's name and the value's element path (e.g. objects[3].transform[0].scale),
// so a bad value becomes ONE message:
//     Input_Error("<file>: <element>: expected <what was expected>, found <what was there>")
// Internal to the framework (the scene loader); nothing here is part of the students' API.
#include "vec_math.h"

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <memory>
#include <string>

// Objects keep the order of the file, so e.g. materials are numbered as they are written.
using Json = nlohmann::ordered_json;

class Json_Element {
public:
	// Reads and parses a whole file. Errors: the file cannot be read, the text is not JSON (with
	// line and column), a number overflows, a key appears twice in one object.
	static Json_Element parse_file(const std::string& file);
	// A document made in code, read as if it were `file` (its errors and relative paths name it).
	static Json_Element from_json(Json root, const std::string& file);

	// --- Objects. A missing member is an element too: reading a value from it fails with
	// "expected <value>, found nothing (the key is missing)".
	Json_Element operator[](const std::string& key) const;
	bool has(const std::string& key) const;
	// Any member not in `keys` is an error (a typo like "radious" must not be silently ignored).
	void allow_only(std::initializer_list<const char*> keys) const;
	void require_object(const std::string& expected = "an object") const;

	// --- Arrays.
	size_t array_size(const std::string& expected = "an array") const; // fails unless an array
	Json_Element operator[](size_t index) const;

	// --- Values. Each fails (throws Input_Error) unless the value has the stated form.
	std::string string() const;                       // a string
	std::string non_empty_string() const;             // a string with at least one character
	bool boolean() const;                             // true or false
	float number() const;                             // a number, finite as a float
	float number_in(float min, float max) const;      // a finite number in [min, max] (max may be INF_F)
	float positive_number() const;                    // a finite number > 0
	// An integer in [min, max]; `expectation` replaces "a whole number from min to max" in errors.
	uint64_t whole_number(uint64_t min, uint64_t max, const std::string& expectation = "") const;
	Vec3 vec3() const;                                // [x, y, z] of finite numbers
	Vec3 vec3_in(float min, float max) const;         // [x, y, z], each in [min, max]

	// The same, with a default for a missing key.
	bool boolean_or(bool fallback) const;
	float number_in_or(float min, float max, float fallback) const;
	uint64_t whole_number_or(uint64_t min, uint64_t max, uint64_t fallback) const;
	Vec3 vec3_or(Vec3 fallback) const;
	Vec3 vec3_in_or(float min, float max, Vec3 fallback) const;

	bool present() const {
		return value != nullptr;
	}
	bool is_string() const {
		return value && value->is_string();
	}
	bool is_number() const {
		return value && value->is_number();
	}
	const Json& json() const; // fails if missing

	// "<file>: <element>: expected <expected>, found <a description of this value>"
	[[noreturn]] void fail(const std::string& expected) const;
	// "<file>: <element>: <message>"
	[[noreturn]] void error(const std::string& message) const;

	const std::string& file() const {
		return document->file;
	}
	const std::string& path() const {
		return element_path;
	}

private:
	struct Document {
		std::string file;
		Json root;
	};
	Json_Element(std::shared_ptr<const Document> document, const Json* value, std::string path)
		: document(std::move(document)), value(value), element_path(std::move(path)) {
	}
	std::string found() const;
	float finite_float(const std::string& expected) const; // fails with `expected` unless a number

	std::shared_ptr<const Document> document; // keeps the parsed tree alive
	const Json* value = nullptr;              // nullptr: a missing member
	std::string element_path;                 // "" for the whole document
};
