// llvmBackend() of `ladderjit::engines`: jit/ and lowering/ are linked in (tests, benchmarks).
#include "engines/LlvmBackend.h"

namespace lj::engines {

const LlvmBackend *llvmBackend(std::string &) { return &linkedLlvmBackend(); }

} // namespace lj::engines
