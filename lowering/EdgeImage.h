// EdgePolicy::PerObject (ir/Profile.h): the previous-scan image of every edge object, sampled at
// the end of every run of the cyclic part (twin of interp/Interpreter.cpp runPlc1).
#pragma once

#include "lowering/FunctionEmitter.h"

namespace lj::lower {

/// Whether the program has an object edge image to sample (VerifiedProgram::edgeObjects).
bool hasEdgeImage(const VerifiedProgram &prog);

/// Fills `entry` (ctx, state) -> status: calls `body` (same signature), then copies each edge
/// object's bit into its edge slot, then returns the body's status.
void emitEdgeImageEntry(ModuleContext &mc, llvm::Function *entry, llvm::Function *body);

} // namespace lj::lower
