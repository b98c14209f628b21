# lit configuration of the golden IR tests: `RUN: %ladderjit emit-llvm ... | FileCheck`.
# The build writes lit.site.cfg.py (paths) and loads this file from it.
import os

import lit.formats

config.name = "ladderjit"
config.test_format = lit.formats.ShTest(execute_external=True)
config.suffixes = [".stl"]
config.excludes = ["lit.cfg.py", "lit.site.cfg.py", "CMakeLists.txt", "Inputs"]
config.test_source_root = os.path.dirname(__file__)
config.test_exec_root = getattr(config, "ladderjit_obj_root", config.test_source_root)

config.substitutions.append(("%ladderjit", config.ladderjit))
# FileCheck and friends from the same LLVM the JIT is built with, ahead of anything on PATH.
config.environment["PATH"] = os.pathsep.join(
    [config.llvm_tools_dir, config.environment.get("PATH", os.environ.get("PATH", ""))])
