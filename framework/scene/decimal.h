#pragma once
// A decimal number ("1.5", "-2e-3") that is the whole of `text`, read the same in every locale:
// false if `text` is not one. (std::from_chars for floating point is missing from clang's libc++
// before version 17, macOS's among them.)
#include <locale>
#include <sstream>
#include <string>
#include <string_view>

template<typename Real> bool parse_decimal(std::string_view text, Real& value) {
	std::istringstream in{std::string(text)};
	in.imbue(std::locale::classic());
	in >> std::noskipws >> value;
	return !in.fail() && in.peek() == std::char_traits<char>::eof();
}
