// The one exported symbol of libladderjit_llvm.so (engines/LlvmBackend.h): the backend over
// jit/ with the identity of this build. Everything else in the module is hidden.
#include "engines/LlvmBackend.h"

extern "C" __attribute__((visibility("default"))) const lj::engines::LlvmModuleInfo *
ladderjit_llvm_module() {
  static const lj::engines::LlvmModuleInfo info{lj::engines::kLlvmInterfaceVersion,
                                                lj::engines::llvmBuildTag(),
                                                &lj::engines::linkedLlvmBackend()};
  return &info;
}
