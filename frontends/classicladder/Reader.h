// Reading a ClassicLadder project: the `.clp` container (`_FILES_CLASSICLADDER`, one
// `_FILE-name` ... `_/FILE-name` block per file), a project folder holding the same files, and
// the upstream 0.9 `.clprj` container (12x8 rungs, #VER=3.0) into the model of Project.h.
// Errors are located: the project file, the line in it, the embedded file, and for a rung the
// rung, row and column of the cell (docs/classicladder.md "Reading").
#pragma once

#include "frontends/classicladder/Project.h"
#include "ir/Status.h"

#include <string>
#include <string_view>

namespace lj::classicladder {

/// Largest project file or folder file read (bytes); real projects are under 100 KiB.
inline constexpr size_t kMaxProjectBytes = 16u << 20;

/// Reads `path`: a file ending in `.clp` or `.clprj` is a container, anything else a folder.
Result<Project> readProject(const std::string &path);

/// Reads a container held in memory; `path` names it in messages and decides the flavor
/// (`.clprj` = upstream 0.9).
Result<Project> readProjectText(std::string_view text, const std::string &path);

/// One embedded file: its name and lines (CR/LF stripped), each with its line number in the
/// file it came from (the container, or the folder file itself).
struct ProjectFile {
  std::string name;
  std::vector<std::string> lines;
  std::vector<int32_t> lineNumbers;
};

/// Splits a container into its files (the `.clp` syntax of files_project.c SplitFiles).
Result<std::vector<ProjectFile>> splitContainer(std::string_view text, const std::string &path);

/// Builds the project from its files (a split container or a folder's files).
Result<Project> readProjectFiles(const std::vector<ProjectFile> &files, const std::string &path,
                                 Flavor flavor);

} // namespace lj::classicladder
