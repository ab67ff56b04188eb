// Finds solution code by function (the export test, tests/export/test_export.sh): every function of
// the solution sources (reference/, the framework's shipped-compiled sources) is compared with every
// function of the release's sources; a release function that contains most of a solution function's code,
// even with other names, is reported.
//
//   solution_scan --solution FILE... --release FILE...
//
// Code is compared as tokens with comments and preprocessor lines removed, every identifier
// replaced by one symbol and every literal by another, so renaming does not hide a copy. A
// solution function of at least MIN_TOKENS tokens is "found" in a release function when at least
// CONTAINED of its runs of SHINGLE consecutive tokens occur there. Exit status 1 if any is found.
#include <algorithm>
#include <cctype>
#include <fstream>
#include <iostream>
#include <iterator>
#include <set>
#include <string>
#include <unordered_set>
#include <vector>

namespace {

constexpr size_t SHINGLE = 12;
constexpr size_t MIN_TOKENS = 40;
constexpr double CONTAINED = 0.5;

const std::set<std::string> KEYWORDS{"if",     "else",  "for",   "while",    "do",     "return", "switch", "case",
                                     "break",  "const", "auto",  "float",    "double", "int",    "bool",   "void",
                                     "size_t", "true",  "false", "continue", "struct", "static", "constexpr"};

struct Token {
	std::string text;       // as written
	std::string normalized; // identifiers and literals folded
};

struct Function {
	std::string file, name;
	size_t line = 0;
	std::vector<Token> tokens; // of its body
};

// Tokens of C++ source without comments and preprocessor lines, with the line of each.
std::vector<std::pair<Token, size_t>> tokenize(const std::string& source) {
	std::vector<std::pair<Token, size_t>> tokens;
	size_t i = 0, line = 1;
	bool line_start = true;
	auto add = [&](std::string text, std::string normalized) { tokens.push_back({{std::move(text), std::move(normalized)}, line}); };
	while (i < source.size()) {
		char c = source[i];
		if (c == '\n') {
			line++, i++, line_start = true;
			continue;
		}
		if (std::isspace(static_cast<unsigned char>(c))) {
			i++;
			continue;
		}
		if (line_start && c == '#') { // a preprocessor line, with its continuations
			while (i < source.size() && !(source[i] == '\n' && source[i - 1] != '\\')) i++;
			continue;
		}
		line_start = false;
		if (source.compare(i, 2, "//") == 0) {
			while (i < source.size() && source[i] != '\n') i++;
			continue;
		}
		if (source.compare(i, 2, "/*") == 0) {
			size_t end = source.find("*/", i + 2);
			end = end == std::string::npos ? source.size() : end + 2;
			line += size_t(std::count(source.begin() + long(i), source.begin() + long(end), '\n'));
			i = end;
			continue;
		}
		if (c == '"' || c == '\'') {
			size_t j = i + 1;
			while (j < source.size() && source[j] != c) j += source[j] == '\\' ? 2 : 1;
			add(source.substr(i, j + 1 - i), "L");
			i = j + 1;
			continue;
		}
		if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
			size_t j = i;
			while (j < source.size() && (std::isalnum(static_cast<unsigned char>(source[j])) || source[j] == '_')) j++;
			std::string word = source.substr(i, j - i);
			add(word, KEYWORDS.count(word) ? word : "I");
			i = j;
			continue;
		}
		if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && i + 1 < source.size() && std::isdigit(static_cast<unsigned char>(source[i + 1])))) {
			size_t j = i;
			while (j < source.size() && (std::isalnum(static_cast<unsigned char>(source[j])) || source[j] == '.' ||
			                             ((source[j] == '-' || source[j] == '+') && (source[j - 1] == 'e' || source[j - 1] == 'E')))) {
				j++;
			}
			add(source.substr(i, j - i), "L");
			i = j;
			continue;
		}
		add(std::string(1, c), std::string(1, c));
		i++;
	}
	return tokens;
}

// Every function body: a `{` after the `)` of a parameter list (not of if/for/while/switch/catch),
// possibly with const, noexcept, override or a trailing return type between.
std::vector<Function> functions(const std::string& file) {
	std::ifstream in(file);
	std::string source((std::istreambuf_iterator<char>(in)), {});
	auto tokens = tokenize(source);
	std::vector<Function> found;
	for (size_t i = 0; i < tokens.size(); i++) {
		if (tokens[i].first.text != "{") continue;
		size_t j = i;
		while (j > 0 && (tokens[j - 1].first.text == "const" || tokens[j - 1].first.text == "noexcept" ||
		                 tokens[j - 1].first.text == "override" || tokens[j - 1].first.text == "mutable")) {
			j--;
		}
		if (j == 0 || tokens[j - 1].first.text != ")") continue;
		size_t depth = 0, k = j - 1;
		for (;; k--) {
			if (tokens[k].first.text == ")") depth++;
			if (tokens[k].first.text == "(" && --depth == 0) break;
			if (k == 0) break;
		}
		std::string before = k > 0 ? tokens[k - 1].first.text : "";
		if (before == "if" || before == "for" || before == "while" || before == "switch" || before == "catch") continue;
		Function f{file, before, tokens[i].second, {}};
		size_t level = 0;
		for (size_t m = i; m < tokens.size(); m++) {
			f.tokens.push_back(tokens[m].first);
			if (tokens[m].first.text == "{") level++;
			if (tokens[m].first.text == "}" && --level == 0) break;
		}
		found.push_back(std::move(f));
	}
	return found;
}

std::unordered_set<std::string> shingles(const std::vector<Token>& tokens) {
	std::unordered_set<std::string> set;
	for (size_t i = 0; i + SHINGLE <= tokens.size(); i++) {
		std::string key;
		for (size_t j = i; j < i + SHINGLE; j++) key += tokens[j].normalized + " ";
		set.insert(key);
	}
	return set;
}

} // namespace

int main(int argc, char** argv) {
	std::vector<std::string> solution_files, release_files;
	std::vector<std::string>* list = nullptr;
	for (int i = 1; i < argc; i++) {
		std::string arg = argv[i];
		if (arg == "--solution") list = &solution_files;
		else if (arg == "--release") list = &release_files;
		else if (list) list->push_back(arg);
	}
	if (solution_files.empty() || release_files.empty()) {
		std::cerr << "usage: solution_scan --solution FILE... --release FILE...\n";
		return 2;
	}
	struct Candidate {
		Function function;
		std::unordered_set<std::string> shingles;
	};
	std::vector<Candidate> release;
	for (const std::string& file : release_files) {
		for (Function& f : functions(file)) {
			auto set = shingles(f.tokens);
			release.push_back({std::move(f), std::move(set)});
		}
	}
	size_t checked = 0, found = 0;
	for (const std::string& file : solution_files) {
		for (const Function& f : functions(file)) {
			if (f.tokens.size() < MIN_TOKENS) continue;
			checked++;
			auto own = shingles(f.tokens);
			for (const Candidate& c : release) {
				size_t common = 0;
				for (const std::string& s : own) common += c.shingles.count(s);
				double contained = double(common) / double(own.size());
				if (contained >= CONTAINED) {
					found++;
					std::cout << c.function.file << ":" << c.function.line << " (" << c.function.name << ") holds "
					          << int(100.0 * contained) << "% of the solution function " << f.name << " ("
					          << f.file << ":" << f.line << ")\n";
				}
			}
		}
	}
	std::cout << "solution_scan: " << checked << " solution functions of at least " << MIN_TOKENS
	          << " tokens compared with " << release.size() << " functions of " << release_files.size()
	          << " release files; " << found << " found\n";
	return found == 0 ? 0 : 1;
}
