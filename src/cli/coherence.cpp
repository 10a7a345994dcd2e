// placeholder
#include "cli/commands.h"
namespace rc::cli {
void addCoherenceCommand(CLI::App&, Commands&) {}
}
