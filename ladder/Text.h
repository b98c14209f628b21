// The readable text form of networks (`ladderjit ladder --format text`).
#pragma once

#include "ladder/Network.h"

#include <string>

namespace lj::ladder {

/// Every part and rung: comments, the network as an indented series/parallel drawing, STL rungs
/// verbatim, markers as `--- IEND ---` lines.
std::string renderText(const Networks &nets);

} // namespace lj::ladder
