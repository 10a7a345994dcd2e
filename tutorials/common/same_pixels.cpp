// same_pixels A.png B.png: whether two pictures show the same pixels. Exit 0 when both
// decode to the same size and the same 8-bit RGB values, 1 when they differ, 2 when one
// cannot be read. Compares what the PNGs show, not their bytes: another zlib may
// compress the same pixels differently.
#include <cstdio>
#include <cstring>

#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: same_pixels A.png B.png\n");
        return 2;
    }
    int w[2], h[2], channels;
    unsigned char* pixels[2];
    for (int i = 0; i < 2; ++i) {
        pixels[i] = stbi_load(argv[1 + i], &w[i], &h[i], &channels, 3);
        if (!pixels[i]) {
            std::fprintf(stderr, "same_pixels: %s: %s\n", argv[1 + i], stbi_failure_reason());
            return 2;
        }
    }
    const bool same = w[0] == w[1] && h[0] == h[1] && std::memcmp(pixels[0], pixels[1], std::size_t(w[0]) * h[0] * 3) == 0;
    if (!same) std::fprintf(stderr, "same_pixels: %s (%dx%d) and %s (%dx%d) differ\n", argv[1], w[0], h[0], argv[2], w[1], h[1]);
    stbi_image_free(pixels[0]);
    stbi_image_free(pixels[1]);
    return same ? 0 : 1;
}
