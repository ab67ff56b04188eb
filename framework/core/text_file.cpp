#include "text_file.h"
#include "error.h"

#include <filesystem>
#include <fstream>
#include <iterator>

std::string read_text_file(const std::string& path) {
	std::error_code ec;
	if (!std::filesystem::is_regular_file(path, ec)) {
		throw Input_Error(path + ": cannot read the file (it does not exist or is not a regular file)");
	}
	std::ifstream in(path, std::ios::binary);
	if (!in) throw Input_Error(path + ": cannot open the file for reading");
	std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
	if (in.bad()) throw Input_Error(path + ": cannot read the file");
	return text;
}
