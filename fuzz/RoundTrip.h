// The ladder round trip as an engine under test (`ladderjit fuzz --round-trip`).
#pragma once

#include "fuzz/Fuzz.h"
#include "ir/Engine.h"
#include "ladder/Network.h"

#include <memory>

namespace lj::fuzz {

/// Builds, for each program, the interpreter on its round-tripped twin (STL -> networks -> JSON
/// text -> networks -> STL -> verify); for a FANUC or IEC program, checks that networks -> JSON
/// -> networks holds exactly its statements (an engine error otherwise) and runs the program
/// itself. Adds each program's rung counts to `counts` if given.
EngineFactory roundTripFactory(std::shared_ptr<ladder::RungCounts> counts);

} // namespace lj::fuzz
