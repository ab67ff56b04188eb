// lab_source_check: what the compiler saw of a student's task file must be C++ that the compiler
// translates, nothing that places bytes or names symbols by hand (grading/bin/compile-student).
//
//   lab_source_check PREPROCESSED.ii SOURCE
//
// PREPROCESSED is the compiler's preprocessed output of SOURCE (g++ -E, with its line markers), so
// every macro is already expanded: a check of the text a student typed could be dodged by a macro,
// this one cannot. Only the lines that come from SOURCE are checked (the system's and the
// framework's headers are not the student's). Refused, each named with its line:
//   - asm in any spelling (asm, __asm, __asm__): machine code or assembler directives (.incbin,
//     .byte, .symver) instead of C++;
//   - attributes that place code or data, or name or replace symbols: section, alias, weakref, weak,
//     ifunc, target_clones, target_version, symver, naked, noinit, persistent, init_priority,
//     constructor, destructor, copy;
//   - pragmas but for diagnostics, packing and loop hints (#pragma weak and redefine_extname rename
//     symbols).
//   - line directives (#line, or GCC's "# N file" markers) in the file itself: they would make its
//     own lines look like a header's, whose lines are not checked (so SOURCE is read too).
// Exits 0 when nothing is refused, 1 after listing what is (on stderr), 2 on a usage error.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <algorithm>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

const std::set<std::string> ASM = {"asm", "__asm", "__asm__"};

// Attribute names, without the __x__ spelling (name() strips it).
const std::set<std::string> REFUSED_ATTRIBUTES = {
	"section",   "alias",    "weakref",    "weak",          "ifunc",      "target_clones", "target_version",
	"symver",    "naked",    "noinit",     "persistent",    "init_priority", "constructor", "destructor", "copy"};

// The first word (or two, for GCC's and clang's) of the pragmas a task file may use.
const std::set<std::string> ALLOWED_PRAGMAS = {"once", "GCC diagnostic", "clang diagnostic", "pack", "GCC unroll",
                                               "GCC ivdep", "unroll"};

bool is_identifier_start(char c) {
	return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool is_identifier_char(char c) {
	return is_identifier_start(c) || (c >= '0' && c <= '9');
}

// __section__ -> section
std::string name(const std::string& word) {
	if (word.size() > 4 && word.compare(0, 2, "__") == 0 && word.compare(word.size() - 2, 2, "__") == 0) {
		return word.substr(2, word.size() - 4);
	}
	return word;
}

struct Token {
	std::string text;
	bool identifier = false;
	size_t line = 0; // in SOURCE
};

// The tokens of SOURCE's lines of the preprocessed text, and its pragma lines. The tokenizer knows
// what a student's C++ can hold after preprocessing: identifiers, numbers (with ' separators),
// string and character literals (raw ones too), punctuation; comments are gone.
class Reader {
public:
	Reader(const std::string& text, const std::string& source) : text(text), source(source) {
	}

	void read() {
		while (at < text.size()) {
			if (line_start && text[at] == '#') {
				directive();
				continue;
			}
			char c = text[at];
			if (c == '\n') {
				line++;
				at++;
				line_start = true;
				continue;
			}
			if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
				at++;
				continue;
			}
			line_start = false;
			size_t start = at;
			if (is_identifier_start(c)) {
				while (at < text.size() && is_identifier_char(text[at])) at++;
				std::string word = text.substr(start, at - start);
				if (at < text.size() && (text[at] == '"' || text[at] == '\'') && is_literal_prefix(word)) {
					literal(word.back() == 'R');
					continue;
				}
				emit(word, true);
			} else if (c >= '0' && c <= '9') {
				number();
			} else if (c == '"' || c == '\'') {
				literal(false);
			} else {
				at++;
				emit(std::string(1, c), false);
			}
		}
	}

	std::vector<Token> tokens;
	std::vector<std::pair<size_t, std::string>> pragmas; // line, text after "#pragma"
	bool saw_source = false; // a line marker named the source

private:
	static bool is_literal_prefix(const std::string& word) {
		for (const char* prefix : {"L", "u", "U", "u8", "R", "LR", "uR", "UR", "u8R"}) {
			if (word == prefix) return true;
		}
		return false;
	}
	void emit(const std::string& token, bool identifier) {
		if (in_source) tokens.push_back(Token{token, identifier, line});
	}
	// A line marker (# N "file" flags), or a directive the preprocessor kept (#pragma, #ident).
	void directive() {
		size_t end = text.find('\n', at);
		if (end == std::string::npos) end = text.size();
		std::string content = text.substr(at + 1, end - at - 1);
		at = end; // the newline is read as one
		std::istringstream words(content);
		std::string first;
		words >> first;
		if (!first.empty() && first[0] >= '0' && first[0] <= '9') {
			size_t quote = content.find('"'), last = content.rfind('"');
			std::string file = quote != std::string::npos && last > quote ? content.substr(quote + 1, last - quote - 1) : "";
			in_source = file == source;
			saw_source = saw_source || in_source;
			line = std::stoul(first) - 1; // the next line is number `first`
			return;
		}
		if (first == "line") return;
		if (in_source && first == "pragma") {
			std::string rest;
			std::getline(words, rest);
			size_t begin = rest.find_first_not_of(" \t");
			pragmas.emplace_back(line, begin == std::string::npos ? "" : rest.substr(begin));
		}
	}
	void number() {
		// A pp-number: digits, letters, '.', exponent signs, and ' between digits.
		while (at < text.size()) {
			char c = text[at];
			if (is_identifier_char(c) || c == '.') {
				at++;
			} else if ((c == '+' || c == '-') && (text[at - 1] == 'e' || text[at - 1] == 'E' || text[at - 1] == 'p' ||
			                                      text[at - 1] == 'P')) {
				at++;
			} else if (c == '\'' && at + 1 < text.size() && is_identifier_char(text[at + 1])) {
				at++;
			} else {
				break;
			}
		}
	}
	// A string or character literal from its opening quote; raw strings end at )delimiter".
	void literal(bool raw) {
		char quote = text[at++];
		if (raw) {
			size_t open = text.find('(', at);
			if (open == std::string::npos) { at = text.size(); return; }
			std::string end = ")" + text.substr(at, open - at) + "\"";
			size_t close = text.find(end, open);
			size_t stop = close == std::string::npos ? text.size() : close + end.size();
			for (size_t i = at; i < stop; i++) line += text[i] == '\n';
			at = stop;
			return;
		}
		while (at < text.size() && text[at] != quote && text[at] != '\n') at += text[at] == '\\' ? 2 : 1;
		at = std::min(at + 1, text.size());
	}

	const std::string& text;
	const std::string source;
	size_t at = 0, line = 0;
	bool line_start = true, in_source = false;
};

struct Refusal {
	size_t line;
	std::string what;
};

// The source's text as the preprocessor reads its directives (C++ translation phases 2 and 3):
// backslash-newlines spliced, comments replaced by a space, string and character literals kept
// whole; a spliced line keeps its newline count at its end, so that line numbers stay right.
std::string without_comments(const std::string& text) {
	std::string spliced, out;
	size_t pending = 0; // newlines removed by splicing, put back at the end of the logical line
	for (size_t i = 0; i < text.size(); i++) {
		if (text[i] == '\\' && i + 1 < text.size() && text[i + 1] == '\n') {
			pending++, i++;
			continue;
		}
		spliced += text[i];
		if (text[i] == '\n') spliced.append(pending, '\n'), pending = 0;
	}
	for (size_t i = 0; i < spliced.size(); i++) {
		char c = spliced[i];
		if (c == '/' && i + 1 < spliced.size() && spliced[i + 1] == '/') {
			while (i < spliced.size() && spliced[i] != '\n') i++;
			out += '\n';
		} else if (c == '/' && i + 1 < spliced.size() && spliced[i + 1] == '*') {
			size_t end = spliced.find("*/", i + 2);
			end = end == std::string::npos ? spliced.size() : end + 2;
			for (size_t k = i; k < end; k++) if (spliced[k] == '\n') out += '\n';
			out += ' ';
			i = end - 1;
		} else if (c == '"' || c == '\'') {
			size_t k = i + 1;
			while (k < spliced.size() && spliced[k] != c && spliced[k] != '\n') k += spliced[k] == '\\' ? 2 : 1;
			out += spliced.substr(i, std::min(k + 1, spliced.size()) - i);
			i = k;
		} else {
			out += c;
		}
	}
	return out;
}

// The line directives of the source itself: a line whose first token is # (or %:) and whose next is
// a number or `line`.
void check_line_directives(const std::string& source_text, std::vector<Refusal>& refused) {
	std::istringstream lines(without_comments(source_text));
	size_t number = 0;
	for (std::string line; std::getline(lines, line);) {
		number++;
		size_t at = line.find_first_not_of(" \t\f\v\r");
		if (at == std::string::npos) continue;
		if (line.compare(at, 1, "#") == 0) at += 1;
		else if (line.compare(at, 2, "%:") == 0) at += 2;
		else continue;
		at = line.find_first_not_of(" \t\f\v\r", at);
		if (at == std::string::npos) continue;
		if ((line[at] >= '0' && line[at] <= '9') ||
		    (line.compare(at, 4, "line") == 0 && (at + 4 == line.size() || !is_identifier_char(line[at + 4])))) {
			refused.push_back({number, "a line directive, which would make the lines after it look like another file's"});
		}
	}
}

// The attribute-specifier opened at tokens[i] (the "(" after __attribute__, or the first "[" of
// "[["): every attribute name in it is checked, up to the bracket that closes it.
void check_attribute(const std::vector<Token>& tokens, size_t i, std::vector<Refusal>& refused) {
	const std::string open = tokens[i].text, close = open == "(" ? ")" : "]";
	int depth = 0;
	for (size_t j = i; j < tokens.size(); j++) {
		const Token& t = tokens[j];
		depth += t.text == open ? 1 : t.text == close ? -1 : 0;
		if (t.identifier && REFUSED_ATTRIBUTES.count(name(t.text))) {
			refused.push_back({t.line, "the attribute '" + t.text + "', which places code or data or names symbols by hand"});
		}
		if (depth == 0) return;
	}
}

} // namespace

std::string read_whole(const char* path, bool& ok) {
	std::ifstream in(path, std::ios::binary);
	ok = bool(in);
	return std::string((std::istreambuf_iterator<char>(in)), {});
}

int main(int argc, char** argv) {
	if (argc != 3) {
		std::cerr << "usage: lab_source_check PREPROCESSED.ii SOURCE\n";
		return 2;
	}
	bool preprocessed_ok = false, source_ok = false;
	std::string text = read_whole(argv[1], preprocessed_ok), source_text = read_whole(argv[2], source_ok);
	if (!preprocessed_ok || !source_ok) {
		std::cerr << "lab_source_check: cannot read " << (preprocessed_ok ? argv[2] : argv[1]) << "\n";
		return 2;
	}
	std::string source = argv[2];
	Reader reader(text, source);
	reader.read();
	if (!reader.saw_source) {
		// Never a pass by default: the preprocessed text names its source as the compile was given it.
		std::cerr << "lab_source_check: " << argv[1] << " has no line of " << source << "\n";
		return 2;
	}

	std::vector<Refusal> refused;
	check_line_directives(source_text, refused);
	const std::vector<Token>& tokens = reader.tokens;
	for (size_t i = 0; i < tokens.size(); i++) {
		const Token& t = tokens[i];
		if (t.identifier && ASM.count(t.text)) {
			refused.push_back({t.line, "'" + t.text + "': assembly in a task file (only C++ is compiled and graded)"});
		} else if (t.identifier && (t.text == "__attribute__" || t.text == "__attribute") && i + 1 < tokens.size() &&
		           tokens[i + 1].text == "(") {
			check_attribute(tokens, i + 1, refused);
		} else if (t.text == "[" && i + 1 < tokens.size() && tokens[i + 1].text == "[") {
			check_attribute(tokens, i, refused);
			for (int depth = 0; i < tokens.size(); i++) { // on past it: its inner "[" is not another one
				depth += tokens[i].text == "[" ? 1 : tokens[i].text == "]" ? -1 : 0;
				if (depth == 0) break;
			}
		}
	}
	for (const auto& [line, pragma] : reader.pragmas) {
		std::istringstream words(pragma);
		std::string first, second;
		words >> first >> second;
		if (!ALLOWED_PRAGMAS.count(first) && !ALLOWED_PRAGMAS.count(first + " " + second)) {
			refused.push_back({line, "'#pragma " + pragma + "' (a task file may use only #pragma GCC diagnostic, pack and loop hints)"});
		}
	}
	for (const Refusal& r : refused) std::cerr << source << ":" << r.line << ": refused: " << r.what << "\n";
	if (!refused.empty()) {
		std::cerr << source << ": a task file must be C++ that the compiler translates: no assembly, no attributes that "
		                       "place code or name symbols, no pragmas but diagnostics, no line directives"
		          << "\n";
		return 1;
	}
	return 0;
}
