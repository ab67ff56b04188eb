#pragma once
// SHA-256 (FIPS 180-4) of a file, as lowercase hex: the checksums with which the graders check their
// reference images and test data (graded_images.h).
#include <string>

std::string sha256_of_bytes(const std::string& bytes);
std::string sha256_of_file(const std::string& path); // throws Input_Error if it cannot be read
