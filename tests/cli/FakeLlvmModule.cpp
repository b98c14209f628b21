// A module that says it belongs to another build of ladderjit (tests/cli/LlvmModuleCliTest.cpp):
// the driver must refuse it by its build tag, without calling anything in it.
#include "engines/LlvmBackend.h"

extern "C" __attribute__((visibility("default"))) const lj::engines::LlvmModuleInfo *
ladderjit_llvm_module() {
  static const lj::engines::LlvmModuleInfo info{lj::engines::kLlvmInterfaceVersion,
                                                "ladderjit 0.0.0 build of another tree", nullptr};
  return &info;
}
