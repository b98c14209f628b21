// The ladder round trip as an engine under test (`ladderjit fuzz --round-trip`).
#pragma once

#include "fuzz/Fuzz.h"
#include "ir/Engine.h"
#include "ladder/Network.h"

#include <memory>

namespace lj::fuzz {

/// Builds, for each program, the interpreter on its round-tripped twin (STL -> networks -> JSON
/// text -> networks -> STL -> verify). Adds each program's rung counts to `counts` if given.
EngineFactory roundTripFactory(std::shared_ptr<ladder::RungCounts> counts);

} // namespace lj::fuzz
