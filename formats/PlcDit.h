// The plc.dit container (docs/plc-dit.md): one versioned text file holding an STL program, its
// symbol table, its run parameters and a SHA-256 content hash. Reading never throws or crashes;
// every problem is one `file:line: problem` message.
#pragma once

#include "formats/Address.h"
#include "frontends/hnc8/Address.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lj::formats {

/// First word of every container; the version follows it on the first line.
inline constexpr std::string_view kDitMagic = "ladderjit-plc-dit";
/// The only version this build reads and writes.
inline constexpr int kDitVersion = 1;

/// Everything a container holds.
struct DitFile {
  int32_t plc2Nvalue = 200;                 ///< PLC2 statements per tick (CLI.md default)
  uint64_t periodMs = 1;                    ///< PLC1 period in ms (CLI.md default)
  std::vector<Assignment> params;           ///< P values, file order, no index twice
  SymbolTable symbols{hnc8::symbolRules()}; ///< at most 1,000 names
  std::string program;                      ///< STL text: LF line ends, a final LF unless empty
  int32_t programLine = 0;                  ///< reader: container line of the first program line
  std::string hash;                         ///< `sha256:` + 64 lowercase hex digits of the content
};

/// Whether `text` starts with the container magic (after an optional UTF-8 BOM): the test the
/// CLI uses to tell a plc.dit from an STL file.
bool looksLikeDit(std::string_view text);

/// Parse a container. On any problem returns nothing and sets `error` to
/// `file:line: problem` (docs/plc-dit.md "Errors"); the hash is checked last, so a specific
/// structural error wins over "content hash does not match".
std::optional<DitFile> parseDit(std::string_view text, const std::string &file, std::string &error);

/// The canonical serialization the hash covers: the container without its hash line, comments
/// and blank lines, with normalized values (docs/plc-dit.md "Content hash").
std::string ditCanonical(const DitFile &dit);

/// `sha256:` + hex of SHA-256 over `bytes` (OpenSSL EVP).
std::string sha256Hash(std::string_view bytes);

/// The container text for `dit` (hash computed here; `dit.hash` and `programLine` ignored).
std::string writeDit(const DitFile &dit);

/// Normalize STL text for a container: CR before LF dropped, final LF added. Fails (returns
/// false, `error` = `file:line: problem`) when a line starts with `[`, which the container
/// reserves for section headers (no STL statement starts with it).
bool normalizeProgram(std::string_view stl, const std::string &file, std::string &out,
                      std::string &error);

/// The program as the STL parser should see it so diagnostics carry container line numbers:
/// `programLine - 1` empty lines, then the program.
std::string programForParser(const DitFile &dit);

/// Parse a symbols file (also the body of the `[symbols]` section): `NAME ADDR [comment...]`
/// per line, lines starting with `#` and blank lines ignored. Appends to `table`; errors are
/// `file:line: problem`.
bool parseSymbols(std::string_view text, const std::string &file, SymbolTable &table,
                  std::string &error);

} // namespace lj::formats
