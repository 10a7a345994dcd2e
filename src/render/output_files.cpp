#include "render/output_files.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include <unistd.h>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace rc {

namespace {
// Write to a temporary file beside the target, then rename it over the target
template <class Write>
void atomically(const std::string& path, Write write) {
    const std::string tmp = path + ".tmp." + std::to_string(::getpid());
    if (!write(tmp)) {
        std::error_code ec;
        std::filesystem::remove(tmp, ec);
        throw std::runtime_error(path + ": cannot write file");
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::filesystem::remove(tmp, ec);
        throw std::runtime_error(path + ": cannot write file (" + ec.message() + ")");
    }
}
}  // namespace

void writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb) {
    atomically(path, [&](const std::string& tmp) {
        return stbi_write_png(tmp.c_str(), width, height, 3, rgb.data(), width * 3) != 0;
    });
}

void writeTextFile(const std::string& path, const std::string& text) {
    atomically(path, [&](const std::string& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        out.close();
        return bool(out);
    });
}

}  // namespace rc
