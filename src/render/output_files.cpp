#include "render/output_files.h"

#include <filesystem>
#include <fstream>
#include <system_error>

#include <unistd.h>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace rc {

namespace {
// Write to a temporary file beside the target, then rename it over the target; write a
// device or a pipe in place (a rename would replace it)
template <class Write>
void atomically(const std::string& path, Write write) {
    std::error_code ec;
    const std::filesystem::file_status target = std::filesystem::status(path, ec);
    if (std::filesystem::exists(target) && !std::filesystem::is_regular_file(target)) {
        if (!write(path)) throw OutputError(path + ": cannot write file");
        return;
    }
    const std::string tmp = path + ".tmp." + std::to_string(::getpid());
    if (!write(tmp)) {
        std::filesystem::remove(tmp, ec);
        throw OutputError(path + ": cannot write file");
    }
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::filesystem::remove(tmp, ec);
        throw OutputError(path + ": cannot write file (" + ec.message() + ")");
    }
}
}  // namespace

void writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb) {
    // Encoded in memory, then written and closed like any file: stb's own file writer
    // does not report a write that fails when the file is closed
    std::string png;
    const auto append = [](void* to, void* data, int size) {
        static_cast<std::string*>(to)->append(static_cast<const char*>(data), std::size_t(size));
    };
    if (stbi_write_png_to_func(append, &png, width, height, 3, rgb.data(), width * 3) == 0)
        throw OutputError(path + ": cannot encode the image");
    writeTextFile(path, png);
}

void writePpm(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb) {
    std::string ppm = "P6\n" + std::to_string(width) + " " + std::to_string(height) + "\n255\n";
    ppm.append(rgb.begin(), rgb.end());
    writeTextFile(path, ppm);
}

void writeImage(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb) {
    if (path.ends_with(".ppm"))
        writePpm(path, width, height, rgb);
    else
        writePng(path, width, height, rgb);
}

void writeTextFile(const std::string& path, const std::string& text) {
    atomically(path, [&](const std::string& to) {
        std::ofstream out(to, std::ios::binary);
        out << text;
        out.close();
        return bool(out);
    });
}

}  // namespace rc
