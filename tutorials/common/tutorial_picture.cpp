#include "tutorial_picture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

#include "render/output_files.h"

namespace tutorial {

std::string programName = "tutorial";

Rgb labelColour(int label) {
    if (label < 0) return {40, 40, 48};
    // Golden-ratio hues: neighbouring labels get far-apart colours. Hues stop short of
    // magenta (300 degrees), which the checks keep for wrong answers.
    const double h = std::fmod(0.13 + 0.618033988749895 * label, 1.0) * 4.4;
    const double s = label % 2 ? 0.55 : 0.75, v = label % 3 == 1 ? 0.80 : 0.95;
    const int i = int(h);
    const double f = h - i, p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    double r = v, g = t, b = p;
    switch (i % 6) {
        case 1: r = q, g = v, b = p; break;
        case 2: r = p, g = v, b = t; break;
        case 3: r = p, g = q, b = v; break;
        case 4: r = t, g = p, b = v; break;
        case 5: r = v, g = p, b = q; break;
        default: break;
    }
    return {std::uint8_t(255 * r), std::uint8_t(255 * g), std::uint8_t(255 * b)};
}

Rgb shade(Rgb c, double f) {
    f = std::clamp(f, 0.0, 1.0);
    return {std::uint8_t(c.r * f), std::uint8_t(c.g * f), std::uint8_t(c.b * f)};
}

Picture::Picture(int width, int height, Rgb fill)
    : width_(width), height_(height), px_(std::size_t(width) * height, fill) {}

void Picture::set(int x, int y, Rgb c) {
    if (x >= 0 && y >= 0 && x < width_ && y < height_) px_[std::size_t(y) * width_ + x] = c;
}

Rgb Picture::get(int x, int y) const { return px_[std::size_t(y) * width_ + x]; }

void Picture::circle(double cx, double cy, double r, Rgb c) {
    const int n = std::max(16, int(8 * r));
    for (int i = 0; i < n; ++i) {
        const double a = 2 * M_PI * i / n;
        set(int(std::floor(cx + r * std::cos(a))), int(std::floor(cy + r * std::sin(a))), c);
    }
}

void Picture::disc(double cx, double cy, double r, Rgb c) {
    for (int y = int(std::floor(cy - r)); y <= int(std::ceil(cy + r)); ++y)
        for (int x = int(std::floor(cx - r)); x <= int(std::ceil(cx + r)); ++x)
            if ((x + 0.5 - cx) * (x + 0.5 - cx) + (y + 0.5 - cy) * (y + 0.5 - cy) <= r * r) set(x, y, c);
}

std::string Picture::save(const std::string& name, int scale) const {
    std::vector<std::uint8_t> rgb;
    rgb.reserve(std::size_t(width_) * height_ * scale * scale * 3);
    for (int y = 0; y < height_ * scale; ++y)
        for (int x = 0; x < width_ * scale; ++x) {
            const Rgb c = get(x / scale, y / scale);
            rgb.insert(rgb.end(), {c.r, c.g, c.b});
        }
    const char* dir = std::getenv("TUTORIAL_PICTURE_DIR");
    const std::filesystem::path folder = dir && *dir ? dir : ".";
    std::filesystem::create_directories(folder);
    const std::filesystem::path file = folder / (programName + "-" + name + ".png");
    rc::writePng(file.string(), width_ * scale, height_ * scale, rgb);
    return std::filesystem::absolute(file).lexically_normal().string();
}

void announcePicture(const std::string& what, const std::string& path) {
    std::printf("Picture (%s): %s\n", what.c_str(), path.c_str());
}

int differingPixels(const std::string& picture, const std::string& reference) {
    int w[2], h[2], channels;
    unsigned char* px[2] = {stbi_load(picture.c_str(), &w[0], &h[0], &channels, 3),
                            stbi_load(reference.c_str(), &w[1], &h[1], &channels, 3)};
    int differ = -1;
    if (px[0] && px[1] && w[0] == w[1] && h[0] == h[1]) {
        differ = 0;
        for (int i = 0; i < w[0] * h[0]; ++i)
            differ += px[0][3 * i] != px[1][3 * i] || px[0][3 * i + 1] != px[1][3 * i + 1] || px[0][3 * i + 2] != px[1][3 * i + 2];
    }
    for (unsigned char* p : px)
        if (p) stbi_image_free(p);
    return differ;
}

}  // namespace tutorial
