#include "json_element.h"
#include "error.h"
#include "text_file.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <vector>

namespace {

// Follows the parser through the document so that problems the parser itself does not report can
// still be located by element path: a key repeated in one object (nlohmann::json would silently
// keep the last value) and a number too large for a double (thrown before its value is stored).
class Path_Tracker {
public:
	// A parser callback (nlohmann::json's parser_callback_t); keeps every value.
	bool operator()(int, Json::parse_event_t event, Json& parsed) {
		using Event = Json::parse_event_t;
		switch (event) {
		case Event::key: enter_key(parsed.get<std::string>()); break;
		case Event::value: next_child(); break;
		case Event::object_start:
		case Event::array_start:
			next_child();
			levels.emplace_back();
			levels.back().is_array = event == Event::array_start;
			break;
		case Event::object_end:
		case Event::array_end: levels.pop_back(); break;
		}
		return true;
	}

	// The path of the value the parser is reading now (for an array, its next element).
	std::string current_path() const {
		std::string path;
		for (size_t i = 0; i < levels.size(); i++) {
			const Level& level = levels[i];
			bool innermost = i + 1 == levels.size();
			if (level.is_array) path += "[" + std::to_string(innermost ? level.count : level.count - 1) + "]";
			else path += (path.empty() ? "" : ".") + level.key;
		}
		return path;
	}

private:
	struct Level {
		bool is_array = false;
		size_t count = 0; // children started so far
		std::string key;  // objects: the current key
		std::set<std::string> keys;
	};

	void next_child() {
		if (!levels.empty()) levels.back().count++;
	}
	void enter_key(const std::string& key) {
		Level& object = levels.back();
		object.key = key;
		if (!object.keys.insert(key).second) {
			throw Input_Error(current_path() + ": this key appears twice in the same object");
		}
	}

	std::vector<Level> levels;
};

// 1-based line and column of the character at `offset`, as editors count them.
std::string line_and_column(const std::string& text, size_t offset) {
	offset = std::min(offset, text.size());
	size_t line_start = offset == 0 ? std::string::npos : text.rfind('\n', offset - 1); // the '\n' before
	size_t line = 1 + size_t(std::count(text.begin(), text.begin() + long(offset), '\n'));
	size_t column = line_start == std::string::npos ? offset + 1 : offset - line_start;
	return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// nlohmann's description of a parse error without its "[json.exception...] ... column N: " prefix.
std::string parse_error_reason(const std::string& what) {
	size_t column = what.find("column ");
	size_t colon = what.find(": ", column == std::string::npos ? 0 : column);
	return colon == std::string::npos ? what : what.substr(colon + 2);
}

std::string join(std::initializer_list<const char*> words) {
	std::string out;
	for (const char* w : words) out += (out.empty() ? "" : ", ") + std::string(w);
	return out;
}

// A short, readable form of a number: integers exactly, others with up to 9 significant digits.
std::string number_text(const Json& value) {
	if (!value.is_number_float()) return value.dump();
	double x = value.get<double>();
	if (!std::isfinite(x)) return "a number beyond the range of a double";
	std::ostringstream s;
	s.precision(9);
	s << x;
	return s.str();
}

// Appends the compact JSON text of `value` to `text` while `text` has at most `limit` characters;
// false once it is longer. Each level of nesting adds a character before going deeper, so the
// recursion is at most `limit` deep (dump() of an array nested 70 000 deep overflows the stack).
bool append_short_text(const Json& value, std::string& text, size_t limit) {
	if (!value.is_structured()) {
		text += value.dump();
		return text.size() <= limit;
	}
	text += value.is_array() ? '[' : '{';
	for (auto item = value.begin(); item != value.end(); ++item) {
		if (item != value.begin()) text += ',';
		if (value.is_object()) text += Json(item.key()).dump() + ':';
		if (text.size() > limit || !append_short_text(*item, text, limit)) return false;
	}
	text += value.is_array() ? ']' : '}';
	return text.size() <= limit;
}

// "from 0 to 1", or "of at least 0" when there is no upper limit.
std::string range_text(float min, float max) {
	std::ostringstream s;
	if (max == INF_F) s << "of at least " << min;
	else s << "from " << min << " to " << max;
	return s.str();
}

} // namespace

Json_Element Json_Element::parse_file(const std::string& file) {
	std::string text = read_text_file(file);
	auto document = std::make_shared<Document>();
	document->file = file;
	Path_Tracker tracker;
	try {
		document->root = Json::parse(text, std::ref(tracker));
	} catch (const Json::parse_error& e) {
		throw Input_Error(file + ": " + line_and_column(text, e.byte == 0 ? 0 : e.byte - 1) +
		                  ": not valid JSON: " + parse_error_reason(e.what()));
	} catch (const Json::out_of_range&) {
		// The only out_of_range the parser throws: a number like 1e999 that overflows a double.
		std::string path = tracker.current_path();
		throw Input_Error(file + ": " + (path.empty() ? "top level" : path) +
		                  ": expected a finite number, found a number beyond the range of a double");
	} catch (const Input_Error& e) {
		throw Input_Error(file + ": " + e.what()); // from the tracker: a repeated key
	}
	const Json* root = &document->root;
	return Json_Element(std::move(document), root, "");
}

Json_Element Json_Element::from_json(Json root, const std::string& file) {
	auto document = std::make_shared<Document>();
	document->file = file;
	document->root = std::move(root);
	const Json* value = &document->root;
	return Json_Element(std::move(document), value, "");
}

// --- Errors

std::string Json_Element::found() const {
	if (!value) return "nothing (the key is missing)";
	switch (value->type()) {
	case Json::value_t::null: return "null";
	case Json::value_t::boolean: return value->dump();
	case Json::value_t::number_integer:
	case Json::value_t::number_unsigned:
	case Json::value_t::number_float: return number_text(*value);
	case Json::value_t::string: {
		std::string s = value->get<std::string>();
		if (s.size() > 60) s = s.substr(0, 57) + "...";
		return "\"" + s + "\"";
	}
	case Json::value_t::array: {
		std::string text;
		if (append_short_text(*value, text, 60)) return text;
		return "an array of " + std::to_string(value->size()) + (value->size() == 1 ? " element" : " elements");
	}
	case Json::value_t::object: return "an object";
	default: return "a value of type " + std::string(value->type_name());
	}
}

void Json_Element::error(const std::string& message) const {
	throw Input_Error(file() + ": " + (element_path.empty() ? "top level" : element_path) + ": " + message);
}

void Json_Element::fail(const std::string& expected) const {
	error("expected " + expected + ", found " + found());
}

// --- Objects

const Json& Json_Element::json() const {
	if (!value) fail("a value");
	return *value;
}

void Json_Element::require_object(const std::string& expected) const {
	if (!value || !value->is_object()) fail(expected);
}

bool Json_Element::has(const std::string& key) const {
	return value && value->is_object() && value->contains(key);
}

Json_Element Json_Element::operator[](const std::string& key) const {
	require_object("an object with the key \"" + key + "\"");
	auto it = value->find(key);
	const Json* member = it == value->end() ? nullptr : &*it;
	return Json_Element(document, member, element_path.empty() ? key : element_path + "." + key);
}

void Json_Element::allow_only(std::initializer_list<const char*> keys) const {
	require_object();
	for (const auto& item : value->items()) {
		const std::string& key = item.key(); // (a structured binding cannot be captured before C++20)
		bool known = std::any_of(keys.begin(), keys.end(), [&](const char* k) { return key == k; });
		if (!known) (*this)[key].error("unknown key; expected one of: " + join(keys));
	}
}

// --- Arrays

size_t Json_Element::array_size(const std::string& expected) const {
	if (!value || !value->is_array()) fail(expected);
	return value->size();
}

Json_Element Json_Element::operator[](size_t index) const {
	if (index >= array_size()) fail("an array with an element " + std::to_string(index));
	return Json_Element(document, &(*value)[index], element_path + "[" + std::to_string(index) + "]");
}

// --- Values

std::string Json_Element::string() const {
	if (!value || !value->is_string()) fail("a string");
	return value->get<std::string>();
}

std::string Json_Element::non_empty_string() const {
	if (!value || !value->is_string() || value->get<std::string>().empty()) fail("a non-empty string");
	return value->get<std::string>();
}

bool Json_Element::boolean() const {
	if (!value || !value->is_boolean()) fail("true or false");
	return value->get<bool>();
}

float Json_Element::finite_float(const std::string& expected) const {
	if (!value || !value->is_number()) fail(expected);
	// A double that is finite may still overflow a float (e.g. 1e39).
	float x = value->get<float>();
	if (!std::isfinite(x)) fail("a finite number (within +-3.4e38)");
	return x;
}

float Json_Element::number() const {
	return finite_float("a number");
}

float Json_Element::number_in(float min, float max) const {
	std::string expected = "a number " + range_text(min, max);
	float x = finite_float(expected);
	if (!(x >= min && x <= max)) fail(expected);
	return x;
}

float Json_Element::positive_number() const {
	float x = finite_float("a number greater than 0");
	if (!(x > 0.0f)) fail("a number greater than 0");
	return x;
}

uint64_t Json_Element::whole_number(uint64_t min, uint64_t max, const std::string& expectation) const {
	std::string expected = !expectation.empty() ? expectation
	                       : "a whole number from " + std::to_string(min) + " to " + std::to_string(max);
	if (!value || !value->is_number_integer()) fail(expected);
	if (value->is_number_unsigned()) {
		uint64_t x = value->get<uint64_t>();
		if (x < min || x > max) fail(expected);
		return x;
	}
	int64_t x = value->get<int64_t>(); // negative (non-negative integers are parsed as unsigned)
	if (x < 0 || uint64_t(x) < min || uint64_t(x) > max) fail(expected);
	return uint64_t(x);
}

Vec3 Json_Element::vec3() const {
	if (!value || !value->is_array() || value->size() != 3) fail("an array of three numbers [x, y, z]");
	return Vec3{(*this)[0].number(), (*this)[1].number(), (*this)[2].number()};
}

Vec3 Json_Element::vec3_in(float min, float max) const {
	if (!value || !value->is_array() || value->size() != 3) fail("an array of three numbers, each " + range_text(min, max));
	return Vec3{(*this)[0].number_in(min, max), (*this)[1].number_in(min, max), (*this)[2].number_in(min, max)};
}

bool Json_Element::boolean_or(bool fallback) const {
	return present() ? boolean() : fallback;
}
float Json_Element::number_in_or(float min, float max, float fallback) const {
	return present() ? number_in(min, max) : fallback;
}
uint64_t Json_Element::whole_number_or(uint64_t min, uint64_t max, uint64_t fallback) const {
	return present() ? whole_number(min, max) : fallback;
}
Vec3 Json_Element::vec3_or(Vec3 fallback) const {
	return present() ? vec3() : fallback;
}
Vec3 Json_Element::vec3_in_or(float min, float max, Vec3 fallback) const {
	return present() ? vec3_in(min, max) : fallback;
}
