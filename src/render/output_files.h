#pragma once
/// \file
/// \brief Writing results: PNG images and text files, atomically (temporary file, rename).
#include <cstdint>
#include <string>
#include <vector>

namespace rc {

/// Writes an 8-bit RGB image as PNG. Throws std::runtime_error naming the file.
void writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb);

/// Writes text to a file; an interrupted write never leaves a truncated file behind.
void writeTextFile(const std::string& path, const std::string& text);

}  // namespace rc
