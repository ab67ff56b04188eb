#pragma once
// Small pieces of HTML for the grade report.
#include <filesystem>
#include <string>
#include <string_view>

// Text as HTML: &, <, >, " and ' escaped.
std::string escape(std::string_view text);

// Base64 (RFC 4648, with padding).
std::string base64(std::string_view bytes);

// A PNG file as a data: URI, so that the page needs no other file; empty if it cannot be read.
std::string png_data_uri(const std::filesystem::path& file);
