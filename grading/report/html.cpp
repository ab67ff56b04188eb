#include "html.h"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iterator>

std::string escape(std::string_view text) {
	std::string html;
	html.reserve(text.size());
	for (char c : text) {
		switch (c) {
		case '&': html += "&amp;"; break;
		case '<': html += "&lt;"; break;
		case '>': html += "&gt;"; break;
		case '"': html += "&quot;"; break;
		case '\'': html += "&#39;"; break;
		default: html += c;
		}
	}
	return html;
}

// Every 3 bytes become 4 characters of 6 bits each; '=' pads the last group to 4 characters.
std::string base64(std::string_view bytes) {
	static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
	std::string text;
	text.reserve((bytes.size() + 2) / 3 * 4);
	for (size_t i = 0; i < bytes.size(); i += 3) {
		size_t n = std::min<size_t>(3, bytes.size() - i);
		uint32_t group = 0;
		for (size_t k = 0; k < 3; k++) group = group << 8 | (k < n ? uint8_t(bytes[i + k]) : 0u);
		for (size_t k = 0; k < 4; k++) text += k <= n ? digits[(group >> (18 - 6 * k)) & 63] : '=';
	}
	return text;
}

std::string png_data_uri(const std::filesystem::path& file) {
	std::ifstream in(file, std::ios::binary);
	if (!in) return "";
	std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
	if (bytes.empty()) return "";
	return "data:image/png;base64," + base64(bytes);
}
