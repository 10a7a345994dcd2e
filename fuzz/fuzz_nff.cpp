// libFuzzer target: rc::parseNff on arbitrary bytes. It must return a scene that keeps
// the reader's promises or throw an rc::SceneError at a valid file:line:column; any other
// exception, a crash, a sanitizer report, a hang (-timeout) or a runaway allocation
// (-malloc_limit_mb) is a finding. Run it with scripts/fuzz.sh.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::string file = "fuzz.nff";
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        rc::fuzz::checkScene(rc::parseNff(text, file));
    } catch (const rc::SceneError& e) {
        rc::fuzz::checkError(e, file);
    }
    return 0;
}
