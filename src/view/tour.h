#pragma once
/// \file
/// \brief A tour: the paper told as a sequence of stops, each a caption and the whole
/// state of the viewer that illustrates it (see the Tours page of the docs).
#include <stdexcept>
#include <string>
#include <vector>

namespace rc {

/// One setting of a stop: a viewer option by its command-line name, without the dashes
/// (`cache`, `select`, `overlays`, ...), and its value ("" for a switch). Where it stands
/// in the file, for error messages.
struct TourSetting {
    std::string key, value;
    int line = 0, column = 0;
};

/// One stop: what to say and what to show.
struct TourStop {
    std::string title;
    std::string caption;  ///< one to three sentences; the paper's words in quotation marks
    std::string page;     ///< the docs page it illustrates (its label, e.g. safety_cylinder); may be empty
    std::vector<TourSetting> settings;
    /// What the stop's picture must show, each a comparison of quantities read from what
    /// it draws (view/claim.h), e.g. "right.misses < left.misses"; checked by the tests
    /// and, when the tour is opened, for names the stop does not draw.
    std::vector<std::string> claims;
    int claimsLine = 0, claimsColumn = 0;  ///< where its 'claims' key stands
    int line = 0, column = 0;  ///< where the stop's object opens
    /// The value of setting `key`, or `otherwise` when the stop does not set it.
    std::string value(const std::string& key, const std::string& otherwise = {}) const;
};

/// A parsed tour file.
struct Tour {
    std::string file;   ///< as given to loadTour()
    std::string title;
    std::vector<TourStop> stops;
};

/// A tour file that cannot be read, with `file:line:column: message` as what().
class TourError : public std::runtime_error {
public:
    TourError(const std::string& file, int line, int column, const std::string& message);
    std::string file;
    int line = 0, column = 0;
};

/// The settings a stop may hold: the viewer's options that make sense in a tour. Every
/// other key of a stop but `title`, `caption`, `page` and `claims` is an error.
const std::vector<std::string>& tourSettingNames();

/// Parses a tour from JSON text: a top-level object with an optional `title` and a
/// non-empty `stops` array of objects, each with a `title`, a `caption` and a `scene`.
/// Values are strings, numbers, `true` (a switch; `false` leaves it out) or arrays of
/// strings (joined with commas). \throws TourError naming `file` and the position.
Tour parseTour(const std::string& text, const std::string& file);
/// Reads and parses a tour file. \throws TourError (line 0 when it cannot be read).
Tour loadTour(const std::string& path);

/// The scene `stop` opens: its `scene` setting, with a relative file path resolved against
/// the folder of the tour file (a built-in name such as `cube:4` stays as it is).
std::string stopScene(const Tour& tour, const TourStop& stop);
/// Checks what parsing cannot see of stop `stop` (from 1): its scene opens; its `select`
/// pixel and `focus` rectangle lie in its image; the selected path is a ray of that pixel
/// (its scanline traced to find out); its claims name quantities it draws (view/claim.h).
/// \throws TourError at the field, "stop K (title): field: why".
void checkStop(const Tour& tour, int stop);
/// checkStop() of every stop, in order: a tour is checked whole when it is opened.
void checkTour(const Tour& tour);

}  // namespace rc
