// Between the two halves of the AOT build: code generation (jit/Aot.cpp) and linking with the
// system compiler (jit/AotLink.cpp).
#pragma once

#include "jit/Aot.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace lj::jit::detail {

/// Link the program object `obj` with the ABI shim and tick.c into `opts.output` (atomically),
/// and append the trailer signed with `opts.signingKey` (program.h, signing/AotSigned.h). False +
/// `error` on failure.
bool linkSharedObject(std::string_view obj, const AotOptions &opts, uint32_t slices,
                      std::string &error);

} // namespace lj::jit::detail
