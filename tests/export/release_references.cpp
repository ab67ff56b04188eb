// Everything the student release's text names, the release has (tests/export/test_export.sh, label
// export). Scanned: the README and the handouts (whole text), the output of `./lab help`, and the
// comments of the shipped code (.h, .cpp, .sh; not the CMake files, whose notes describe the build
// of both trees, the instructors' and the release). Checked, in each:
//   - repository paths (framework/api/camera.h, scenes/graded/, grading/judge/protocol.h, ...): the file or
//     folder exists (for a pattern such as student/task*.cpp, a name that starts like it); in a
//     Markdown link or image, the target exists relative to the document, and a #fragment names a
//     heading of the target;
//   - handout sections, §N.M: a heading "## N.M" in the handout of task N;
//   - commands, ./lab CMD: CMD is a command listed by the release's `./lab help`;
//   - functions, `name(` inside backticks in the handouts: `name` is a word of the release's
//     sources (.h, .cpp), unless qualified by std:: or a C math function (sqrt, fma, ...).
// Prints one line per wrong reference (file:line: what is named and what was expected) and exits 1 if
// there is any.
//
// usage: release_references RELEASE_DIR
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// Top-level folders of the repository: a word ending in one of these and a slash starts a path.
const char* const PATH_PATTERN =
	R"((^|[^A-Za-z0-9_./$}-])((framework|student|tests|scenes|handouts|bench|tools|cmake|tasks|prebuilt|reference|grading|notes)/[A-Za-z0-9_./-]*)(.?))";
// A path followed by one of these is a pattern (student/task*.cpp, prebuilt/libtask[1-7]_...).
const std::string PATTERN_CHARACTERS = "*[<{$";

// Functions of the C library that handouts write without std:: in formulas.
const std::set<std::string> C_MATH{"sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sqrt", "fma",
                                    "floor", "ceil", "abs", "fabs", "min", "max", "exp", "log", "pow"};

struct Line {
	std::string file; // relative to the release
	int number;
	std::string text;
};

struct Problem_List {
	std::vector<std::string> problems;
	void add(const Line& line, const std::string& message) {
		problems.push_back(line.file + ":" + std::to_string(line.number) + ": " + message);
	}
};

std::string read_text(const fs::path& path) {
	std::ifstream in(path, std::ios::binary);
	std::ostringstream text;
	text << in.rdbuf();
	return text.str();
}

std::vector<Line> lines_of(const std::string& file, const std::string& text) {
	std::vector<Line> lines;
	std::istringstream in(text);
	std::string line;
	for (int number = 1; std::getline(in, line); number++) lines.push_back({file, number, line});
	return lines;
}

// The comment part of a line of code: after "//" (not a URL's "://") in C++, after a leading "#"
// in shell and CMake files; empty if the line has none.
std::string comment_of(const std::string& line, bool cpp) {
	if (cpp) {
		for (size_t at = line.find("//"); at != std::string::npos; at = line.find("//", at + 2)) {
			if (at == 0 || line[at - 1] != ':') return line.substr(at + 2);
		}
		size_t star = line.find_first_not_of(" \t");
		if (star != std::string::npos && line.compare(star, 2, "* ") == 0) return line.substr(star + 2);
		return "";
	}
	size_t hash = line.find_first_not_of(" \t");
	if (hash == std::string::npos || line[hash] != '#' || line.compare(hash, 2, "#!") == 0) return "";
	return line.substr(hash + 1);
}

bool is_code_file(const fs::path& path, bool& cpp) {
	std::string ext = path.extension().string(), name = path.filename().string();
	cpp = ext == ".h" || ext == ".cpp";
	return cpp || ext == ".sh";
}

// Placeholders a text writes for "any task": taskN, libtaskN_reference.a.
std::string with_placeholders_filled(std::string path) {
	return std::regex_replace(path, std::regex("task(N|<N>)"), "task1");
}

std::string trimmed_path(std::string path) {
	while (!path.empty() && std::string(".,:;-").find(path.back()) != std::string::npos) path.pop_back();
	return path;
}

// The headings of a Markdown file as GitHub's anchors: lower case, punctuation dropped, spaces as '-'.
std::set<std::string> heading_anchors(const fs::path& markdown) {
	std::set<std::string> anchors;
	for (const Line& line : lines_of("", read_text(markdown))) {
		if (line.text.rfind("#", 0) != 0) continue;
		std::string title = line.text.substr(line.text.find_first_not_of('#'));
		std::string anchor;
		for (unsigned char c : title) {
			if (std::isalnum(c) || c == '_' || c == '-' || c >= 0x80) anchor += char(std::tolower(c));
			else if (c == ' ') anchor += '-';
		}
		anchors.insert(anchor.substr(anchor.find_first_not_of('-') == std::string::npos ? 0 : anchor.find_first_not_of('-')));
	}
	return anchors;
}

class Release {
public:
	explicit Release(fs::path root_) : root(std::move(root_)) {
		load_sections();
		load_commands();
		load_source_words();
	}

	// Paths written from the repository's root.
	void check_paths(const Line& line, const std::string& text, Problem_List& problems) const {
		static const std::regex path_pattern(PATH_PATTERN);
		for (std::sregex_iterator it(text.begin(), text.end(), path_pattern), end; it != end; ++it) {
			std::string path = trimmed_path((*it)[2]);
			bool pattern = PATTERN_CHARACTERS.find(std::string((*it)[4])) != std::string::npos && (*it)[4].length() == 1;
			if (pattern ? !some_name_starts_with(path) : !fs::exists(root / with_placeholders_filled(path))) {
				problems.add(line, "names " + path + ", which the release does not have (expected a file or folder of the release)");
			}
		}
	}

	// Markdown links and images, relative to the document: [text](target) or ![alt](target#fragment).
	void check_links(const Line& line, const fs::path& document, Problem_List& problems) const {
		static const std::regex link(R"(\]\(([^)\s]+)\))");
		for (std::sregex_iterator it(line.text.begin(), line.text.end(), link), end; it != end; ++it) {
			std::string target = (*it)[1];
			if (target.find("://") != std::string::npos) continue;
			std::string fragment;
			if (size_t hash = target.find('#'); hash != std::string::npos) {
				fragment = target.substr(hash + 1);
				target = target.substr(0, hash);
			}
			fs::path file = target.empty() ? document : document.parent_path() / target;
			if (!fs::exists(file)) {
				problems.add(line, "links to " + target + ", which the release does not have");
			} else if (!fragment.empty() && !heading_anchors(file).count(fragment)) {
				problems.add(line, "links to #" + fragment + ", which is no heading of " + fs::relative(file, root).string());
			}
		}
	}

	void check_sections(const Line& line, const std::string& text, Problem_List& problems) const {
		static const std::regex section(R"(§([0-9]+)(\.[0-9]+)?)");
		for (std::sregex_iterator it(text.begin(), text.end(), section), end; it != end; ++it) {
			std::string name = (*it)[0];
			std::string number = name.substr(std::string("§").size());
			if (!sections.count(number)) {
				problems.add(line, "names " + name + ", which is no heading '## " + number + " ...' of the handout of task " +
				                   std::string((*it)[1]) + " (handouts/task" + std::string((*it)[1]) + "_*.md)");
			}
		}
	}

	void check_commands(const Line& line, const std::string& text, Problem_List& problems) const {
		static const std::regex command(R"(\./lab ([a-z][a-z0-9-]*))");
		for (std::sregex_iterator it(text.begin(), text.end(), command), end; it != end; ++it) {
			if (!commands.count((*it)[1])) {
				problems.add(line, "names ./lab " + std::string((*it)[1]) + ", which is no command of the release's ./lab help");
			}
		}
	}

	// `... name(...) ...` in backticks: name must be a word of the release's sources.
	void check_functions(const Line& line, Problem_List& problems) const {
		static const std::regex code_span("`([^`]+)`");
		static const std::regex call(R"(([A-Za-z_][A-Za-z0-9_]*(?:(?:::|\.)[A-Za-z_][A-Za-z0-9_]*)*)\()");
		for (std::sregex_iterator span(line.text.begin(), line.text.end(), code_span), end; span != end; ++span) {
			std::string code = (*span)[1];
			for (std::sregex_iterator it(code.begin(), code.end(), call); it != end; ++it) {
				std::string qualified = (*it)[1];
				if (qualified.rfind("std::", 0) == 0 || C_MATH.count(qualified)) continue;
				size_t last = qualified.find_last_of(":.");
				std::string name = last == std::string::npos ? qualified : qualified.substr(last + 1);
				if (!source_words.count(name)) {
					problems.add(line, "names the function " + qualified + "(), which is in no header or source of the release");
				}
			}
		}
	}

	const fs::path root;

private:
	// For a pattern such as student/task*: a file or folder student/task...
	bool some_name_starts_with(const std::string& path) const {
		fs::path prefix = root / path;
		fs::path folder = path.back() == '/' ? prefix : prefix.parent_path();
		std::string start = path.back() == '/' ? "" : prefix.filename().string();
		if (!fs::is_directory(folder)) return false;
		for (const auto& entry : fs::directory_iterator(folder)) {
			if (entry.path().filename().string().rfind(start, 0) == 0) return true;
		}
		return false;
	}

	void load_sections() {
		static const std::regex heading(R"(^## ([0-9]+\.[0-9]+) )");
		for (const auto& entry : fs::directory_iterator(root / "handouts")) {
			std::string name = entry.path().filename().string();
			if (name.rfind("task", 0) != 0 || entry.path().extension() != ".md") continue;
			std::string task = name.substr(4, name.find('_') - 4);
			sections.insert(task);
			for (const Line& line : lines_of(name, read_text(entry.path()))) {
				std::smatch m;
				if (std::regex_search(line.text, m, heading) && m[1].str().rfind(task + ".", 0) == 0) sections.insert(m[1]);
			}
		}
	}

	// The commands of `./lab help`: its lines "  name ...".
	void load_commands() {
		std::string command = "bash '" + (root / "lab").string() + "' help";
		FILE* pipe = popen(command.c_str(), "r");
		if (!pipe) return;
		char buffer[4096];
		while (std::fgets(buffer, sizeof buffer, pipe)) help_text += buffer;
		pclose(pipe);
		static const std::regex entry(R"(^  ([a-z][a-z0-9-]*)( |$))");
		for (const Line& line : lines_of("./lab help", help_text)) {
			std::smatch m;
			if (std::regex_search(line.text, m, entry)) commands.insert(m[1]);
		}
	}

	void load_source_words() {
		static const std::regex word("[A-Za-z_][A-Za-z0-9_]*");
		for (const auto& entry : fs::recursive_directory_iterator(root)) {
			std::string ext = entry.path().extension().string();
			if (!entry.is_regular_file() || (ext != ".h" && ext != ".cpp") || in_build(entry.path())) continue;
			std::string text = read_text(entry.path());
			for (std::sregex_iterator it(text.begin(), text.end(), word), end; it != end; ++it) source_words.insert((*it)[0]);
		}
	}

public:
	bool in_build(const fs::path& path) const {
		std::string relative = fs::relative(path, root).string();
		return relative.rfind("build", 0) == 0 || relative.rfind("prebuilt", 0) == 0 || relative.rfind("out/", 0) == 0;
	}

	std::string help_text;

private:
	std::set<std::string> sections, commands, source_words;
};

void check_document(const Release& release, const fs::path& path, Problem_List& problems) {
	std::string file = fs::relative(path, release.root).string();
	for (const Line& line : lines_of(file, read_text(path))) {
		release.check_paths(line, line.text, problems);
		release.check_links(line, path, problems);
		release.check_sections(line, line.text, problems);
		release.check_commands(line, line.text, problems);
		if (file.rfind("handouts/", 0) == 0) release.check_functions(line, problems);
	}
}

void check_code_comments(const Release& release, Problem_List& problems) {
	std::vector<fs::path> files;
	for (const auto& entry : fs::recursive_directory_iterator(release.root)) {
		bool cpp = false;
		if (entry.is_regular_file() && is_code_file(entry.path(), cpp) && !release.in_build(entry.path())) {
			files.push_back(entry.path());
		}
	}
	std::sort(files.begin(), files.end());
	for (const fs::path& path : files) {
		bool cpp = false;
		is_code_file(path, cpp);
		std::string file = fs::relative(path, release.root).string();
		for (const Line& line : lines_of(file, read_text(path))) {
			std::string comment = comment_of(line.text, cpp);
			release.check_paths(line, comment, problems);
			release.check_sections(line, comment, problems);
			release.check_commands(line, comment, problems);
		}
	}
}

} // namespace

int main(int argc, char** argv) {
	if (argc != 2) {
		std::cerr << "usage: release_references RELEASE_DIR\n";
		return 2;
	}
	Release release(argv[1]);
	if (release.help_text.empty()) {
		std::cerr << "release_references: " << (release.root / "lab").string() << " help printed nothing\n";
		return 1;
	}
	Problem_List problems;
	std::vector<fs::path> documents{release.root / "README.md"};
	for (const auto& entry : fs::directory_iterator(release.root / "handouts")) {
		if (entry.path().extension() == ".md") documents.push_back(entry.path());
	}
	std::sort(documents.begin(), documents.end());
	for (const fs::path& document : documents) check_document(release, document, problems);
	for (const Line& line : lines_of("./lab help", release.help_text)) {
		release.check_paths(line, line.text, problems);
		release.check_sections(line, line.text, problems);
		release.check_commands(line, line.text, problems);
	}
	check_code_comments(release, problems);

	for (const std::string& problem : problems.problems) std::cout << problem << "\n";
	if (!problems.problems.empty()) {
		std::cout << problems.problems.size() << " references in the release name what it does not have\n";
		return 1;
	}
	std::cout << "release_references: every path, §section, ./lab command and function that the release's "
	             "text names exists in it\n";
	return 0;
}
