#pragma once
/// \file
/// \brief Writing results: PNG and PPM images and text files, atomically (temporary file, rename).
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace rc {

/// An output file that could not be written; the message names it.
struct OutputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// A regular file (or a new one) is written to a temporary file beside it and renamed
/// over it; anything else that exists there (a device, a pipe) is written in place, never
/// replaced. Both throw OutputError naming the file when the write fails.
///
/// Writes an 8-bit RGB image as PNG.
void writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb);

/// Writes an 8-bit RGB image as binary PPM (P6): a short header, then the pixel bytes
/// as they are, rows top to bottom.
void writePpm(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb);

/// writePpm() when `path` ends in .ppm, else writePng().
void writeImage(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb);

/// Writes text (or any bytes) to a file; an interrupted write never leaves a truncated
/// file behind.
void writeTextFile(const std::string& path, const std::string& text);

}  // namespace rc
