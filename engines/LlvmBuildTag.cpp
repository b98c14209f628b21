// The build identity the driver and its LLVM module compare (engines/LlvmBackend.h): compiled
// into both, from the same definitions.
#include "engines/LlvmBackend.h"

#include "signing/AotTrust.h"

#ifndef LADDERJIT_VERSION
#error "LADDERJIT_VERSION must be defined (engines/CMakeLists.txt)"
#endif
#ifndef LADDERJIT_BUILD_ID
#error "LADDERJIT_BUILD_ID must be defined (engines/CMakeLists.txt)"
#endif

#define LJ_STR2(x) #x
#define LJ_STR(x) LJ_STR2(x)

namespace lj::engines {

const char *llvmBuildTag() {
  // The sizes catch a module of another layout even within one build tree.
  static const std::string tag =
      std::string("ladderjit " LADDERJIT_VERSION " build " LADDERJIT_BUILD_ID " interface ") +
      std::to_string(kLlvmInterfaceVersion) + " gcc " + __VERSION__ + " sizes " +
      std::to_string(sizeof(VerifiedProgram)) + "/" + std::to_string(sizeof(jit::JitOptions)) +
      "/" + std::to_string(sizeof(jit::AotOptions)) + "/" +
      std::to_string(sizeof(jit::CompileTimes)) + "/" +
      std::to_string(sizeof(signing::SigningKey)) + "/" + std::to_string(sizeof(Stmt));
  return tag.c_str();
}

} // namespace lj::engines
