#include "obj_check.h"
#include "decimal.h"
#include "error.h"

#include <charconv>
#include <cmath>
#include <string_view>
#include <vector>

namespace {

// The lines of the text as tinyobjloader counts them: each ended by "\n", "\r\n" or a lone "\r".
std::vector<std::string_view> lines_of(std::string_view text) {
	std::vector<std::string_view> lines;
	while (!text.empty()) {
		size_t end = text.find_first_of("\r\n");
		lines.push_back(text.substr(0, end));
		if (end == std::string_view::npos) break;
		text.remove_prefix(end + (text.compare(end, 2, "\r\n") == 0 ? 2 : 1));
	}
	return lines;
}

// The words of a line, separated by spaces and tabs.
std::vector<std::string_view> words_of(std::string_view line) {
	std::vector<std::string_view> words;
	for (size_t start = line.find_first_not_of(" \t"); start != std::string_view::npos;
	     start = line.find_first_not_of(" \t", start)) {
		size_t end = line.find_first_of(" \t", start);
		words.push_back(line.substr(start, end - start));
		start = end;
	}
	return words;
}

// What an index of an "f" line may refer to.
struct Element {
	const char* keyword; // the lines that define one: "v", "vt", "vn"
	const char* name;
	const char* plural;
	long long in_file = 0, before_line = 0;
};

class Obj_Checker {
public:
	Obj_Checker(const std::string& path, const std::string& text) : path(path), lines(lines_of(text)) {
		for (std::string_view line : lines) {
			std::vector<std::string_view> words = words_of(line);
			if (Element* element = defined_by(words)) element->in_file++;
		}
	}

	void check() {
		for (line_number = 1; line_number <= lines.size(); line_number++) {
			std::vector<std::string_view> words = words_of(lines[line_number - 1]);
			if (words.empty()) continue;
			if (words[0] == "v" || words[0] == "vn") check_coordinates(words);
			if (words[0] == "f") {
				for (size_t i = 1; i < words.size(); i++) check_corner(words[i]);
			}
			if (Element* element = defined_by(words)) element->before_line++;
		}
	}

private:
	[[noreturn]] void fail(const std::string& what) const {
		throw Input_Error(path + ": line " + std::to_string(line_number) + ": " + what);
	}

	Element* defined_by(const std::vector<std::string_view>& words) {
		for (Element& element : elements) {
			if (!words.empty() && words[0] == element.keyword) return &element;
		}
		return nullptr;
	}

	// "v x y z" (more numbers may follow: w, or a colour) and "vn x y z": finite as floats.
	void check_coordinates(const std::vector<std::string_view>& words) {
		const std::string form = std::string(words[0]) + " x y z";
		const char* name = words[0] == "v" ? "vertex" : "normal";
		if (words.size() < 4) {
			fail("expected three coordinates \"" + form + "\", found " + std::to_string(words.size() - 1));
		}
		for (size_t i = 1; i <= 3; i++) {
			std::string_view word = words[i].substr(words[i].rfind('+', 0) == 0 ? 1 : 0);
			double value = 0.0;
			if (!parse_decimal(word, value) || !std::isfinite(float(value))) {
				fail(std::string(name) + " coordinate '" + std::string(words[i]) + "' is not a finite number (expected \"" +
				     form + "\")");
			}
		}
	}

	// "v", "v/vt", "v//vn" or "v/vt/vn".
	void check_corner(std::string_view corner) {
		std::vector<std::string_view> parts;
		for (size_t start = 0;; ) {
			size_t slash = corner.find('/', start);
			parts.push_back(corner.substr(start, slash - start));
			if (slash == std::string_view::npos) break;
			start = slash + 1;
		}
		if (parts.size() > 3 || parts[0].empty() || (parts.size() == 3 && parts[2].empty())) {
			fail("'" + std::string(corner) + "' is not a face corner (expected v, v/vt, v//vn or v/vt/vn)");
		}
		for (size_t i = 0; i < parts.size(); i++) {
			if (!parts[i].empty()) check_index(parts[i], elements[i]);
		}
	}

	void check_index(std::string_view written, const Element& element) {
		long long index = 0;
		auto [end, status] = std::from_chars(written.data(), written.data() + written.size(), index);
		if (status != std::errc() || end != written.data() + written.size()) {
			fail("face index '" + std::string(written) + "' is not a whole number");
		}
		if ((index >= 1 && index <= element.in_file) || (index <= -1 && -index <= element.before_line)) return;
		std::string expected;
		if (element.in_file == 0) expected = "the file defines no " + std::string(element.plural);
		else expected = "expected 1 to " + std::to_string(element.in_file);
		if (element.before_line > 0) {
			expected += ", or -1 to -" + std::to_string(element.before_line) + " counting back from this line";
		}
		fail("face index " + std::string(written) + " refers to a " + element.name +
		     " the file does not define (" + expected + ")");
	}

	const std::string& path;
	std::vector<std::string_view> lines;
	size_t line_number = 0;
	Element elements[3] = {{"v", "vertex", "vertices"}, {"vt", "texture coordinate", "texture coordinates"},
	                       {"vn", "normal", "normals"}};
};

} // namespace

void check_obj_text(const std::string& path, const std::string& text) {
	Obj_Checker(path, text).check();
}
