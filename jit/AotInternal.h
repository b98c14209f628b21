// Between the two halves of the AOT build: code generation (jit/Aot.cpp) and linking with the
// system compiler (jit/AotLink.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace lj::jit::detail {

/// Link the program object `obj` with the ABI shim and tick.c into `output` (atomically), and
/// append the integrity trailer (program.h LJPROG_TRAILER_*). False + `error` on failure.
bool linkSharedObject(std::string_view obj, const std::string &hash, uint32_t slices,
                      const std::string &output, std::string &error);

} // namespace lj::jit::detail
