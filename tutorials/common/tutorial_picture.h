#pragma once
// Pictures the tutorial checks draw from the student's own answers. A check paints a
// Picture and saves it as a PNG (rc::writePng, stb_image_write: no Qt) next to the
// program, or in $TUTORIAL_PICTURE_DIR, and prints its absolute path.
#include <cstdint>
#include <string>
#include <vector>

namespace tutorial {

struct Rgb {
    std::uint8_t r = 0, g = 0, b = 0;
};

/// A small colour for each label (an object id, a region, a beam): distinct neighbours,
/// the same colour for the same label on every run. -1 is the background, dark grey.
Rgb labelColour(int label);

/// `c` with its brightness scaled by `f` in [0, 1] (shading).
Rgb shade(Rgb c, double f);

class Picture {
public:
    Picture(int width, int height, Rgb fill = {});
    int width() const { return width_; }
    int height() const { return height_; }
    void set(int x, int y, Rgb c);        ///< ignores pixels outside the picture
    Rgb get(int x, int y) const;
    void circle(double cx, double cy, double r, Rgb c);  ///< a ring one pixel wide
    void disc(double cx, double cy, double r, Rgb c);    ///< filled
    /// Saves the picture `scale` times larger (each pixel a square) as
    /// <program>-<name>.png and returns the absolute path.
    std::string save(const std::string& name, int scale = 1) const;

private:
    int width_, height_;
    std::vector<Rgb> px_;
};

/// The running program's name (set by the tutorials' main from argv[0]).
extern std::string programName;

/// How many pixels of the PNG `picture` differ from those of the PNG `reference` (decoded,
/// 8-bit RGB); -1 when either cannot be read or their sizes differ.
int differingPixels(const std::string& picture, const std::string& reference);

/// Prints where a picture was written (one line a student can open).
void announcePicture(const std::string& what, const std::string& path);

}  // namespace tutorial
